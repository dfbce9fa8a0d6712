package moire.recording

import moire.calibration.{CalibrationData, CalibrationError}

/** Turntable calibration data (`moire-calibration v1`): error against angle, optionally per direction.
  * direction: +1 = cw, -1 = ccw, 0 = not given.
  */
final case class Calibration(angleDeg: Array[Double], errorArcsec: Array[Double], direction: Array[Int],
                             meta: Map[String, String] = Map.empty, notes: Seq[String] = Nil) {
  def length: Int = angleDeg.length
  def hasDirection: Boolean = direction.exists(_ != 0)
}

object Calibration {
  val Magic = "# moire-calibration v1"

  def read(path: os.Path): Calibration = {
    moire.files.PathKind.notAFile(path).foreach(m => throw new RecordingError(m))
    // through the bounded line reader, which also tells whether the last line had a line end (a cut file's may not)
    val (lines, ended) = CsvText.linesEnded(path)
    val c = parse(path.toString, lines)
    if (!ended && lines.lastOption.exists(_.trim.nonEmpty)) c.copy(notes = Seq(CalibrationData.cutShortNote(lines.size))) else c
  }

  def write(path: os.Path, c: Calibration): Unit = {
    val sb = new StringBuilder
    sb.append(Magic).append('\n')
    c.meta.toSeq.sortBy(_._1).foreach { case (k, v) => sb.append(s"# $k: $v\n") }
    sb.append(if (c.hasDirection) "angle_deg,error_arcsec,direction\n" else "angle_deg,error_arcsec\n")
    for (i <- 0 until c.length) {
      sb.append(c.angleDeg(i)).append(',').append(c.errorArcsec(i))
      if (c.hasDirection) sb.append(',').append(if (c.direction(i) > 0) "cw" else "ccw")
      sb.append('\n')
    }
    moire.files.SafeWrite.text(path, sb.toString)
  }

  /** Parsed and checked by the one reader, [[moire.calibration.CalibrationData]]; errors become one-line usage errors. */
  def parse(name: String, lines: IndexedSeq[String]): Calibration = {
    val d = try CalibrationData.parse(name, lines.mkString("\n"))
    catch { case e: CalibrationError => throw new RecordingError(e.getMessage) }
    if (d.points.size < 3) throw new RecordingError(s"$name:${d.points.last.line}: ${d.points.size} data rows; at least 3 are needed")
    val dir = d.points.map(_.direction match { case Some("cw") => 1; case Some(_) => -1; case None => 0 })
    Calibration(d.points.map(_.angleDeg).toArray, d.points.map(_.errorArcsec).toArray, dir.toArray, d.meta)
  }
}
