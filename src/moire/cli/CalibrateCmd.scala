package moire.cli

import moire.harmonic.{Calibrate, CalibrationError, HarmonicParams}

/** `calibrate`: options to params, user mistakes to one-line [[UsageError]]s. */
object CalibrateCmd {
  def run(input: String, harmonics: Int, maxOrder: Int, lines: Int, subdivision: Int, out: String): Unit = {
    val p = try HarmonicParams(lines = lines, subdivision = subdivision, harmonics = harmonics)
    catch { case e: IllegalArgumentException => throw new UsageError("--" + e.getMessage.stripPrefix("requirement failed: ")) }
    val r = try Calibrate.run(os.Path(input, os.pwd), os.Path(out, os.pwd), p, maxOrder)
    catch { case e: CalibrationError => throw new UsageError(e.getMessage) }
    print(Calibrate.report(r))
  }
}
