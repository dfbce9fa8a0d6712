package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** No stories: structure whose fitted parameters the recording cannot support is unexplained, not a finding. */
class PlausibleSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "Interference" should "refuse a line under 10 cycles by more than its uncertainty, and only that" in {
    // 2 MS/s, 0.1 s: the oscilloscope capture of issue 12
    effects.Interference.tooFewCycles(64.5, 0.01, 0.1).get should include("6.45 +- 0.0010")
    effects.Interference.tooFewCycles(100.0, 0.01, 0.1) shouldBe None
    // 9.99 +- 0.01 cycles is not "fewer than 10" (issue 28: the hum of exactly 10 cycles), nor is 9.6 (the record
    // resolves a cycle count to half a cycle); 9.4 +- 0.01 is
    effects.Interference.tooFewCycles(99.9, 0.1, 0.1) shouldBe None
    effects.Interference.tooFewCycles(96.0, 0.1, 0.1) shouldBe None
    effects.Interference.tooFewCycles(94.0, 0.1, 0.1).get should include("9.40 +- 0.010")
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
