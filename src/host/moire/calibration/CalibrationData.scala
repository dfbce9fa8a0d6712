package moire.calibration

import moire.harmonic._

/** A user mistake in a calibration file or option: one line, naming file and line where there is one. */
final class CalibrationError(msg: String) extends Exception(msg)

/** One measured point: position error (encoder reading minus true angle, arcsec) at an angle. */
final case class CalPoint(angleDeg: Double, errorArcsec: Double, direction: Option[String], line: Int)

/** A parsed `moire-calibration v1` file. */
final case class CalibrationData(file: String, meta: Map[String, String], points: Seq[CalPoint], cutShort: Option[Int] = None) {
  /** What the reader could not tell: the last row without a line end (kept, but it may have been cut short). */
  def notes: Seq[String] = cutShort.toSeq.map(CalibrationData.cutShortNote)
  /** The directions present, in file order ("" for rows without a direction column). */
  def directions: Seq[String] = points.map(_.direction.getOrElse("")).distinct
  def of(direction: String): Seq[CalPoint] = points.filter(_.direction.getOrElse("") == direction)

  /** Without `step_deg`: when a direction's angles lie on an even grid (step = smallest spacing,
    * dividing 360) with at least half of it present, the grid step and the angles missing from it.
    */
  def gridGaps: Seq[(String, Double, Seq[Double])] = if (meta.contains("step_deg")) Nil else directions.flatMap { d =>
    val as = of(d).map(_.angleDeg).sorted
    val step = as.zip(as.drop(1)).map { case (a, b) => b - a }.filter(_ > 1e-6).minOption.getOrElse(360.0)
    val n = math.round(360 / step).toInt
    def onGrid(a: Double) = { val q = (a - as.head) / step; math.abs(q - math.round(q)) < 1e-6 }
    if (n < 4 || math.abs(n * step - 360) > 1e-6 || !as.forall(onGrid) || as.size * 2 < n) None
    else {
      val sorted = as.toArray
      val missing = (0 until n).map(k => (as.head + k * step) % 360).filterNot(a => CalibrationData.near(sorted, a))
      if (missing.isEmpty) None else Some((d, step, missing.sorted))
    }
  }
}

/** Reader of the `moire-calibration v1` CSV format:
  * {{{
  * # moire-calibration v1
  * # table: air-bearing turntable   <- "# key: value" metadata, optional; "# text" without a colon: a comment
  * # step_deg: 10                   <- when given, every multiple of the step must be present
  * angle_deg,error_arcsec[,direction]
  * 0,-1.83[,cw]
  * }}}
  * Angles in [0, 360] degrees (360 is the same point as 0), errors in arcsec, direction cw or ccw.
  */
object CalibrationData {
  /** The note on a last data row (on line `line`) without a line end: kept, but it may have been cut short. */
  def cutShortNote(line: Int): String =
    s"line $line, the last, has no line end: if the file was cut short there, its row may be wrong (end the file with a line break if it is complete)"

  /** The largest angle error a row may state: one turn. */
  val MaxErrorArcsec = 1296000.0
  val magic = "# moire-calibration v1"
  private val columns2 = Seq("angle_deg", "error_arcsec")
  private val columns3 = columns2 :+ "direction"

  def read(path: os.Path): CalibrationData = {
    moire.files.PathKind.notAFile(path).foreach(m => throw new CalibrationError(m))
    // through the bounded line reader: a binary file or one endless line is refused at once
    val (lines, ended) = try moire.recording.CsvText.linesEnded(path) catch { case e: moire.recording.RecordingError => throw new CalibrationError(e.getMessage) }
    // errors name the file as given (explain's do), the data keep its name (the coefficients' source, the plots' stem)
    val d = try parse(path.last, lines.mkString("\n")) catch {
      case e: CalibrationError if e.getMessage.startsWith(path.last + ":") => throw new CalibrationError(path.toString + e.getMessage.drop(path.last.length))
    }
    // a last data row without a line end is kept and said (a hand-made table often ends so; a cut file too)
    if (!ended && d.points.lastOption.exists(_.line == lines.size)) d.copy(cutShort = Some(lines.size)) else d
  }

  def parse(file: String, text: String): CalibrationData = {
    def fail(line: Int, msg: String) = throw new CalibrationError(s"$file:$line: $msg")
    val lines = text.stripPrefix("\uFEFF").split("\n", -1).toSeq.map(_.stripSuffix("\r"))
    if (lines.isEmpty || lines.head.trim != magic) fail(1, s"first line must be '$magic', got '${moire.files.Shown.text(lines.headOption.getOrElse(""))}'")
    val meta = scala.collection.mutable.LinkedHashMap[String, String]()
    var header: Option[Seq[String]] = None
    val points = Seq.newBuilder[CalPoint]
    val seen = scala.collection.mutable.HashMap[(String, Long), Int]()
    for ((raw, i) <- lines.zipWithIndex.drop(1); n = i + 1; l = raw.trim if l.nonEmpty) {
      if (l.startsWith("#")) {
        val kv = l.stripPrefix("#").trim
        val at = kv.indexOf(':')
        // a line with no key (no colon) is a comment, as in a recording
        if (at > 0 && !l.startsWith("# ")) fail(n, s"metadata must read '# key: value', got '${moire.files.Shown.text(l)}'")
        if (at > 0) {
          val key = kv.substring(0, at).trim
          if (meta.contains(key)) fail(n, s"metadata key '$key' appears twice")
          meta(key) = kv.substring(at + 1).trim
        }
      } else header match {
        case None =>
          val h = l.split(",", -1).toSeq.map(_.trim.toLowerCase)
          if (h != columns2 && h != columns3)
            fail(n, s"header row must be '${columns2.mkString(",")}' or '${columns3.mkString(",")}', got '${moire.files.Shown.text(l)}'")
          header = Some(h)
        case Some(h) =>
          val cells = l.split(",", -1).toSeq.map(_.trim)
          if (cells.size != h.size) fail(n, s"${cells.size} fields, the header has ${h.size}: '${moire.files.Shown.text(l)}'")
          def num(col: Int): Double = {
            val s = cells(col)
            if (s.isEmpty) fail(n, s"missing ${h(col)}")
            val v = moire.numbers.Decimal.double(s).getOrElse(fail(n, s"${h(col)} '${moire.files.Shown.text(s)}' is not a number"))
            if (v.isNaN) fail(n, s"${h(col)} is $s")
            if (v.isInfinite) fail(n, s"${h(col)} is $s: infinite (beyond the largest number, about 1.8e308)")
            v
          }
          val a = num(0)
          if (a < 0 || a > 360) fail(n, s"angle_deg $a is outside [0, 360]")
          val e = num(1)
          // an angle error beyond a whole turn is no calibration error (and its squares overflow the fit)
          if (math.abs(e) > CalibrationData.MaxErrorArcsec) fail(n, f"error_arcsec $e%.6g is beyond a whole turn (${CalibrationData.MaxErrorArcsec}%.0f arcsec)")
          val dir = if (h.size == 3) {
            val d = cells(2).toLowerCase
            if (d != "cw" && d != "ccw") fail(n, s"direction '${cells(2)}' must be cw or ccw")
            Some(d)
          } else None
          val key = (dir.getOrElse(""), math.round((a % 360) * 1e6))
          seen.get(key).foreach(prev => fail(n, s"angle $a repeats line $prev${dir.fold("")(d => s" ($d)")}"))
          seen(key) = n
          points += CalPoint(a % 360, e, dir, n)
      }
    }
    val lastLine = lines.lastIndexWhere(_.trim.nonEmpty) + 1
    if (header.isEmpty) fail(lastLine, s"no header row '${columns2.mkString(",")}'")
    val data = CalibrationData(file, meta.toMap, points.result())
    if (data.points.isEmpty) fail(lastLine, "no data rows")
    meta.get("step_deg").foreach(checkGrid(data, _, lines.indexWhere(_.trim.startsWith("# step_deg")) + 1))
    data
  }

  /** An angle of the sorted `as` within 1e-6 degree of `a` (a binary search: a 0.001 degree table has 360,000). */
  def near(as: Array[Double], a: Double): Boolean = {
    val i = java.util.Arrays.binarySearch(as, a - 1e-6)
    val at = if (i >= 0) i else -i - 1
    at < as.length && as(at) - a < 1e-6
  }

  /** With `# step_deg: s`, every angle k s in [0, 360) must be present in each direction. */
  private def checkGrid(d: CalibrationData, step: String, line: Int): Unit = {
    val s = moire.numbers.Decimal.double(step).filter(v => v > 0 && v <= 180 && !v.isNaN)
      .getOrElse(throw new CalibrationError(s"${d.file}:$line: step_deg '$step' must be a number in (0, 180]"))
    val n = math.round(360 / s).toInt
    if (math.abs(n * s - 360) > 1e-6) throw new CalibrationError(s"${d.file}:$line: step_deg $s does not divide 360")
    for (dir <- d.directions; as = d.of(dir).map(_.angleDeg).sorted.toArray; k <- 0 until n) {
      val want = k * s
      if (!near(as, want)) {
        val angle = BigDecimal(want).setScale(6, BigDecimal.RoundingMode.HALF_UP).bigDecimal.stripTrailingZeros.toPlainString
        val where = if (dir.isEmpty) "" else s" ($dir)"
        throw new CalibrationError(s"${d.file}: angle $angle deg missing$where (step_deg: $s on line $line)")
      }
    }
  }
}
