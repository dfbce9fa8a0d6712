package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A signal beyond the ADC's range at a reversal sits at the rail while the model goes beyond it: clipping, no dropout. */
class RailTurnSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "read codes at the rail under a prediction beyond it as clipping, not as lost samples" in {
    for (seed <- Seq(1L, 2L)) {
      val spec = FringeGenerator.Spec(n = 40000, motion = "reverse", travel = 20, rateHz = 100, amp = 1.1, seed = seed)
      val r = explainAll(s"rail-turn-$seed", spec)
      withClue(s"seed $seed: ${r.notes.filter(_.contains("hold both"))}; ${clue(r)}") {
        r.notes.exists(_.contains("hold both channels still")) shouldBe false
        r.notes.exists(_.contains("end codes")) shouldBe true
      }
    }
  }
}
