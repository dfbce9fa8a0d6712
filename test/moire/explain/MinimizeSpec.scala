package moire.explain

import moire.recording.Reference
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The line search of the candidates (`Candidates.minimize`): a grid, then Brent's method to the bracket the given
  * number of golden sections would leave, in fewer calls than they take.
  */
class MinimizeSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private lazy val cands = {
    val rec = sim(Nil, motion = Motion.Ramp(20e3, 250e3, 0.002), n = 20000)
    val e = new SignalEngine(rec, Reference.of(rec).toOption.flatten)
    e.init(); new Candidates(e)
  }

  /** The minimum found, its value and the calls it took. */
  private def search(f: Double => Double, lo: Double, hi: Double, grid: Int, golden: Int): (Double, Double, Int) = {
    var calls = 0
    val (x, fx) = cands.minimizeAt(v => { calls += 1; f(v) }, lo, hi, grid, golden)
    (x, fx, calls)
  }

  "minimize" should "find a smooth minimum to the golden sections' bracket in fewer calls than they take" in {
    val cases = Seq[(String, Double => Double, Double)](
      ("a parabola", x => 3 * (x - 0.3217) * (x - 0.3217) + 5, 0.3217),
      ("a profile of a cut-off (1 / x)", x => 1 / x + 4 * x, 0.5),
      ("a spectral peak", x => -1 / (1 + 50 * (x - 0.6) * (x - 0.6)), 0.6))
    for ((name, f, x0) <- cases; (grid, golden) <- Seq((12, 14), (8, 16), (12, 30))) withClue(s"$name, grid $grid, golden $golden: ") {
      val (lo, hi) = (0.05, 1.1)
      val bracket = math.pow(Candidates.GoldenRatio, golden) * 2 * (hi - lo) / grid
      val (x, fx, calls) = search(f, lo, hi, grid, golden)
      math.abs(x - x0) should be <= bracket
      fx shouldBe f(x)
      // the golden sections' own count: the grid, two points, then one a section
      calls should be < grid + 1 + 2 + golden
    }
  }

  it should "stay at the end of the range when the function falls to it" in {
    val (x, _, _) = search(x => -x, 0.0, 1.0, 12, 14)
    x should be >= 1.0 - math.pow(Candidates.GoldenRatio, 14) * 2.0 / 12
  }

  it should "return a grid point, not fail, where the function is no number" in {
    val (x, fx, _) = search(_ => Double.NaN, 0.0, 1.0, 12, 14)
    x should (be >= 0.0 and be <= 1.0)
    fx.isNaN shouldBe true
  }
}
