package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A pickup line's frequency is moved to the whole record's optimum in its own round; an effect found after it that
  * adds no term of its own (a skew, a stuck bit, jitter) leaves the line as it is and carries no `frequency_hz`.
  */
class LineKeySpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "give frequency_hz to the pickup line only, when a skew is found after it" in {
    val r = explain(sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 12345.0, "amplitude_fs" -> 8 * lsb12)),
      EffectSpec("channel_skew", Map("skew_s" -> 5e-9)))))
    withClue(describe(r) + " | " + r.unexplained.map(_.where).mkString("; ") + " | " + r.misfit.map(_.where).mkString("; ")) {
      r.findings.map(_.effect) shouldBe Seq("interference", "channel_skew")
      r.findings.find(_.effect == "interference").get.params.keySet should contain("frequency_hz")
      r.findings.find(_.effect == "channel_skew").get.params.keySet should not contain "frequency_hz"
    }
  }
}
