package moire.explain

import moire.recording.Calibration
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.util.Random

class CalibrationExplainSpec extends AnyFlatSpec with Matchers {
  /** Turntable error: eccentricity and ellipticity (default model), optional hidden order-7 term and reversal. */
  def cal(h7: Double, reversal: Double, seed: Long): Calibration = {
    val rnd = new Random(seed)
    val rows = for (d <- Seq(1, -1); k <- 0 until 720) yield {
      val a = k * 0.5; val r = math.toRadians(a)
      val e = 5 * math.cos(r + 0.3) + 2 * math.cos(2 * r - 1) + h7 * math.cos(7 * r + 1) + 0.5 * reversal * d + 0.5 * rnd.nextGaussian()
      (a, e, d)
    }
    Calibration(rows.map(_._1).toArray, rows.map(_._2).toArray, rows.map(_._3).toArray, Map("source" -> "test"))
  }

  "explain on calibration data" should "find a missing harmonic order and a reversal error, both below the noise" in {
    val r = CalibrationExplain.run("cal", cal(0.3, 0.4, 5)).report
    info(r.text)
    r.kind shouldBe "calibration"
    r.findings.map(_.effect).toSet shouldBe Set("harmonic_order", "reversal")
    val h = r.findings.find(_.effect == "harmonic_order").get
    h.params("order") shouldBe 7.0
    h.params("amplitude_arcsec") shouldBe 0.3 +- 0.06
    r.findings.find(_.effect == "reversal").get.params("reversal_arcsec") shouldBe 0.4 +- 0.08
    r.finalRms should be < r.baselineRms
  }

  it should "name nothing in clean calibration data" in {
    for (seed <- 1 to 5) CalibrationExplain.run("cal", cal(0, 0, seed)).report.findings shouldBe empty
  }

  it should "report a flat table (every error the same, both directions) with finite figures and nothing found" in {
    val rows = for (d <- Seq(1, -1); k <- 0 until 36) yield (k * 10.0, 0.0, d)
    val r = CalibrationExplain.run("flat", Calibration(rows.map(_._1).toArray, rows.map(_._2).toArray, rows.map(_._3).toArray, Map("source" -> "test"))).report
    r.findings shouldBe empty
    r.located.map(_.where).toSet shouldBe Set("against angle (harmonics of the turn)", "by direction")
    r.located.flatMap(_.params.values).forall(x => !x.isNaN && !x.isInfinite) shouldBe true
    r.json.toString should not include "NaN"
  }

  it should "note a last row without a line end (kept: a hand-made table often ends so, a cut file too)" in {
    val p = os.temp(suffix = ".csv"); Calibration.write(p, cal(0, 0, 2))
    CalibrationExplain.run("cal", Calibration.read(p)).report.notes shouldBe empty
    val text = os.read(p); os.write.over(p, text.stripSuffix("\n"))
    val c = Calibration.read(p)
    c.length shouldBe 1440
    CalibrationExplain.run("cal", c).report.notes.mkString should include("the last, has no line end")
  }

  it should "read back what it writes" in {
    val c = cal(0.3, 0.4, 1)
    val p = os.temp(suffix = ".csv"); Calibration.write(p, c)
    val back = Calibration.read(p)
    back.angleDeg shouldBe c.angleDeg; back.direction shouldBe c.direction
    back.errorArcsec.zip(c.errorArcsec).foreach { case (a, b) => a shouldBe b +- 1e-12 }
  }
}
