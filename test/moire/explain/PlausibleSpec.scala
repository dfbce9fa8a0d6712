package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** No stories: structure whose fitted parameters the recording cannot support is unexplained, not a finding. */
class PlausibleSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def cand(effect: String, p: (String, Double)*) = Cand(effect, "both", ModelSpec(), 0, 0, p.toMap, Map.empty, "")

  "Plausible" should "refuse lines under 10 cycles and jitter that is not well below the sample period" in {
    // 2 MS/s, 0.1 s: the oscilloscope capture of issue 12
    Plausible.why(cand("interference", "frequency_hz" -> 64.5), 2e6, 200000).get should include("6.5 cycles")
    Plausible.why(cand("interference", "frequency_hz" -> 100.0), 2e6, 200000) shouldBe None
    Plausible.why(cand("jitter", "jitter_s" -> 32610e-12), 2e6, 200000).get should include("6.5 % of the sample period")
    Plausible.why(cand("jitter", "jitter_s" -> 300e-12), 10e6, 200000) shouldBe None
    Plausible.why(cand("harmonic", "order" -> 2.0), 2e6, 10) shouldBe None
  }

  "explain" should "put a 4-cycle pickup in a short record under unexplained, not name it" in {
    val rec = sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 40.0, "amplitude_fs" -> 0.01))),
      motion = Motion.Constant(20e3), n = 100000, fs = 1e6)
    val r = explain(rec)
    println(s"40 Hz pickup in 0.1 s: findings [${describe(r)}]; unexplained [${r.unexplained.map(_.summary).mkString("; ")}]")
    r.findings.map(_.effect) should not contain "interference"
    println(s"not tested: ${r.untested.mkString("; ")}")
    r.untested.exists(_.startsWith("interference below 100.0 Hz")) shouldBe true
    r.untested.exists(_.contains("not identifiable without a reference")) shouldBe true
    r.untested.exists(_.startsWith("channel skew")) shouldBe true   // one constant speed
    r.unexplained.exists(u => u.where.startsWith("interference") && u.summary.contains("cycles")) shouldBe true
    // the same pickup over 20 cycles is a finding
    val long = explain(sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 200.0, "amplitude_fs" -> 0.01))),
      motion = Motion.Constant(20e3), n = 100000, fs = 1e6))
    println(s"200 Hz pickup in 0.1 s: findings [${describe(long)}]")
    long.findings.map(_.effect) should contain("interference")
  }
}
