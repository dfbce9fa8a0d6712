package moire.recording

import moire.cli.UsageError

/** Turntable calibration data (`moire-calibration v1`): error against angle, optionally per direction.
  * direction: +1 = cw, -1 = ccw, 0 = not given.
  */
final case class Calibration(angleDeg: Array[Double], errorArcsec: Array[Double], direction: Array[Int],
                             meta: Map[String, String] = Map.empty) {
  def length: Int = angleDeg.length
  def hasDirection: Boolean = direction.exists(_ != 0)
}

object Calibration {
  val Magic = "# moire-calibration v1"

  def read(path: os.Path): Calibration = {
    if (!os.isFile(path)) throw new UsageError(s"$path: no such file")
    parse(path.toString, CsvText.lines(path))
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
    os.write.over(path, sb.toString, createFolders = true)
  }

  def parse(name: String, lines: IndexedSeq[String]): Calibration = {
    def bad(line: Int, msg: String) = throw new UsageError(s"$name:$line: $msg")
    if (lines.isEmpty || lines.forall(_.trim.isEmpty)) bad(1, "empty file, expected '# moire-calibration v1'")
    if (lines.head.trim != Magic) bad(1, s"first line must be '$Magic', got '${lines.head.take(40)}'")
    val (meta, headerAt) = CsvText.metadata(name, lines)
    if (headerAt >= lines.length) bad(lines.length, "the header row 'angle_deg,error_arcsec' is missing")
    val header = lines(headerAt).split(",", -1).map(_.trim)
    val ai = header.indexOf("angle_deg"); val ei = header.indexOf("error_arcsec"); val di = header.indexOf("direction")
    if (ai < 0 || ei < 0) bad(headerAt + 1, s"header must name columns angle_deg and error_arcsec, got '${lines(headerAt).take(60)}'")
    val rows = (headerAt + 1 until lines.length).filter(i => lines(i).trim.nonEmpty)
    if (rows.size < 3) bad(headerAt + 1, s"${rows.size} data rows; at least 3 are needed")
    val a = new Array[Double](rows.size); val e = new Array[Double](rows.size); val d = new Array[Int](rows.size)
    val seen = scala.collection.mutable.HashMap.empty[(Double, Int), Int]
    for ((li, r) <- rows.zipWithIndex) {
      val ln = li + 1
      val cells = lines(li).split(",", -1).map(_.trim)
      if (cells.length != header.length) bad(ln, s"${cells.length} cells, the header has ${header.length}")
      def num(c: Int) = cells(c).toDoubleOption.filter(v => !v.isNaN && !v.isInfinite)
        .getOrElse(bad(ln, s"${header(c)} '${cells(c)}' is not a finite number"))
      a(r) = num(ai); e(r) = num(ei)
      if (di >= 0) d(r) = cells(di).toLowerCase match {
        case "cw" => 1
        case "ccw" => -1
        case other => bad(ln, s"direction '$other' must be cw or ccw")
      }
      val key = (((a(r) % 360) + 360) % 360, d(r))
      seen.get(key).foreach(prev => bad(ln, s"angle ${a(r)} deg appears twice (also line $prev)"))
      seen(key) = ln
    }
    Calibration(a, e, d, meta)
  }
}
