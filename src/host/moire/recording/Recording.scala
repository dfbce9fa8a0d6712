package moire.recording

import moire.signal.{Adc, AdcFormat}

/** A `moire-recording v1` file: ADC pin codes of the sin and cos channels, with metadata.
  * Codes are as the ADC drives its pins (`adc_format`); `extra` holds any further numeric columns.
  */
final case class Recording(
  sampleRateHz: Double,
  adc: Adc,
  sin: Array[Int],
  cos: Array[Int],
  meta: Map[String, String] = Map.empty,
  extra: Map[String, Array[Double]] = Map.empty
) {
  require(sin.length == cos.length, "sin and cos must have the same length")
  def length: Int = sin.length
  def linesPerRev: Option[Double] = meta.get("lines_per_rev").flatMap(_.toDoubleOption)
  /** Signed values in full-scale units (-1 .. 1) of one channel. */
  def values(codes: Array[Int]): Array[Double] = {
    val out = new Array[Double](codes.length); val lsb = adc.lsb
    var i = 0
    while (i < codes.length) { out(i) = adc.fromPins(codes(i)) * lsb; i += 1 }
    out
  }
}

object Recording {
  val Magic = "# moire-recording v1"
  /** The fastest sample rate a file may state (100 GS/s, beyond any ADC a read head is sampled with). */
  val MaxSampleRateHz = 1e11

  /** Writes the file; metadata keys `sample_rate_hz`, `adc_bits`, `adc_format`, `samples` are set from the
    * recording; every other key (`adc`, free text naming the converter, among them) is kept as it is.
    */
  def write(path: os.Path, r: Recording): Unit = {
    val sb = new java.lang.StringBuilder(r.length * 12 + 256)
    sb.append(Magic).append('\n')
    val fixed = Seq("sample_rate_hz" -> fmt(r.sampleRateHz), "adc_bits" -> r.adc.bits.toString,
      "adc_format" -> r.adc.format.name, "samples" -> r.length.toString)
    val rest = r.meta.filter { case (k, _) => !fixed.exists(_._1 == k) }.toSeq.sortBy(_._1)
    for ((k, v) <- fixed ++ rest) sb.append("# ").append(k).append(": ").append(v).append('\n')
    val cols = r.extra.keys.toSeq.sorted
    sb.append((Seq("sin", "cos") ++ cols).mkString(",")).append('\n')
    var i = 0
    while (i < r.length) {
      sb.append(r.sin(i)).append(',').append(r.cos(i))
      cols.foreach(c => sb.append(',').append(fmt(r.extra(c)(i))))
      sb.append('\n'); i += 1
    }
    moire.files.SafeWrite.text(path, sb.toString)
  }

  private def fmt(d: Double): String = if (d == math.rint(d) && math.abs(d) < 1e15) d.toLong.toString else d.toString

  /** Reads a file; any problem is one RecordingError naming the file, the line and what is wrong. */
  def read(path: os.Path): Recording = {
    if (!os.isFile(path)) throw new RecordingError(s"$path: no such file")
    val lines = CsvText.lines(path)
    parse(path.toString, lines)
  }

  /** The code format: `adc_format` (offset-binary or twos-complement); files written before it held the
    * format under `adc`, which is free text now (`AD9226`): a format name there still counts, anything
    * else is a converter's name, and the codes are offset binary.
    */
  def format(meta: Map[String, String]): Either[String, AdcFormat] = meta.get("adc_format") match {
    case Some(f) => AdcFormat.parse(f).left.map(e => s"metadata adc_format: $e")
    case None => Right(meta.get("adc").flatMap(a => AdcFormat.parse(a).toOption).getOrElse(AdcFormat.OffsetBinary))
  }

  def parse(name: String, lines: IndexedSeq[String]): Recording = {
    def bad(line: Int, msg: String) = throw new RecordingError(s"$name:$line: $msg")
    if (lines.isEmpty || lines.forall(_.trim.isEmpty)) bad(1, "empty file, expected '# moire-recording v1'")
    if (lines.head.stripPrefix("\uFEFF").trim != Magic) bad(1, s"first line must be '$Magic', got '${lines.head.take(40)}'")
    val (meta, headerAt) = CsvText.metadata(name, lines)
    def need(k: String) = meta.getOrElse(k, bad(headerAt + 1, s"metadata '$k' is missing (a line '# $k: value' before the header)"))
    val fs = need("sample_rate_hz").toDoubleOption.filter(v => v > 0 && v <= MaxSampleRateHz)
      .getOrElse(bad(headerAt + 1, s"metadata sample_rate_hz '${meta("sample_rate_hz")}' is not a sample rate (a number above 0 and at most 1e11 Hz)"))
    val bits = need("adc_bits").toIntOption.filter(b => b >= 4 && b <= 24)
      .getOrElse(bad(headerAt + 1, s"metadata adc_bits '${meta("adc_bits")}' is not an integer in 4..24"))
    val adc = Adc(bits, format(meta).fold(e => bad(headerAt + 1, e), identity))
    if (headerAt >= lines.length) bad(lines.length, "the header row 'sin,cos' is missing")
    val header = lines(headerAt).split(",", -1).map(_.trim)
    header.groupBy(identity).collectFirst { case (c, cs) if cs.length > 1 => bad(headerAt + 1, s"column '$c' appears ${cs.length} times in the header") }
    val si = header.indexOf("sin"); val ci = header.indexOf("cos")
    if (si < 0 || ci < 0) bad(headerAt + 1, s"header must name columns sin and cos, got '${lines(headerAt).take(60)}'")
    val rows = (headerAt + 1 until lines.length).filter(i => lines(i).trim.nonEmpty)
    if (rows.isEmpty) bad(headerAt + 1, "no data rows after the header")
    val n = rows.length
    meta.get("samples").foreach { s =>
      if (!s.toLongOption.contains(n.toLong))
        bad(lines.length, s"metadata samples says '$s' but the file has $n data rows: a truncated or edited file")
    }
    val sin = new Array[Int](n); val cos = new Array[Int](n)
    val extraIdx = header.indices.filter(i => i != si && i != ci)
    val extra = extraIdx.map(_ => new Array[Double](n))
    val maxCode = (1 << bits) - 1
    var r = 0
    while (r < n) {
      val ln = rows(r) + 1
      val cells = lines(rows(r)).split(",", -1)
      if (cells.length != header.length) bad(ln, s"${cells.length} cells, the header has ${header.length}")
      def code(c: Int, col: String): Int = {
        val v = cells(c).trim.toIntOption.getOrElse(bad(ln, s"$col '${cells(c).trim}' is not an integer ADC code"))
        if (v < 0 || v > maxCode) bad(ln, s"$col code $v is outside the $bits-bit ADC range 0..$maxCode")
        v
      }
      sin(r) = code(si, "sin"); cos(r) = code(ci, "cos")
      var e = 0
      while (e < extraIdx.length) {
        val c = extraIdx(e)
        extra(e)(r) = cells(c).trim.toDoubleOption.filter(v => !v.isNaN && !v.isInfinite)
          .getOrElse(bad(ln, s"${header(c)} '${cells(c).trim}' is not a finite number"))
        e += 1
      }
      r += 1
    }
    Recording(fs, adc, sin, cos, meta, extraIdx.zip(extra).map { case (c, a) => header(c) -> a }.toMap)
  }
}

/** Shared text helpers of the two CSV formats. */
object CsvText {
  def lines(path: os.Path): IndexedSeq[String] = {
    val text = try os.read(path) catch { case e: java.io.IOException => throw new RecordingError(s"$path: cannot read (${moire.files.SafeWrite.reason(e)})") }
    text.stripPrefix("\uFEFF").split("\r?\n", -1).toIndexedSeq match { case s if s.nonEmpty && s.last.isEmpty => s.init; case s => s }
  }

  /** `# key: value` lines after the first; returns the map and the index of the first other line. */
  def metadata(name: String, lines: IndexedSeq[String]): (Map[String, String], Int) = {
    var i = 1; val m = scala.collection.mutable.LinkedHashMap.empty[String, String]
    while (i < lines.length && (lines(i).startsWith("#") || lines(i).trim.isEmpty)) {
      val body = lines(i).stripPrefix("#").trim
      if (body.nonEmpty) {
        val at = body.indexOf(':')
        if (at <= 0) throw new RecordingError(s"$name:${i + 1}: metadata line must be '# key: value', got '${lines(i).take(60)}'")
        val key = body.substring(0, at).trim
        if (m.contains(key)) throw new RecordingError(s"$name:${i + 1}: metadata key '$key' appears twice")
        m(key) = body.substring(at + 1).trim
      }
      i += 1
    }
    (m.toMap, i)
  }
}
