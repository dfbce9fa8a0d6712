package moire.explain

import moire.recording.Calibration
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.concurrent.{Await, Future}
import scala.concurrent.ExecutionContext.Implicits.global
import scala.concurrent.duration._

/** Plots of flat or nearly flat data end (XChart's tick search did not where the axis step left the value unchanged). */
class AxesSpec extends AnyFlatSpec with Matchers {
  "an axis range" should "be wide enough for its ticks to move" in {
    for ((lo, hi) <- Seq((0.0, 0.0), (5.0, 5.0 + 1e-15), (1e-300, 2e-300), (-3e-17, 4e-17), (1e8, 1e8 + 1e-3), (0.0, 1.0), (-2.0, 3.5))) {
      val (a, b) = Axes.span(lo, hi)
      withClue(s"[$lo, $hi] -> [$a, $b]: ") {
        a should be <= lo; b should be >= hi
        val s = Axes.step(b - a)
        (a + s) should be > a
        (b - a) should be >= Axes.MinRange * math.max(math.max(math.abs(a), math.abs(b)), 1.0)
      }
    }
    Axes.span(0.0, 1.0) shouldBe ((0.0, 1.0))
  }

  "a constant calibration table's plots" should "be written" in {
    // every error the same: the residuals are 0 or rounding errors, the fit the constant to a few ulps
    for (v <- Seq(0.0, 5.0, 1e-300)) withClue(s"errors all $v: ") {
      val rows = for (d <- Seq(1, -1); k <- 0 until 36) yield (k * 10.0, v, d)
      val r = CalibrationExplain.run("flat", Calibration(rows.map(_._1).toArray, rows.map(_._2).toArray, rows.map(_._3).toArray, Map("source" -> "test")))
      val plots = Await.result(Future(CalibrationExplain.plots(r, "flat")), 60.seconds)
      plots.size shouldBe 3
      plots.foreach(p => p._2.length should be > 1000)
    }
  }
}
