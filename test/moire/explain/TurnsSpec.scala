package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class TurnsSpec extends AnyFlatSpec with Matchers {
  "Turns.sinCos" should "give sin and cos of 2 pi x within 1e-15 of the library's, over a turn and at its ends" in {
    val o = new Array[Double](2); val rnd = new scala.util.Random(9)
    val xs = Seq(0.0, 1.0, 0.25, 0.5, 0.75, 1.0 / 1024, 1 - 1e-17, Math.nextDown(1.0)) ++ Seq.fill(100000)(rnd.nextDouble())
    var worst = 0.0
    for (x <- xs) {
      Turns.sinCos(x, o, 0)
      worst = math.max(worst, math.max(math.abs(o(0) - math.sin(2 * math.Pi * x)), math.abs(o(1) - math.cos(2 * math.Pi * x))))
    }
    worst should be <= 1e-15
    worst should be > 0.0 // a table and a series, not the library itself
  }

  "Turns.floor" should "be math.floor to the bit: fractions, integers, halves, negatives, zeros, the limits and beyond" in {
    val rnd = new scala.util.Random(11)
    def bits(x: Double) = java.lang.Double.doubleToRawLongBits(x)
    val big = math.pow(2, 51)
    val special = Seq(0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.5, -2.5, 3.0, -3.0, 1e-300, -1e-300, Double.MinPositiveValue, -Double.MinPositiveValue,
      Math.nextDown(1.0), -Math.nextDown(1.0), Math.nextUp(1.0), big - 0.5, big - 1, Math.nextDown(big), big, -big, big + 2, 1e300, -1e300,
      Double.PositiveInfinity, Double.NegativeInfinity, Double.NaN, 1023.9999999999999, 1024.0)
    val spread = Seq.fill(200000)((rnd.nextDouble() - 0.5) * math.pow(10, rnd.nextInt(17)))
    val grid = (-2000 to 2000).flatMap(k => Seq(k.toDouble, k + 0.5, Math.nextUp(k.toDouble), Math.nextDown(k.toDouble)))
    for (x <- special ++ spread ++ grid) withClue(s"x = $x: ") { bits(Turns.floor(x)) shouldBe bits(math.floor(x)) }
  }
}
