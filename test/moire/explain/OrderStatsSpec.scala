package moire.explain

import org.scalacheck.Gen
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers
import org.scalatestplus.scalacheck.ScalaCheckPropertyChecks

class OrderStatsSpec extends AnyFlatSpec with Matchers with ScalaCheckPropertyChecks {
  implicit override val generatorDrivenConfig: PropertyCheckConfiguration = PropertyCheckConfiguration(minSuccessful = 300)

  private def same(a: Array[Double]): Unit = {
    val ranks = (Seq(0, a.length - 1, a.length / 2, a.length / 50, a.length * 49 / 50) ++ (0 until 8).map(_ * a.length / 8)).distinct
    val got = OrderStats.of(a.length, a(_), ranks); val want = OrderStats.sorted(a.length, a(_), ranks)
    for (k <- ranks.indices) withClue(s"rank ${ranks(k)} of ${a.length}: ") {
      if (want(k).isNaN) got(k).isNaN shouldBe true else got(k) shouldBe want(k)
    }
  }

  // values of every kind a fit's frequencies or differences hold: spread, clustered, repeated, signed, NaN, huge
  private val values: Gen[Double] = Gen.frequency(
    8 -> Gen.choose(-1e6, 1e6), 3 -> Gen.choose(0, 5).map(_.toDouble), 2 -> Gen.choose(-1e-12, 1e-12),
    1 -> Gen.const(Double.NaN), 1 -> Gen.oneOf(1e300, -1e300, 0.0, Double.MinPositiveValue))

  "OrderStats.of" should "give the values a sort puts at the ranks asked, for any values" in {
    forAll(Gen.choose(1, 3000).flatMap(n => Gen.listOfN(n, values))) { xs => same(xs.toArray) }
  }

  it should "hold on a record's length with one bucket holding most values, a constant, infinities and all NaN" in {
    val rnd = new scala.util.Random(3)
    same(Array.tabulate(200000)(i => if (i % 10 == 0) rnd.nextDouble() * 1e5 else 250e3 + rnd.nextGaussian() * 1e-3))
    same(Array.fill(70000)(42.0))
    same(Array.tabulate(1000)(i => if (i % 3 == 0) Double.PositiveInfinity else if (i % 3 == 1) Double.NegativeInfinity else i))
    same(Array.fill(10)(Double.NaN))
    an[IllegalArgumentException] should be thrownBy OrderStats.of(5, _.toDouble, Seq(5))
  }
}
