package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A harmonic fitted on both channels whose part on one is not significant becomes that channel's harmonic, in its
  * own round only: a later effect's round (one that adds no term, a skew) leaves it and its finding as they are.
  */
class DemoteSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private val withHarm = {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 2e-3), "sin")), n = 60000)
    () => {
      val e = new SignalEngine(rec); e.init()
      e.spec = e.spec.copy(terms = e.spec.terms :+ Term.Harm(3, "both")); e.converge()
      e
    }
  }
  private def cand(effect: String, channel: String, sp: ModelSpec) = Cand(effect, channel, sp, 0.0, 2, Map.empty, Map.empty, s"$effect here")

  "demote" should "make the candidate's own both-channel harmonic a one-channel one" in {
    val e = withHarm(); val sp = e.spec
    val c = SignalExplain.demote(e, sp.copy(terms = sp.terms.init), cand("harmonic", "both", sp))
    c.channel shouldBe "sin"
    e.spec.terms.last shouldBe Term.Harm(3, "sin")
  }

  it should "leave a harmonic of an earlier round, and a later candidate's channel and where" in {
    val e = withHarm(); val sp = e.spec
    val skew = cand("channel_skew", "cos", sp.copy(hasSkew = true, skewS = 1e-9))
    SignalExplain.demote(e, sp, skew) shouldBe skew
    e.spec shouldBe sp
  }
}
