package moire.explain

import moire.recording.Recording
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The fast fit (blocked sums on all cores, the channel response without atan, one refining step per iteration) and the
  * reference path it replaced give the same report: the same findings, each parameter within its stated uncertainty,
  * the same negligible and unexplained entries. Records long enough (100,000 samples) that the fast path's blocks and
  * cores are used.
  */
class FitPathSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def both(rec: Recording): (Report, Report) = {
    def run() = SignalExplain.run("path", rec, Nil, Progress.none).report
    (run(), FitPath.reference(run()))
  }

  private def agree(fast: Report, ref: Report): Unit = withClue(s"fast: ${describe(fast)}\nreference: ${describe(ref)}\n") {
    fast.findings.map(f => (f.effect, f.channel)) shouldBe ref.findings.map(f => (f.effect, f.channel))
    for ((f, r) <- fast.findings.zip(ref.findings); (k, v) <- r.params) {
      // within the larger stated uncertainty of the two (a parameter stated exactly, e.g. a bit number, must be equal)
      val u = math.max(f.unc.getOrElse(k, 0.0), r.unc.getOrElse(k, 0.0))
      withClue(s"${f.effect} $k: fast ${f.params.get(k)} reference $v +- $u: ") {
        math.abs(f.params(k) - v) should be <= (if (u.isNaN) 1e-6 * math.abs(v) else u + 1e-9 * math.abs(v))
      }
    }
    fast.negligible.map(x => (x.effect, x.channel)) shouldBe ref.negligible.map(x => (x.effect, x.channel))
    fast.unexplained.map(_.where.takeWhile(_ != ':')) shouldBe ref.unexplained.map(_.where.takeWhile(_ != ':'))
    fast.finalRms shouldBe ref.finalRms +- 1e-3 * ref.finalRms
  }

  "the fast fit" should "match the reference path on a ramp with skew, bandwidth, a harmonic and a stuck bit" in {
    val rec = sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9)), EffectSpec("bandwidth", Map("cutoff_hz" -> 500e3), "both"),
      EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 1e-3), "sin"), EffectSpec("adc_bit_fault", Map("bit" -> 2, "stuck_at" -> 0), "cos")),
      motion = Motion.Ramp(20e3, 250e3, 0.01))
    val (fast, ref) = both(rec)
    fast.findings.size should be >= 3
    agree(fast, ref)
  }

  it should "match it on a clean record (no findings) and on a drift with INL" in {
    val clean = sim(Nil)
    val (f1, r1) = both(clean)
    agree(f1, r1)
    val drift = sim(Seq(EffectSpec("drift", Map("offset_sin_per_s" -> 0.02, "gain_cos_per_s" -> 0.05)),
      EffectSpec("adc_nonlinearity", Map("inl2_lsb" -> 2.0, "inl3_lsb" -> 1.5))))
    val (f2, r2) = both(drift)
    f2.findings should not be empty
    agree(f2, r2)
  }

  it should "match it on another generator's rotary record with a reference column" in {
    val s = ThirdGenerator.Rotary(ecc = 0.02, bits = 12, seed = 12)
    val rec = Recording.parse("third", ThirdGenerator.rotary(s).split("\n").toIndexedSeq)
    val (fast, ref) = both(rec)
    fast.findings should not be empty
    agree(fast, ref)
  }
}
