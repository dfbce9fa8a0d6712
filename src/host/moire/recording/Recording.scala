package moire.recording

import moire.files.Shown
import moire.signal.{Adc, AdcFormat}

/** A `moire-recording v1` file: ADC pin codes of the sin and cos channels, with metadata.
  * Codes are as the ADC drives its pins (`adc_format`); `extra` holds any further numeric columns; `comments`
  * the header's comment lines (text without a `key: value` form), kept as they were; `warnings` what the reader
  * left out and why (never written to a file).
  */
final case class Recording(
  sampleRateHz: Double,
  adc: Adc,
  sin: Array[Int],
  cos: Array[Int],
  meta: Map[String, String] = Map.empty,
  extra: Map[String, Array[Double]] = Map.empty,
  comments: Seq[String] = Nil,
  warnings: Seq[String] = Nil
) {
  require(sin.length == cos.length, "sin and cos must have the same length")
  def length: Int = sin.length
  def linesPerRev: Option[Double] = meta.get("lines_per_rev").flatMap(moire.numbers.Decimal.double)
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
  /** Columns that hold a flag or a pin level, 0 or 1 (docs/recording.md). */
  val FlagColumns: Set[String] = Set("otr_sin", "otr_cos", "present", "over_range", "step_fault", "direction", "ref_a", "ref_b", "ref_z")
  /** The fastest sample rate a file may state (100 GS/s, beyond any ADC a read head is sampled with). */
  val MaxSampleRateHz = 1e11
  /** The slowest (one sample in about 12 days): below it a sample's time overflows or is no number. */
  val MinSampleRateHz = 1e-6

  /** Writes the file; metadata keys `sample_rate_hz`, `adc_bits`, `adc_format`, `samples` are set from the
    * recording; every other key (`adc`, free text naming the converter, among them) is kept as it is.
    */
  def write(path: os.Path, r: Recording): Unit = {
    val fixed = Seq("sample_rate_hz" -> fmt(r.sampleRateHz), "adc_bits" -> r.adc.bits.toString,
      "adc_format" -> r.adc.format.name, "samples" -> r.length.toString)
    val rest = r.meta.filter { case (k, _) => !fixed.exists(_._1 == k) }.toSeq.sortBy(_._1)
    val cols = r.extra.keys.toSeq.sorted
    val colData = cols.map(r.extra).toArray
    // streamed row by row: a file of 20 million rows is never held as text; a recording may replace a simulated one
    moire.files.SafeWrite.writesRecordings.withValue(true)(moire.files.SafeWrite(path) { tmp =>
      val w = new java.io.BufferedWriter(new java.io.OutputStreamWriter(java.nio.file.Files.newOutputStream(tmp.toNIO), "UTF-8"), 1 << 16)
      try {
        w.write(Magic); w.write('\n')
        for ((k, v) <- fixed ++ rest) { w.write("# "); w.write(k); w.write(": "); w.write(v); w.write('\n') }
        for (c <- r.comments) { w.write("# "); w.write(c); w.write('\n') }
        w.write((Seq("sin", "cos") ++ cols).mkString(",")); w.write('\n')
        val sb = new java.lang.StringBuilder(128)
        var i = 0
        while (i < r.length) {
          sb.setLength(0)
          sb.append(r.sin(i)).append(',').append(r.cos(i))
          var c = 0
          while (c < colData.length) { sb.append(',').append(fmt(colData(c)(i))); c += 1 }
          sb.append('\n'); w.append(sb); i += 1
        }
      } finally w.close()
    })
  }

  private def fmt(d: Double): String = if (d == math.rint(d) && math.abs(d) < 1e15) d.toLong.toString else d.toString

  /** Reads a file, streamed line by line into primitive arrays (the text is never held whole); any problem is
    * one RecordingError naming the file, the line and what is wrong.
    */
  def read(path: os.Path): Recording = {
    moire.files.PathKind.notAFile(path).foreach(m => throw new RecordingError(m))
    CsvText.checkText(path)
    val in = try CsvText.reader(path) catch {
      case e: java.io.IOException => throw new RecordingError(s"$path: cannot read (${moire.files.SafeWrite.reason(e)})")
    }
    try { val lines = CsvText.lineIterator(path, in); parse(path.toString, lines, () => lines.lastEnded) } finally in.close()
  }

  /** The code format: `adc_format` (offset-binary or twos-complement); files written before it held the
    * format under `adc`, which is free text now (`AD9226`): a format name there still counts, anything
    * else is a converter's name, and the codes are offset binary.
    */
  def format(meta: Map[String, String]): Either[String, AdcFormat] = meta.get("adc_format") match {
    case Some(f) => AdcFormat.parse(f).left.map(e => s"metadata adc_format: $e")
    case None => Right(meta.get("adc").flatMap(a => AdcFormat.parse(a).toOption).getOrElse(AdcFormat.OffsetBinary))
  }

  def parse(name: String, lines: IndexedSeq[String]): Recording = parse(name, lines.iterator)

  /** Parses lines as they come: metadata and header first, then the rows into growing primitive arrays.
    * `lastEnded` tells (once the lines are all taken) whether the last one had a line end: a last data row
    * without one may be cut short, and is left out with a warning.
    */
  def parse(name: String, lines: Iterator[String], lastEnded: () => Boolean = () => true): Recording = {
    def bad(line: Long, msg: String) = throw new RecordingError(s"$name:$line: $msg")
    val it = lines.buffered
    if (!it.hasNext) bad(1, "empty file, expected '# moire-recording v1'")
    val first = it.next()
    if (first.stripPrefix("\uFEFF").trim != Magic)
      bad(1, if (first.trim.isEmpty && !it.exists(_.trim.nonEmpty)) "empty file, expected '# moire-recording v1'" else s"first line must be '$Magic', got '${Shown.text(first)}'")
    val (meta, comments, headerAt, metaLine) = CsvText.header(name, it)
    def lineOf(k: String): Long = metaLine.getOrElse(k, headerAt + 1).toLong
    def need(k: String) = meta.getOrElse(k, bad(headerAt + 1, s"metadata '$k' is missing (a line '# $k: value' before the header)"))
    val fs = moire.numbers.Decimal.double(need("sample_rate_hz")).filter(v => v >= MinSampleRateHz && v <= MaxSampleRateHz)
      .getOrElse(bad(lineOf("sample_rate_hz"), s"metadata sample_rate_hz '${meta("sample_rate_hz")}' is not a sample rate (a number from 1e-6 to 1e11 Hz)"))
    val bits = moire.numbers.Decimal.int(need("adc_bits")).filter(b => b >= 4 && b <= 24)
      .getOrElse(bad(lineOf("adc_bits"), s"metadata adc_bits '${meta("adc_bits")}' is not an integer in 4..24"))
    val adc = Adc(bits, format(meta).fold(e => bad(lineOf(if (meta.contains("adc_format")) "adc_format" else "adc"), e), identity))
    if (!it.hasNext) bad(headerAt, "the header row 'sin,cos' is missing")
    val headerLine = it.next()
    val header = headerLine.split(",", -1).map(_.trim)
    header.groupBy(identity).collectFirst { case (c, cs) if cs.length > 1 => bad(headerAt + 1, s"column '$c' appears ${cs.length} times in the header") }
    val si = header.indexOf("sin"); val ci = header.indexOf("cos")
    if (si < 0 || ci < 0) bad(headerAt + 1, s"header must name columns sin and cos, got '${Shown.text(headerLine)}'")
    // the `samples` line sizes the arrays when it is there (checked against the rows at the end)
    val expect = meta.get("samples").flatMap(moire.numbers.Decimal.int).filter(n => n > 0 && n < Int.MaxValue - 8)
    // a hint only, never trusted for more than 4 Mi rows: a wrong `samples` line must not size the arrays
    val rows = new Rows(name, adc, header, si, ci, expect.fold(1 << 16)(math.min(_, 1 << 22)))
    var ln = headerAt + 1L
    var cut = 0L // the last line, when it has no line end
    // empty lines between data rows (those after the last row are a file's usual end): the first and how many
    var pending = 0L; var pendingAt = 0L; var blanks = 0L; var firstBlank = 0L
    while (it.hasNext) {
      val line = it.next(); ln += 1
      if (line.trim.isEmpty) { if (rows.n > 0) { if (pending == 0) pendingAt = ln; pending += 1 } }
      else {
        if (pending > 0) { if (firstBlank == 0) firstBlank = pendingAt; blanks += pending; pending = 0 }
        if (!it.hasNext && !lastEnded()) cut = ln else rows.add(line, ln)
      }
    }
    val n = rows.n
    val cutShort = "has no line end: the file may be cut short; end it with a line break if it is complete"
    if (n == 0) bad(headerAt + 1, if (cut == 0) "no data rows after the header" else s"no data rows after the header but the last line ($cut), which $cutShort")
    meta.get("samples").foreach { s =>
      if (moire.numbers.Decimal.long(s).isEmpty) bad(lineOf("samples"), s"metadata samples '${Shown.text(s)}' is not a whole number of rows")
      if (!moire.numbers.Decimal.long(s).contains(n.toLong))
        bad(ln, if (cut == 0) s"metadata samples says '$s' but the file has $n data rows: a truncated or edited file"
          else s"metadata samples says '$s' but the file has $n whole data rows; the last line ($cut), left out, $cutShort")
    }
    val warnings = (if (cut == 0) Nil else Seq(s"line $cut, the last, $cutShort; that row was left out")) ++
      (if (firstBlank == 0) Nil else Seq(s"line $firstBlank is empty among the data rows${if (blanks > 1) s" ($blanks such lines in all)" else ""}: " +
        "skipped, the rows around it taken as consecutive samples; if rows were lost there, the time base is off from there on"))
    def trim[A](a: Array[A], copy: (Array[A], Int) => Array[A]): Array[A] = if (a.length == n) a else copy(a, n)
    Recording(fs, adc, trim[Int](rows.sin, (a, k) => java.util.Arrays.copyOf(a, k)), trim[Int](rows.cos, (a, k) => java.util.Arrays.copyOf(a, k)), meta,
      rows.extraIdx.indices.map(e => header(rows.extraIdx(e)) -> trim[Double](rows.extra(e), (a, k) => java.util.Arrays.copyOf(a, k))).toMap, comments, warnings)
  }

  /** The data rows of a recording into growing primitive arrays, a row at a time (`add`): the common row of two plain
    * integers from a small method the JIT compiles at once, every other row the general way (which also words what is
    * wrong). One loop holding both was compiled as one method of 63 kB, four times, in 1.8 s of a 1 M explain's JIT (now 0.6 s).
    */
  private final class Rows(name: String, adc: Adc, header: Array[String], si: Int, ci: Int, cap0: Int) {
    private val bits = adc.bits
    val extraIdx: Array[Int] = header.indices.filter(i => i != si && i != ci).toArray
    // the documented flag columns (docs/recording.md): 0 or 1 only (a 2 read as set would pass as sense)
    private val flag: Array[Boolean] = extraIdx.map(c => Recording.FlagColumns.contains(header(c)))
    private val plainTwo = header.length == 2
    private var cap = cap0
    var sin = new Array[Int](cap); var cos = new Array[Int](cap)
    val extra: Array[Array[Double]] = Array.fill(extraIdx.length)(new Array[Double](cap))
    private val maxCode = (1 << bits) - 1
    // two's complement: signed codes (-2^(b-1)..2^(b-1)-1) or pin patterns (0..2^b-1), told apart by the values
    private val signedOk = adc.format == AdcFormat.TwosComplement
    private val minCode = if (signedOk) -(1 << (bits - 1)) else 0
    private var firstNegative = 0L; private var firstHigh = 0L
    var n = 0
    private val pair = new Array[Int](2)
    private var p = 0

    private def bad(line: Long, msg: String) = throw new RecordingError(s"$name:$line: $msg")
    private def badRow(ln: Long, line: String, msg: String) = bad(ln, s"$msg: '${Shown.text(line)}'")

    def add(line: String, ln: Long): Unit = {
      if (n == cap) grow(ln)
      if (plainTwo && twoInts(line)) { sin(n) = checked(pair(si), "sin", line, ln); cos(n) = checked(pair(ci), "cos", line, ln) }
      else general(line, ln)
      n += 1
    }

    private def grow(ln: Long): Unit = {
      if (cap >= Int.MaxValue / 2) bad(ln, s"more than $cap rows: too long for one recording")
      cap *= 2
      sin = java.util.Arrays.copyOf(sin, cap); cos = java.util.Arrays.copyOf(cos, cap)
      var e = 0
      while (e < extra.length) { extra(e) = java.util.Arrays.copyOf(extra(e), cap); e += 1 }
    }

    // a row "a,b" of two integers of at most 9 digits (a minus sign allowed, nothing else) into `pair`
    private def twoInts(line: String): Boolean = {
      p = 0
      if (!int(line, 0) || p >= line.length || line.charAt(p) != ',') return false
      p += 1
      int(line, 1) && p == line.length
    }
    private def digit(line: String, q: Int) = q < line.length && line.charAt(q) >= '0' && line.charAt(q) <= '9'
    private def int(line: String, k: Int): Boolean = {
      val len = line.length
      val neg = p < len && line.charAt(p) == '-'; if (neg) p += 1
      val d0 = p; var v = 0
      while (p - d0 < 9 && digit(line, p)) { v = v * 10 + (line.charAt(p) - '0'); p += 1 }
      pair(k) = if (neg) -v else v
      p > d0 && !digit(line, p)
    }

    // the code v of column col, checked: within the converter's range, signed codes and pin patterns not mixed
    private def checked(v: Int, col: String, line: String, ln: Long): Int = {
      if (v < minCode || v > maxCode)
        bad(ln, s"$col code $v is outside the $bits-bit ADC range ${if (signedOk) s"$minCode..$maxCode (signed codes or pin patterns)" else s"0..$maxCode"}: " +
          s"'${Shown.text(line)}'" +
          // a negative code in a file read as offset binary: signed codes, said how to declare them
          (if (!signedOk && v < 0 && v >= -(maxCode + 1) / 2) "; signed codes need the line '# adc_format: twos-complement' before the header (docs/recording.md)" else ""))
      if (v < 0) { if (firstNegative == 0) firstNegative = ln }
      else if (v > (maxCode >> 1) && firstHigh == 0) firstHigh = ln
      if (firstNegative != 0 && firstHigh != 0) mixed(ln)
      v & maxCode
    }
    private def mixed(ln: Long): Nothing =
      bad(ln, s"signed codes (a negative one on line $firstNegative) and pin patterns above ${maxCode >> 1} (line $firstHigh) in one file: " +
        "a two's-complement file holds one or the other")

    private def general(line: String, ln: Long): Unit = {
      if (line.startsWith("#")) badRow(ln, line, "a '#' line among the data rows (comments and metadata go before the header row)")
      val cells = line.split(",", -1)
      if (cells.length != header.length) badRow(ln, line, s"${cells.length} cells, the header has ${header.length}")
      def code(c: Int, col: String): Int =
        checked(moire.numbers.Decimal.int(cells(c)).getOrElse(badRow(ln, line, s"$col '${Shown.text(cells(c).trim)}' is not an integer ADC code")), col, line, ln)
      sin(n) = code(si, "sin"); cos(n) = code(ci, "cos")
      var e = 0
      while (e < extraIdx.length) {
        val c = extraIdx(e)
        extra(e)(n) = moire.numbers.Decimal.double(cells(c)).filter(v => !v.isNaN && !v.isInfinite)
          .getOrElse(badRow(ln, line, s"${Shown.text(header(c))} '${Shown.text(cells(c).trim)}' is not a finite number"))
        if (flag(e) && extra(e)(n) != 0 && extra(e)(n) != 1) badRow(ln, line, s"${header(c)} is a flag: 0 or 1, got '${Shown.text(cells(c).trim)}'")
        e += 1
      }
    }
  }
}

/** Shared text helpers of the two CSV formats. */
object CsvText {
  /** The longest line a text file of moire may hold (a recording's row is a few dozen characters). */
  val MaxLineChars: Int = 1 << 20

  /** All lines of a (small) text file, read through the bounded reader. */
  def lines(path: os.Path): IndexedSeq[String] = linesEnded(path)._1

  /** All lines of a (small) text file and whether the last had a line end (false: the file may be cut short). */
  def linesEnded(path: os.Path): (IndexedSeq[String], Boolean) = {
    checkText(path)
    val in = try reader(path) catch { case e: java.io.IOException => throw new RecordingError(s"$path: cannot read (${moire.files.SafeWrite.reason(e)})") }
    try { val it = lineIterator(path, in); val ls = it.toIndexedSeq; (ls, it.lastEnded) } finally in.close()
  }

  /** Refuses, from its first bytes, a file that is no text: gzip, UTF-16, a zip archive, NUL bytes. */
  def checkText(path: os.Path): Unit = Shown.binaryKind(path).foreach { k =>
    throw new RecordingError(s"$path: is $k; it starts with '${Shown.head(path, 16)}'")
  }

  /** A UTF-8 reader of a file; bytes that are not UTF-8 (a Latin-1 comment) become U+FFFD, never an error. */
  def reader(path: os.Path): java.io.BufferedReader =
    new java.io.BufferedReader(new java.io.InputStreamReader(java.nio.file.Files.newInputStream(path.toNIO), java.nio.charset.StandardCharsets.UTF_8), 1 << 16)

  /** The first line of a file ("" when empty), without reading the rest; a byte-order mark dropped. */
  def firstLine(path: os.Path): String = {
    val in = try CsvText.reader(path) catch {
      case e: java.io.IOException => throw new RecordingError(s"$path: cannot read (${moire.files.SafeWrite.reason(e)})")
    }
    try lineIterator(path, in).nextOption().getOrElse("") finally in.close()
  }

  /** The lines of an open reader (a byte-order mark dropped, CRLF or LF), read as they are asked for; a read
    * error is a RecordingError naming the file.
    */
  def lineIterator(path: os.Path, in: java.io.BufferedReader): Lines = new Lines(path, in)

  /** The lines of [[lineIterator]]; `lastEnded`, once `hasNext` is false, whether the last had a line end. */
  final class Lines(path: os.Path, in: java.io.BufferedReader) extends Iterator[String] {
    private val bounded = new BoundedLines(in, MaxLineChars, line => throw new RecordingError(
      if (line <= 1) s"$path:$line: a line longer than $MaxLineChars characters: not a moire text file (it starts with '${Shown.head(path, 16)}')"
      else s"$path:$line: a line longer than $MaxLineChars characters, more than a moire text file's lines hold (a metadata value or a row run together?)"))
    private var first = true
    private var nextLine: String = read()
    private def read(): String = try bounded.readLine() catch {
      case e: java.io.IOException => throw new RecordingError(s"$path: cannot read (${moire.files.SafeWrite.reason(e)})")
    }
    def hasNext: Boolean = nextLine != null
    def lastEnded: Boolean = bounded.lastEnded
    def next(): String = {
      val l = if (first) nextLine.stripPrefix("\uFEFF") else nextLine
      first = false
      nextLine = read()
      l
    }
  }

  /** A metadata key: a plain identifier (letters, digits, `_`, not starting with a digit). */
  private val Key = """[A-Za-z_][A-Za-z0-9_]*""".r

  /** The `#` lines after the first, taken from `it` (which is left at the first other line): `# key: value`
    * lines whose key is a plain identifier are metadata; every other `#` line is a comment, kept as its text
    * (`# exported by scope-dump rev 7 (CH1 = sin, CH2 = cos)`, `# taken at 12:30`). Returns the metadata, the
    * comments and the index (0-based line number) of the line after them.
    */
  def header(name: String, it: scala.collection.BufferedIterator[String]): (Map[String, String], Seq[String], Int, Map[String, Int]) = {
    var i = 1; val m = scala.collection.mutable.LinkedHashMap.empty[String, String]; val comments = Seq.newBuilder[String]
    val lineOf = Map.newBuilder[String, Int]
    while (it.hasNext && (it.head.startsWith("#") || it.head.trim.isEmpty)) {
      val line = it.next()
      val body = line.stripPrefix("#").trim
      if (body.nonEmpty) {
        val at = body.indexOf(':')
        val key = if (at > 0) body.substring(0, at).trim else ""
        if (Key.matches(key)) {
          if (m.contains(key)) throw new RecordingError(s"$name:${i + 1}: metadata key '$key' appears twice")
          m(key) = body.substring(at + 1).trim; lineOf += key -> (i + 1)
        } else comments += body
      }
      i += 1
    }
    (m.toMap, comments.result(), i, lineOf.result())
  }
}
