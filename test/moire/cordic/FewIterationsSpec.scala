package moire.cordic

import org.scalatest.flatspec.AnyFlatSpec

/** Few iterations at wide words: the rounding terms vanish, so each bound stands on its algorithmic term
  * alone. The conventional arcsine's used to be a 2^16-point grid maximum, which the model exceeded
  * (n = 4, b = 44: measured 0.2251172 rad, bound 0.2251148; the exact worst case is 0.2251223).
  */
class FewIterationsSpec extends AnyFlatSpec {
  for (mode <- CordicMode.all) {
    s"${mode.name} model" should "stay within its bound for n = 4 .. 8 at widths 40 .. 48" in {
      for (n <- 4 to 8; b <- Seq(40, 44, 48)) {
        val m = CordicAccuracy.measure(CordicParams(mode, n, b))
        assert(m.ok, f"$mode n=$n b=$b: measured ${m.maxError}%.6e, bound ${m.bound}%.6e, ${m.violations} inputs beyond their bound")
      }
    }
  }

  "The conventional arcsine's search" should "find the exact worst case, above any sampled one" in {
    // n = 4: exact worst error 0.2251222786 rad (its interval ends, computed independently); the old grid gave 0.2251134
    val p = CordicParams(CordicMode.Asin, 4, 48)
    val ideal = ArcsineSearch.worst(p, 1.0, rounded = false)
    assert(math.abs(ideal - 0.2251222786) < 1e-9, f"$ideal%.10f")
    // the ideal recursion at 2^20 inputs never exceeds it
    val k = p.gain
    def run(a: Double) = (0 until 4).foldLeft((1 / k, 0.0, 0.0)) { case ((x, y, z), i) =>
      val t = math.pow(2, -i); val a_i = math.atan(t)
      if (a >= y) (x - t * y, y + t * x, z + a_i) else (x + t * y, y - t * x, z - a_i)
    }._3
    val sampled = (0 to (1 << 20)).map { j => val a = -1 + 2.0 * j / (1 << 20); math.abs(run(a) - math.asin(a)) }.max
    assert(sampled <= ideal && sampled > ideal - 1e-3)
  }

  it should "cover the rounded comparisons: truncation and guard bits at few iterations" in {
    for (mode <- Seq(CordicMode.Asin, CordicMode.Acos); n <- Seq(4, 5, 6); b <- Seq(10, 16, 40); g <- Seq(0, 2);
         r <- Rounding.all; table <- Seq(0, 64)) {
      val m = CordicAccuracy.measure(CordicParams(mode, n, b, guardBits = g, rounding = r, peakTableSize = table))
      assert(m.ok, f"$mode n=$n b=$b g=$g ${r.name} table=$table: ${m.maxError}%.6e vs ${m.bound}%.6e")
    }
  }
}
