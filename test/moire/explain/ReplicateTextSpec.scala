package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The text of a failed replication: readable for a spline's many parameters, a finite sd far in the tail. */
class ReplicateTextSpec extends AnyFlatSpec with Matchers {
  private def est(theta: Array[Double], sd: Double) =
    Replicate.Est(theta, Array.tabulate(theta.length, theta.length)((a, b) => if (a == b) sd * sd else 0.0), Array.fill(theta.length)(0.0))

  "a failed replication" should "show a long parameter vector by its worst parameter, with a finite sd" in {
    val a = Array.fill(40)(0.0); val b = Array.fill(40)(0.0); b(17) = 90.0; b(3) = 5.0
    val t = Replicate.agree(Seq(Some(est(a, 1.0)), Some(est(b, 1.0))), "halves", "contrast").get
    t should include("parameter 18 of 40")
    t should include("(0.00 +- 1.0) vs (90.0 +- 1.0)")
    t should not include "Infinity"
    t.length should be < 200
  }

  it should "show a short vector whole" in {
    val t = Replicate.agree(Seq(Some(est(Array(1.0, 2.0), 0.1)), Some(est(Array(1.0, 3.0), 0.1))), "halves", "gain").get
    t should include("(1.00 +- 0.10, 2.00 +- 0.10) vs (1.00 +- 0.10, 3.00 +- 0.10)")
  }

  "Wilson-Hilferty" should "match the exact sd where the p-value still exists" in {
    val chi2 = 300.0; val dof = 126
    val pv = 1 - new org.hipparchus.distribution.continuous.ChiSquaredDistribution(dof).cumulativeProbability(chi2)
    val exact = -new org.hipparchus.distribution.continuous.NormalDistribution().inverseCumulativeProbability(pv)
    Replicate.wilsonHilferty(chi2, dof) shouldBe exact +- 0.2
  }
}
