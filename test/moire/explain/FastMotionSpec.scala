package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A back-and-forth motion at up to 100 kHz of fringe frequency has trajectory segments of under 2 fringe periods on
  * average, yet no fringe period there can be a turn of anything (6 million rpm): effects are tested, not all called
  * "not identifiable without a reference" (an 8 LSB harmonic and a 20 LSB drift from another generator had no finding).
  */
class FastMotionSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "find a harmonic on a fast back-and-forth motion whose segments span under 2 fringe periods" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 0.005))), motion = Motion.Oscillate(40, 400), n = 200000)
    val e = new SignalEngine(rec); e.init()
    info(f"periods per segment ${Identifiable.periodsPerSegment(e)}%.2f, typical fringe frequency ${e.typicalHz / 1e3}%.1f kHz")
    Identifiable.periodsPerSegment(e) should be < Identifiable.MinPeriodsPerSegment
    Identifiable.motionConfounded(e) shouldBe false
    val r = explain(rec)
    val f = r.findings.find(_.effect == "harmonic").getOrElse(fail(s"no harmonic: ${describe(r)}; not tested: ${r.untested.mkString("; ")}"))
    assert(within(f.params("amplitude_rel"), 0.005, 0.02), f.params)
  }
}
