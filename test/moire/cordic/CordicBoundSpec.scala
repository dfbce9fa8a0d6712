package moire.cordic

import org.scalatest.flatspec.AnyFlatSpec

/** The bit-accurate model against double precision, within the a priori bound, for the n x b sweep. */
class CordicBoundSpec extends AnyFlatSpec {
  val ns = Seq(8, 12, 16, 20, 24)
  val bs = Seq(12, 16, 18, 24, 32)

  for (mode <- CordicMode.all) {
    s"${mode.name} model" should "stay within its error bound for every (n, b) of the sweep" in {
      info(f"${"n"}%3s ${"b"}%3s ${"measured"}%11s ${"bound"}%11s  inputs")
      for (n <- ns; b <- bs) {
        val m = CordicAccuracy.measure(CordicParams(mode, n, b))
        info(f"$n%3d $b%3d ${m.maxError}%11.4e ${m.bound}%11.4e  ${m.samples} (${m.unit})")
        assert(m.violations == 0, s"$mode n=$n b=$b: ${m.violations} inputs beyond their bound")
        assert(m.maxError <= m.bound, s"$mode n=$n b=$b: ${m.maxError} > ${m.bound} at ${m.worstInput}")
      }
    }
  }

  "Truncation and guard bits" should "keep the model within its bound" in {
    for (mode <- CordicMode.all; n <- Seq(10, 18); b <- Seq(14, 22); g <- Seq(0, 3)) {
      val m = CordicAccuracy.measure(CordicParams(mode, n, b, guardBits = g, rounding = Rounding.Truncate))
      assert(m.ok, s"$mode n=$n b=$b g=$g truncate: ${m.maxError} vs ${m.bound}, ${m.violations} violations")
    }
  }

  "The peak table" should "lower the double-rotation arcsine bound and keep the model within it" in {
    val plain = CordicParams(CordicMode.AsinDouble, 16, 18)
    val withTable = plain.copy(peakTableSize = 256)
    val a = CordicAccuracy.measure(plain); val b = CordicAccuracy.measure(withTable)
    info(f"no table: measured ${a.maxError}%.3e bound ${a.bound}%.3e; 256 entries: measured ${b.maxError}%.3e bound ${b.bound}%.3e")
    assert(b.ok && a.ok)
    assert(b.bound < a.bound / 2, "a 256-entry table should at least halve the bound")
    assert(b.maxError < a.maxError, "a 256-entry table should lower the measured error")
  }

  "The conventional arcsine (seed 002 eq. 8)" should "misjudge directions by degrees where the double rotation does not" in {
    val conv = CordicAccuracy.measure(CordicParams(CordicMode.Asin, 15, 18))
    val dbl = CordicAccuracy.measure(CordicParams(CordicMode.AsinDouble, 15, 18))
    info(f"n=15: conventional ${math.toDegrees(conv.maxError)}%.3f deg, double rotation ${math.toDegrees(dbl.maxError)}%.4f deg")
    assert(math.toDegrees(conv.maxError) > 5.0)
    assert(dbl.maxError < conv.maxError / 20)
  }
}
