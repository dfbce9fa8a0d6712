package moire.calibration

import moire.harmonic._

import moire.cordic.PaperBounds

/** Sample calibration files: seed 001 eq. 19 plus Gaussian noise, 36 points at 10 degree steps
  * (sec. 4.1). Regenerate the files in docs/ with `./sbt "runMain moire.calibration.CalibrationSample docs"`.
  */
object CalibrationSample {
  def eq19(thetaDeg: Double): Double =
    PaperBounds.seed001Eq19.map { case (k, c, phi) => c * math.sin(math.toRadians(k * thetaDeg + phi)) }.sum

  /** @param noise standard deviation in arcsec (the autocollimator's 0.25 arcsec by default)
    * @param reversal when > 0, adds ccw rows offset by this many arcsec (plus noise)
    */
  def csv(noise: Double = 0.25, seed: Long = 1, reversal: Double = 0.0, offset: Double = 0.6): String = {
    val rnd = new scala.util.Random(seed)
    def row(a: Int, extra: Double) = f"$a,${eq19(a) + offset + extra + noise * rnd.nextGaussian()}%.3f"
    val head = Seq(CalibrationData.magic, "# source: seed 001 eq. 19 plus Gaussian noise (synthetic)",
      f"# noise_arcsec: $noise", s"# seed: $seed", "# step_deg: 10")
    val rows =
      if (reversal > 0) "angle_deg,error_arcsec,direction" +: ((0 until 360 by 10).map(a => row(a, 0) + ",cw") ++
        (0 until 360 by 10).map(a => row(a, -reversal) + ",ccw"))
      else "angle_deg,error_arcsec" +: (0 until 360 by 10).map(row(_, 0))
    (head ++ rows).mkString("", "\n", "\n")
  }

  val files: Seq[(String, String)] = Seq(
    "calibration-sample.csv" -> csv(),
    "calibration-sample-cw-ccw.csv" -> csv(seed = 2, reversal = 0.4))

  def main(args: Array[String]): Unit = {
    val dir = os.Path(args.headOption.getOrElse("docs"), os.pwd)
    for ((name, text) <- files) { moire.files.SafeWrite.text(dir / name, text); println(s"wrote ${dir / name}") }
  }
}
