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
}
