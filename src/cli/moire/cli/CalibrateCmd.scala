package moire.cli

import moire.harmonic.HarmonicParams
import moire.calibration.{Calibrate, CalibrationError, HarmonicEmit}

/** `calibrate` and `emit-harmonic`: options to params, user mistakes to one-line [[UsageError]]s. */
object CalibrateCmd {
  private def params(f: => HarmonicParams): HarmonicParams =
    try f catch { case e: IllegalArgumentException => throw new UsageError("--" + e.getMessage.stripPrefix("requirement failed: ")) }

  def emit(lines: Int, subdivision: Int, harmonics: Int, iterations: Int, dataBits: Int, out: String): Unit = {
    val p = params(HarmonicParams(lines = lines, subdivision = subdivision, harmonics = harmonics,
      iterations = iterations, dataBits = dataBits))
    for (f <- HarmonicEmit(p, os.Path(out, os.pwd), counter = true)) println(s"wrote $f")
    println(s"${p.moduleName}: latency ${p.latency} clocks, ${p.countsPerTurn} counts per turn")
  }

  def run(input: String, harmonics: Int, maxOrder: Int, lines: Int, subdivision: Int, out: String): Unit = {
    val p = params(HarmonicParams(lines = lines, subdivision = subdivision, harmonics = harmonics))
    val r = try Calibrate.run(os.Path(input, os.pwd), os.Path(out, os.pwd), p, maxOrder)
    catch { case e: CalibrationError => throw new UsageError(e.getMessage) }
    print(Calibrate.report(r))
  }
}
