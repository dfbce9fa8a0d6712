package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Replication asks the parts to agree with each other and, together, with the whole record: an offset step between
  * two flat halves is a drift over the whole record while each half, its offset free, shows none (a 10 LSB step on sin
  * from another generator was named a drift of 15 LSB over the record).
  */
class StepSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._
  private def est(x: Double, sd: Double) = Some(Replicate.Est(Array(x), Array(Array(sd * sd)), Array(0.0)))

  "replication" should "refuse parts that agree with each other but not with the whole record" in {
    Replicate.agree(Seq(est(0.1, 1), est(-0.1, 1)), "halves", "drift", whole = Some(Array(10.0))).getOrElse("") should
      include("they agree with each other, but their mean drift")
    Replicate.agree(Seq(est(0.1, 1), est(-0.1, 1)), "halves", "drift", whole = Some(Array(0.5))) shouldBe None
    Replicate.agree(Seq(est(0.1, 1), est(-0.1, 1)), "halves", "drift") shouldBe None
  }

  "explain" should "not call an offset step between two flat halves a drift" in {
    val clean = sim(Nil, motion = Motion.Oscillate(40, 400), n = 200000, noiseLsb = 1.0)
    val n = clean.length
    val stepped = clean.copy(sin = Array.tabulate(n)(i => if (i >= n / 2) clean.sin(i) + 10 else clean.sin(i)))
    val r = explain(stepped)
    info(s"findings: ${describe(r)}; unexplained: ${r.unexplained.map(_.where).mkString("; ")}")
    r.findings.map(_.effect) should not contain "drift"
    r.findings.map(_.effect) should not contain "warmup"
  }
}
