package moire.explain

import moire.recording.Reference
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The warm-up's time-constant search from sums (the fast path) against the search that fits the columns at every
  * step (the reference path): the same time constant within its uncertainty and the same -2 ln L.
  */
class WarmupSearchSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "the warm-up search" should "find the time constant the column fits find" in {
    for ((tau, motion) <- Seq((0.002, Motion.Oscillate(60, 400)), (0.004, Motion.Ramp(20e3, 200e3, 0.01)))) {
      val rec = sim(Seq(EffectSpec("warmup", Map("offset_sin_step_fs" -> 0.005, "gain_cos_step_rel" -> 0.01, "time_constant_s" -> tau))),
        motion = motion)
      val e = new SignalEngine(rec, Reference.of(rec).toOption.flatten)
      e.init()
      val c = new Candidates(e)
      val fast = c.warmup().get; val ref = FitPath.reference(c.warmup()).get
      withClue(s"fast ${fast.params} +- ${fast.unc}, reference ${ref.params} +- ${ref.unc}: ") {
        val t = fast.params("time_constant_s"); val u = math.max(fast.unc("time_constant_s"), ref.unc("time_constant_s"))
        math.abs(t - ref.params("time_constant_s")) should be <= u
        fast.m2ll shouldBe ref.m2ll +- math.max(1.0, 1e-9 * math.abs(ref.m2ll))
      }
    }
  }
}
