package moire.calibration

import moire.harmonic._

import moire.cordic.PaperBounds
import org.scalatest.flatspec.AnyFlatSpec

/** The harmonic fit recovers known coefficients; its register words drive the model to the fitted f. */
class HarmonicFitSpec extends AnyFlatSpec {
  val grid: Seq[Double] = (0 until 360 by 10).map(_.toDouble)
  /** Eq. 19 as (sin, cos) components per order: a_k = c cos phi, b_k = c sin phi. */
  def components(hs: Seq[(Int, Double, Double)]): Map[Int, (Double, Double)] =
    hs.map { case (k, c, phi) => k -> (c * math.cos(math.toRadians(phi)), c * math.sin(math.toRadians(phi))) }.toMap
  def components(f: HarmonicFitResult): Map[Int, (Double, Double)] = components(f.harmonics.map(h => (h.order, h.c, h.phiDeg)))
  val truth: Map[Int, (Double, Double)] = components(PaperBounds.seed001Eq19)

  "A noiseless eq. 19 on 36 points" should "come back exactly, orders 1-4, with the offset" in {
    val errors = grid.map(t => CalibrationSample.eq19(t) + 0.7)
    val f = HarmonicFit.analyse(grid, errors, 17, 4)
    assert(f.harmonics.map(_.order) == Seq(1, 2, 3, 4))
    for ((k, (a, b)) <- components(f)) {
      assert(math.abs(a - truth(k)._1) < 1e-9 && math.abs(b - truth(k)._2) < 1e-9, s"order $k")
    }
    assert(math.abs(f.offset - 0.7) < 1e-9 && f.maxAbs < 1e-9 && f.harmonics.forall(_.c > 0))
  }

  "The m largest harmonics" should "be picked by amplitude, also on uneven angles" in {
    val rnd = new scala.util.Random(5)
    val angles = Seq.fill(60)(rnd.nextDouble() * 360)
    val hs = PaperBounds.seed001Eq19 :+ ((7, 3.0, 20.0)) :+ ((9, 0.5, -40.0))
    val errors = angles.map(t => hs.map { case (k, c, p) => c * math.sin(math.toRadians(k * t + p)) }.sum)
    assert(HarmonicFit.analyse(angles, errors, 12, 4).harmonics.map(_.order) == Seq(1, 2, 3, 4))
    val f5 = HarmonicFit.analyse(angles, errors, 12, 5)
    assert(f5.harmonics.map(_.order) == Seq(1, 2, 3, 4, 7))
    val f6 = HarmonicFit.analyse(angles, errors, 12, 6)
    assert(f6.maxAbs < 1e-9, s"all six harmonics present: residual ${f6.maxAbs}")
  }

  "The noisy sample (0.25 arcsec)" should "land within 4 standard errors of eq. 19" in {
    val d = CalibrationData.parse("s", CalibrationSample.csv())
    val f = HarmonicFit.analyse(d.points.map(_.angleDeg), d.points.map(_.errorArcsec), 17, 4)
    val se = 0.25 * math.sqrt(2.0 / 36) // standard error of each component
    for ((k, (a, b)) <- components(f)) {
      assert(math.abs(a - truth(k)._1) < 4 * se && math.abs(b - truth(k)._2) < 4 * se, s"order $k: ($a, $b) vs ${truth(k)}")
    }
    assert(f.rms > 0.1 && f.rms < 0.4, s"residual rms ${f.rms} should look like the 0.25 arcsec noise")
  }

  "Too few points or aliased orders" should "be refused with a hint" in {
    assert(intercept[CalibrationError](HarmonicFit.fit(grid.take(8), grid.take(8), 1 to 4)).getMessage.contains("lower --max-order"))
    assert(intercept[CalibrationError](HarmonicFit.fit(grid, grid, (1 to 16) :+ 18)).getMessage.contains("aliasing"))
    assert(intercept[CalibrationError](HarmonicFit.analyse(grid, grid, 3, 4)).getMessage.contains("below --harmonics"))
  }

  "calibrate on too few angles" should "say how many harmonics the angles support" in {
    val f = os.temp(CalibrationData.magic + "\nangle_deg,error_arcsec\n0,1\n90,2\n180,3\n270,1\n", suffix = ".csv")
    val e = intercept[CalibrationError](Calibrate.run(f, os.temp.dir(), HarmonicParams(), -1))
    assert(e.getMessage == s"${f.last}: 4 distinct angles support harmonics up to order 1, fewer than --harmonics 4")
  }

  "calibrate on a table whose errors are all the same" should "say there is no harmonic to compensate" in {
    val f = os.temp(CalibrationData.magic + "\nangle_deg,error_arcsec\n" + (0 until 360 by 10).map(a => s"$a,5.0").mkString("\n") + "\n", suffix = ".csv")
    val text = Calibrate.report(Calibrate.run(f, os.temp.dir(), HarmonicParams(), -1))
    assert(text.contains("there is no harmonic to compensate"), text)
    val varied = os.temp(CalibrationData.magic + "\nangle_deg,error_arcsec\n" + (0 until 360 by 10).map(a => s"$a,${math.sin(math.toRadians(a))}").mkString("\n") + "\n", suffix = ".csv")
    assert(!Calibrate.report(Calibrate.run(varied, os.temp.dir(), HarmonicParams(), -1)).contains("no harmonic"))
  }

  "The register words of a fit" should "make the bit-accurate compensator remove the fitted harmonics" in {
    val p = HarmonicParams()
    val f = HarmonicFit.analyse(grid, grid.map(CalibrationSample.eq19), 17, 4)
    val model = new HarmonicModel(p)
    val slots = CoefficientFile.slots(p, f)
    assert(CoefficientFile.writes(p, slots).size == 12)
    val worst = (0 until 3600).map { j =>
      val theta = j.toLong * p.countsPerTurn / 3600
      val out = model(theta, slots).out
      math.abs(model.fArcsec(theta, out) - f.harmonicPart(theta * 360.0 / p.countsPerTurn))
    }.max
    assert(worst < 1.5e-3, s"compensator vs fit: $worst arcsec")
    val tooBig = f.copy(harmonics = f.harmonics.map(h => h.copy(c = 200.0)))
    assert(intercept[CalibrationError](CoefficientFile.slots(p, tooBig)).getMessage.contains("does not fit coef-width 28"))
  }
}
