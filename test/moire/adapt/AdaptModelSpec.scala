package moire.adapt

import moire.cordic.Fixed
import moire.signal._
import org.scalatest.flatspec.AnyFlatSpec

/** The model against double precision: each arithmetic piece within its rounding bound, and the
  * whole corrector against the true phase and the true signal parameters.
  */
class AdaptModelSpec extends AnyFlatSpec {
  val configs = Seq(AdaptParams(), AdaptParams(inputBits = 10, outputBits = 14, mulFrac = 2, gainBits = 20),
    AdaptParams(inputBits = 14, outputBits = 18, mulFrac = 2, offsetFrac = 8, phaseBits = 14, tableBits = 20, fineGuard = 6))

  "correct" should "stay within its rounding bound of (s - os) ks and (c - oc) kc + sp t" in {
    for (p <- configs) {
      val rnd = new scala.util.Random(p.hashCode)
      val half = 1L << (p.inputBits - 1)
      var worst = 0.0
      for (_ <- 0 until 20000) {
        val s = rnd.nextLong(2 * half) - half; val c = rnd.nextLong(2 * half) - half
        val os = rnd.nextLong(half << p.offsetFrac >> 2) - (half << p.offsetFrac >> 3)
        val oc = rnd.nextLong(half << p.offsetFrac >> 2) - (half << p.offsetFrac >> 3)
        val ks = p.startGain / 2 + rnd.nextLong(p.startGain); val kc = p.startGain / 2 + rnd.nextLong(p.startGain)
        val t = rnd.nextLong(1L << (p.phaseFrac - 1)) - (1L << (p.phaseFrac - 2))
        val (gs, gc, tt) = (ks * math.pow(2, -p.gainFrac), kc * math.pow(2, -p.gainFrac), t * math.pow(2, -p.phaseFrac))
        val spx = (s - os * math.pow(2, -p.offsetFrac)) * gs
        val cpx = (c - oc * math.pow(2, -p.offsetFrac)) * gc + spx * tt
        val lim = math.pow(2, p.outputBits - 1) - 4
        if (math.abs(spx) < lim && math.abs(cpx) < lim) {
          val (sp, cp) = AdaptModel.correct(p, s, c, os, oc, ks, kc, t)
          val bs = 0.5 * math.pow(2, -p.mulFrac) * gs + 0.5
          val bc = 0.5 * math.pow(2, -p.mulFrac) * gc + 0.5 + math.abs(tt) * bs + 0.5
          assert(math.abs(sp - spx) <= bs, s"${p.moduleName}: sp $sp vs $spx")
          assert(math.abs(cp - cpx) <= bc, s"${p.moduleName}: cp $cp vs $cpx")
          worst = math.max(worst, math.abs(sp - spx) / bs)
        }
      }
      assert(worst > 0.3, "the bound is far from what the rounding reaches: the check is too loose")
    }
  }

  "interpolate, radians and rotate" should "turn the phase by the table value within their bound" in {
    for (p <- configs) {
      val rnd = new scala.util.Random(p.hashCode + 1)
      val r = math.pow(2, p.outputBits - 1) / math.sqrt(2)
      val range = 1L << (p.tableBits - 1)
      for (_ <- 0 until 20000) {
        val a = rnd.nextLong(2 * range) - range; val b = rnd.nextLong(2 * range) - range
        val f = rnd.nextLong(1L << p.interpBits)
        val lin = a + (b - a) * f.toDouble / (1L << p.interpBits)
        val delta = AdaptModel.interpolate(p, a, b, f)
        assert(math.abs(delta - lin) <= 0.5, s"interpolate($a, $b, $f) = $delta, exact $lin")
        val phi = rnd.nextDouble() * 2 * math.Pi
        val (sp, cp) = (math.round(r * math.sin(phi)), math.round(r * math.cos(phi)))
        val rad = delta * 2 * math.Pi / math.pow(2, p.fineBits)
        val dr = AdaptModel.radians(p, delta)
        val drBound = 0.5 * math.pow(2, -p.rotFrac) + math.abs(delta) * math.abs(p.twoPi * math.pow(2, -p.twoPiFrac) - 2 * math.Pi) / math.pow(2, p.fineBits)
        assert(math.abs(dr * math.pow(2, -p.rotFrac) - rad) <= drBound + 1e-15)
        val (so, co) = AdaptModel.rotate(p, sp, cp, dr)
        val got = Fixed.angleDiff(math.atan2(so.toDouble, co.toDouble), math.atan2(sp.toDouble, cp.toDouble))
        val bound = drBound + math.pow(math.abs(rad), 3) / 3 + 1.0 / (r - 2)
        assert(math.abs(got + rad) <= bound, s"${p.moduleName}: turned by $got, wanted ${-rad}, bound $bound")
      }
    }
  }

  /** Closed-form targets of the estimates for the signal. */
  "The corrector" should "converge to the true offsets, gains and phase and to < 0.02 degree, forwards and backwards" in {
    val sp = AdaptFigures.imperfect(noise = true)
    val p = AdaptParams()
    val half = math.pow(2, p.inputBits - 1)
    val r = math.pow(2, p.outputBits - 1) / math.sqrt(2)
    val alpha = math.toRadians(sp.phaseErrorDeg)
    for (hz <- Seq(800e3, -300e3)) {
      val m = new AdaptModel(p)
      val run = AdaptFigures.run(sp, Motion.Constant(hz, 0.3), m, totalMs = 6, measureMs = 1)
      assert(run.uncorrected > 3, s"$hz Hz: uncorrected ${run.uncorrected} deg")
      assert(run.corrected < AdaptFigures.goalDeg, s"$hz Hz: corrected ${run.corrected} deg")
      assert(math.abs(m.os * math.pow(2, -p.offsetFrac) - sp.offsetSin * half) < 0.1, s"os ${m.os}")
      assert(math.abs(m.oc * math.pow(2, -p.offsetFrac) - sp.offsetCos * half) < 0.1, s"oc ${m.oc}")
      // The harmonics carry h2^2 + h3^2 = 5e-4 of the power: exact for ks, the tolerance for kc and t.
      val power = 1 + sp.harmonics.map(h => h.amplitude * h.amplitude).sum
      val ks = r / (sp.amplitude * sp.gainSin * half * math.sqrt(power))
      val kc = r / (sp.amplitude * sp.gainCos * half * math.cos(alpha))
      assert(math.abs(m.ks * math.pow(2, -p.gainFrac) / ks - 1) < 5e-5, s"ks ${m.ks * math.pow(2, -p.gainFrac)} vs $ks")
      assert(math.abs(m.kc * math.pow(2, -p.gainFrac) / kc - 1) < 5e-4, s"kc ${m.kc * math.pow(2, -p.gainFrac)} vs $kc")
      assert(math.abs(m.t * math.pow(2, -p.phaseFrac) - math.tan(alpha)) < 5e-4, s"t ${m.t * math.pow(2, -p.phaseFrac)}")
    }
  }

  it should "leave the harmonics in place without its table, and fix the rest" in {
    val m = new AdaptModel(AdaptParams(harmonicEntries = 0))
    val run = AdaptFigures.run(AdaptFigures.imperfect(noise = false), Motion.Constant(600e3, 0.1), m, totalMs = 5, measureMs = 1)
    assert(run.corrected > 1.0 && run.corrected < 2.0, s"without table: ${run.corrected} deg (H2 + H3 alone give about 1.5)")
  }

  "AdaptParams" should "reject bad values with a message naming the parameter" in {
    def msg(f: => AdaptParams): String = intercept[IllegalArgumentException](f).getMessage
    assert(msg(AdaptParams(inputBits = 7)).contains("inputBits must be in 8..16"))
    assert(msg(AdaptParams(outputBits = 20)).contains("outputBits"))
    assert(msg(AdaptParams(harmonicEntries = 48)).contains("harmonicEntries must be 0 or a power of two"))
    assert(msg(AdaptParams(windowBits = 16)).contains("windowBits"))
    assert(msg(AdaptParams(pllKp = 0)).contains("pllKp"))
    assert(msg(AdaptParams(pllKp = 8, pllKv = 8)).contains("pllKv must be at least 9"))
    assert(msg(AdaptParams(pllKp = 1, pllKv = 2)).contains("pllKv must be at least 3"))
    assert(msg(AdaptParams(initialAmplitude = 2)).contains("initialAmplitude"))
  }

  "latency and module name" should "follow the parameters" in {
    val p = AdaptParams()
    assert(p.latency == 1 + p.correctionStages + p.cordic.latency + p.rmwStage)
    assert(p.moduleName != AdaptParams(harmonicEntries = 32).moduleName)
    assert(p.moduleName != AdaptParams(gainRate = 5).moduleName)
  }
}
