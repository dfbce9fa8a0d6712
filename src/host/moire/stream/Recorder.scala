package moire.stream

import moire.protocol.{Registers, StreamV1}
import moire.recording.Recording
import moire.signal.{Adc, AdcFormat}
import scala.collection.mutable.ArrayBuffer

/** Options of `moire record`. `None` = read the value from the board's registers. */
final case class RecordOptions(
  port: String,
  seconds: Double,
  out: String,
  baud: Int = 115200,
  decimation: Option[Long] = None,
  adcClockHz: Option[Double] = None,
  adcFormat: Option[String] = None,
  countsPerPeriod: Option[Long] = None,
  listenOnly: Boolean = false,
  timeoutMs: Int = 500,
  quiet: Boolean = false,
  refCountsPerPeriod: Option[Double] = None,
  refCountsPerTurn: Option[Double] = None
)

/** What the board told us (or the user, by hand) before recording. */
final case class BoardSetup(decimation: Long, adcClockHz: Double, adc: AdcFormat, countsPerPeriod: Long,
                            frameRecords: Option[Long], fromBoard: Boolean) {
  def sampleRateHz: Double = adcClockHz / decimation
}

/** A finished recording: the file written, the decoder's figures and the warning lines printed. */
final case class RecordResult(file: os.Path, rows: Int, stats: StreamStats, setup: BoardSetup, meta: Map[String, String],
                              warnings: Seq[String])

/** `moire record`: board setup by register commands, a timed read of the stream, a moire-recording v1 file.
  *
  * The recording starts after the setup and after the first frame whose records are D apart (records
  * that were waiting in the board's FIFO at the old decimation are not recorded), and ends at the first frame
  * boundary after `seconds`. Every loss after that start is counted, printed and written to the metadata.
  */
object Recorder {
  /** Records per second the link carries at `baud` with n records per frame (10 bits per byte on the wire). */
  def linkRecordsPerSecond(baud: Int, n: Long): Double = baud / 10.0 / StreamV1.recordFrameBytes(n.toInt) * n

  /** The fastest ADC clock a board can run (its system clock's limit, 200 MHz). */
  val MaxAdcClockHz = 200e6
  /** The slowest ADC clock taken (1 kHz): below it no pipelined converter holds its samples, and a mistyped 1.5 made a
    * 1 s recording of 392 records at 0.000015 Hz, read as 302 days.
    */
  val MinAdcClockHz = 1e3

  def validate(o: RecordOptions): Unit = {
    if (!(o.seconds > 0) || o.seconds > 86400) throw new StreamError(s"--seconds must be in (0, 86400], got ${o.seconds}")
    if (o.baud < 300 || o.baud > 12000000) throw new StreamError(s"--baud must be in 300..12000000, got ${o.baud}")
    o.decimation.foreach(d => if (d < 1 || d > Registers.MaxDecimation) throw new StreamError(s"--decimation must be in 1..${Registers.MaxDecimation}, got $d"))
    o.adcClockHz.foreach(f => if (!(f >= MinAdcClockHz) || f > MaxAdcClockHz)
      throw new StreamError(s"--adc-clock-hz must be from ${MinAdcClockHz.toLong} to ${MaxAdcClockHz.toLong} Hz (an ADC clock a board runs), got $f"))
    o.adcFormat.foreach(f => AdcFormat.parse(f).left.foreach(e => throw new StreamError(s"--adc-format: $e")))
    o.countsPerPeriod.foreach(m => if (!countsOk(m))
      throw new StreamError(s"--counts-per-period must be a power of two from 4 to 65536 (the board's M, counts per grating period), got $m"))
    for ((k, v) <- Seq("--ref-counts-per-period" -> o.refCountsPerPeriod, "--ref-counts-per-turn" -> o.refCountsPerTurn); x <- v)
      if (!(x > 0) || x.isInfinite) throw new StreamError(s"$k must be a positive finite number, got $x")
    if (o.refCountsPerPeriod.isDefined && o.refCountsPerTurn.isDefined) throw new StreamError("give --ref-counts-per-period or --ref-counts-per-turn, not both")
    if (o.timeoutMs < 10 || o.timeoutMs > 60000) throw new StreamError(s"--timeout-ms must be in 10..60000, got ${o.timeoutMs}")
    if (o.listenOnly) {
      val missing = Seq("--decimation" -> o.decimation, "--adc-clock-hz" -> o.adcClockHz, "--adc-format" -> o.adcFormat,
        "--counts-per-period" -> o.countsPerPeriod).collect { case (k, None) => k }
      if (missing.nonEmpty) throw new StreamError(s"--listen-only sends no commands, so give ${missing.mkString(", ")} by hand")
    }
    if (o.port.trim.isEmpty) throw new StreamError("--port is empty: name a serial port, e.g. /dev/ttyUSB0")
    moire.files.SafeWrite.refuseInputs(o.out, Seq(o.port))   // the port's link is no output
    moire.files.SafeWrite.checkFile(os.Path(o.out, os.pwd))   // before the port is opened and the capture runs
    moire.files.SafeWrite.checkKind(os.Path(o.out, os.pwd), "a moire recording") // (notes under its name: refused now, not after it)
  }

  /** Opens the port and records; `say` gets the summary lines, `warn` the notes and warnings (stderr). */
  def run(o: RecordOptions, say: String => Unit, warn: String => Unit): RecordResult = {
    validate(o)
    val link = SerialLink.open(o.port, o.baud)
    try record(link, o, say, warn) finally link.close()
  }

  private val handHint = "; to record without commands give --listen-only with --decimation, --adc-clock-hz, --adc-format and --counts-per-period"

  /** Register reads and the optional decimation write; hand values win over registers. `hint` ends an error of a
    * board that does not answer (record's --listen-only; none for the monitor, which has no such option).
    */
  def setup(c: BoardClient, o: RecordOptions, hint: String = handHint): BoardSetup = {
    BoardClient.check(c, o.baud, hint)
    def ask[T](f: => T): T = try f catch { case e: NoAnswer => throw new StreamError(e.getMessage + hint) }
    val ctl = ask(c.read(Registers.Control))
    if (((ctl >> Registers.ControlBit.Enable) & 1) == 0)
      throw new StreamError(s"${o.port}: streaming is off on the board (control = $ctl); switch it on with: moire board-reg --port ${o.port} --write control=1")
    val d = o.decimation match {
      case Some(want) =>
        val got = ask(c.write(Registers.Decimation.addr, want))
        if (got != want) throw new StreamError(s"${o.port}: wrote decimation $want, the board kept $got")
        got
      case None => ask(c.read(Registers.Decimation))
    }
    if (d < 1) throw new StreamError(s"${o.port}: the board reports decimation $d; give --decimation")
    val (clk, fmt, m) = adcSetup(c, o, ask(_))
    val n = ask(c.read(Registers.FrameRecords))
    BoardSetup(d, clk, fmt, m, Some(n).filter(v => v >= 1 && v <= StreamV1.MaxFrameRecords), fromBoard = true)
  }

  /** ADC clock, code format and counts per period: from the options, else read from the board. */
  def adcSetup(c: BoardClient, o: RecordOptions, ask: (=> Long) => Long): (Double, AdcFormat, Long) = {
    val clk = o.adcClockHz.getOrElse(ask(c.read(Registers.AdcClockHz)).toDouble)
    if (!(clk > 0)) throw new StreamError(s"${o.port}: the board reports adc_clock_hz 0; give --adc-clock-hz")
    val fmt = o.adcFormat.map(s => AdcFormat.parse(s).toOption.get).getOrElse(ask(c.read(Registers.AdcFormat)) match {
      case Registers.AdcOffsetBinary => AdcFormat.OffsetBinary
      case Registers.AdcTwosComplement => AdcFormat.TwosComplement
      case v => throw new StreamError(s"${o.port}: the board reports adc_format $v (0 or 1 expected); give --adc-format")
    })
    val m = o.countsPerPeriod.getOrElse(ask(c.read(Registers.CountsPerPeriod)))
    // a file with another M is one that explain, replay and the monitor refuse: asked for now, not after the recording
    if (!countsOk(m)) throw new StreamError(s"${o.port}: the board reports counts_per_period $m (a power of two from 4 to 65536 expected); give --counts-per-period")
    (clk, fmt, m)
  }
  /** A moire board's subdivider counts M per period, a power of two (`SubdivConfig`): another value is no board's. */
  def countsOk(m: Long): Boolean = m >= 4 && m <= 65536 && (m & (m - 1)) == 0

  def record(link: ByteLink, o: RecordOptions, say: String => Unit, warn: String => Unit): RecordResult = {
    validate(o)
    val client = new BoardClient(link, o.timeoutMs)
    val s = if (o.listenOnly) BoardSetup(o.decimation.get, o.adcClockHz.get, AdcFormat.parse(o.adcFormat.get).toOption.get,
      o.countsPerPeriod.get, None, fromBoard = false) else setup(client, o)
    capacityWarning(s, o.baud).foreach(warn)
    val start = settle(client, o, s)
    // from here on Ctrl-C keeps what arrived: the capture ends early and the file is written before the JVM ends
    moire.files.Interrupts.stoppable(stop => keep(capture(link, o, s, start, stop), o, s, say, warn))
  }

  /** Writes the records captured and says so; fails (after writing them) when the link failed, Ctrl-C stopped the
    * capture, or the file had to go elsewhere.
    */
  private def keep(c: Captured, o: RecordOptions, s: BoardSetup, say: String => Unit, warn: String => Unit): RecordResult = {
    val (rec, stats, elapsed) = (c.cols, c.stats, c.elapsed)
    val upTo = f"after $elapsed%.2f s of ${num(o.seconds)}"
    c.failed.filter(_ => rec.rows == 0).foreach(e => throw e)
    if (c.interrupted && rec.rows == 0) throw new StreamError(s"interrupted $upTo s, before any record arrived; no file written")
    if (stats.frames == 0) throw new StreamError(s"${o.port}: no frames in ${o.seconds} s at ${o.baud} baud after the start " +
      s"(${stats.bytes} bytes): the board stopped streaming?")
    if (rec.rows == 0) throw new StreamError(s"${o.port}: ${stats.frames} frames but no records in ${o.seconds} s: is streaming on (control bit0)?")
    val clock = ClockCheck.measured(c.span, stats, o.baud)
    val meta = metadata(o, s, stats, elapsed) ++ c.failed.map(_ => "link_failed_after_s" -> f"$elapsed%.3f") ++
      (if (c.interrupted) Some("interrupted_after_s" -> f"$elapsed%.3f") else None) ++
      clock.map(m => "adc_clock_measured_hz" -> num(ClockCheck.round3(m)))
    val saved = KeepRecording(os.Path(o.out, os.pwd), rec.recording(s, meta), "moire-record")
    val file = saved.file
    val summary = Seq(
      f"wrote $file: ${rec.rows} records at ${num(s.sampleRateHz)} Hz (adc clock ${num(s.adcClockHz)} Hz / D ${s.decimation}) in $elapsed%.2f s",
      s"frames ${stats.frames}, records ${stats.records}, CRC errors ${stats.crcErrors}, bad headers ${stats.badHeaders}, " +
        s"seq gaps ${stats.seqGaps} (${stats.seqMissing} frames), sample-index gaps ${stats.indexGaps} (${stats.indexMissing} records), " +
        s"dropped records ${stats.dropped}, truncated ${stats.truncated}")
    summary.foreach(say)
    val clockWarning = ClockCheck.warning(clock, s, byHand = o.adcClockHz.isDefined)
    // a wrong clock makes the records look late or early; a link that failed ends them: neither is a stream that stopped
    val stopped = if (c.failed.isDefined || clockWarning.isDefined) None else stoppedWarning(rec.rows, stats, s, o.baud, elapsed)
    val warnings = lossWarning(stats).toSeq ++ clockWarning ++ stopped
    warnings.foreach(warn)
    // the link gone mid-recording (a cable pulled), Ctrl-C, a disk full at the end: the records that arrived are in a
    // file, and the command fails naming it
    val ended = c.failed.map(e => s"${e.getMessage.stripSuffix(".")} $upTo").orElse(if (c.interrupted) Some(s"interrupted $upTo s") else None)
    val where = saved.failure.fold(s"$file holds the ${rec.rows} records received")(f => s"$f; the ${rec.rows} records received are in $file instead")
    if (ended.isDefined || saved.failure.isDefined) throw new StreamError((ended.toSeq :+ where).mkString("; "))
    RecordResult(file, rec.rows, stats, s, meta, warnings)
  }

  /** A WARNING when the board makes more records per second than the link carries (n known from the board). */
  def capacityWarning(s: BoardSetup, baud: Int): Option[String] = s.frameRecords.flatMap { n =>
    val cap = linkRecordsPerSecond(baud, n)
    if (s.sampleRateHz <= cap) None
    else Some(f"WARNING: the board makes ${s.sampleRateHz}%.0f records/s, $baud%d baud carries at most $cap%.0f: " +
      f"records will be dropped; use --decimation ${math.ceil(s.adcClockHz / cap).toLong}%d or more")
  }

  /** Records that arrived short of this share of those due (at the board's rate, or the link's where it is slower) mean
    * the stream stopped or paused part-way: a board reset, a FIFO stuck, streaming switched off by another program.
    */
  val MinDueShare = 0.3

  /** A WARNING when far fewer records arrived than the board makes in the time recorded (the frames said nothing lost:
    * a stream that stops sends no frame to miss). 512 records in 6.09 s at 500 Hz passed as a good recording.
    */
  def stoppedWarning(rows: Long, st: StreamStats, s: BoardSetup, baud: Int, elapsed: Double): Option[String] = {
    val perFrame = math.max(1L, math.round(st.records.toDouble / math.max(1L, st.frames)))
    val rate = math.min(s.sampleRateHz, linkRecordsPerSecond(baud, perFrame)); val due = rate * elapsed
    if (!(rows < MinDueShare * due && due - rows > 4 * perFrame)) None
    else Some(f"WARNING: $rows records arrived in $elapsed%.2f s, where ${rate}%.0f a second were due (about ${due}%.0f): the stream " +
      "stopped or paused part-way (a board reset, streaming switched off); the file holds the records received")
  }

  /** One WARNING line when anything was lost, naming each figure that is not zero. */
  def lossWarning(st: StreamStats): Option[String] = {
    val parts = Seq(
      st.crcErrors -> s"${st.crcErrors} frame(s) failed the CRC", st.badHeaders -> s"${st.badHeaders} frame(s) had a bad header",
      st.seqGaps -> s"${st.seqGaps} seq gaps (${st.seqMissing} frames missing)",
      st.indexGaps -> s"${st.indexGaps} sample-index gaps (${st.indexMissing} records missing)",
      st.dropped -> s"the board dropped ${st.dropped} record(s) (FIFO overflow)",
      st.truncated -> s"the stream ended inside a frame").collect { case (n, t) if n > 0 => t }
    if (parts.isEmpty) None else Some(s"WARNING: data lost: ${parts.mkString(", ")}; the file holds every record received and these figures (docs/recording.md)")
  }

  private def metadata(o: RecordOptions, s: BoardSetup, st: StreamStats, elapsed: Double): Map[String, String] = Map(
    "source" -> "de2-115", "adc" -> "AD9226", "decimation" -> s.decimation.toString, "adc_clock_hz" -> num(s.adcClockHz),
    "counts_per_period" -> s.countsPerPeriod.toString, "frames" -> st.frames.toString, "records" -> st.records.toString,
    "crc_errors" -> st.crcErrors.toString, "bad_headers" -> st.badHeaders.toString, "gaps" -> st.indexGaps.toString,
    "missing_records" -> st.indexMissing.toString, "dropped_records" -> st.dropped.toString, "seq_gaps" -> st.seqGaps.toString,
    "missing_frames" -> st.seqMissing.toString, "truncated" -> st.truncated.toString, "skipped_bytes" -> st.skippedBytes.toString,
    "port" -> o.port, "baud" -> o.baud.toString, "seconds" -> f"$elapsed%.3f",
    "setup" -> (if (s.fromBoard) "registers" else "by hand (listen-only)"),
    "started_utc" -> java.time.Instant.now().minusMillis((elapsed * 1000).toLong).toString) ++ refMeta(o)

  /** Metadata naming the scale of the `ref_counts` column, as given by the user. */
  def refMeta(o: RecordOptions): Map[String, String] =
    o.refCountsPerPeriod.map(v => "ref_counts_per_period" -> num(v)).toMap ++ o.refCountsPerTurn.map(v => "ref_counts_per_turn" -> num(v))

  /** A number for the file's metadata: whole numbers as integers, others as Java writes a double (read back exactly). */
  def num(d: Double): String = if (d == math.rint(d) && math.abs(d) < 1e15) d.toLong.toString else java.lang.Double.toString(d)

  /** Hunts the stream for the first record frame whose records are D apart (with n = 1: D after the previous
    * frame's record); returns the bytes after that frame.
    */
  private def settle(c: BoardClient, o: RecordOptions, s: BoardSetup): Array[Byte] = {
    val dec = new Decoder(s.decimation)
    dec.feed(c.decoder.pending)
    val buf = new Array[Byte](4096)
    // --seconds, plus the time to empty a full 1024-record FIFO at the link rate (old-decimation records may wait
    // there), plus two frames at the record rate (slow when D is large)
    val n = s.frameRecords.getOrElse(8L)
    val limitS = o.seconds + 1024 * 12.5 * 10 / o.baud + 2.0 * n / s.sampleRateHz
    val until = System.nanoTime() + (limitS * 1e9).toLong
    var last = -1L; var lastSeq = -1
    val steps = scala.collection.mutable.LinkedHashSet.empty[Long]
    var frames = Vector.empty[Frame]
    while (System.nanoTime() < until) {
      val n = c.link.read(buf)
      if (n > 0) {
        // byte by byte: stop right after the first frame that qualifies, the rest goes to the recording
        var i = 0
        while (i < n) {
          dec.feed(buf, i, 1).foreach {
            case f: RecordFrame =>
              val idx = f.records.map(_.index)
              val firstOk = last >= 0 && f.seq == ((lastSeq + 1) & 0xFFFF) && ((idx.head - last) & StreamV1.MaxU32) == s.decimation
              val inner = idx.sliding(2).forall(p => p.size < 2 || ((p(1) - p(0)) & StreamV1.MaxU32) == s.decimation)
              idx.sliding(2).foreach(p => if (p.size == 2 && steps.size < 5) steps += ((p(1) - p(0)) & StreamV1.MaxU32))
              if (inner && (idx.size >= 2 || firstOk)) return java.util.Arrays.copyOfRange(buf, i + 1, n)
              last = idx.last; lastSeq = f.seq
            case r: RegisterReply => lastSeq = r.seq
            case _ => ()   // burst frames belong to a burst capture, not to the stream being settled
          }
          i += 1
        }
      }
    }
    val st = dec.stats
    val got = if (st.bytes == 0) "nothing received" else s"${st.bytes} bytes but ${st.recordFrames} record frames"
    if (st.recordFrames == 0)
      throw new StreamError(f"${o.port}: no frames in $limitS%.1f s at ${o.baud} baud ($got): check --baud, the wiring " +
        "(board TXD -> host RXD) and that streaming is on")
    throw new StreamError(f"${o.port}: records are ${steps.mkString(", ")} samples apart, never the decimation ${s.decimation} " +
      f"in one frame in $limitS%.1f s: wrong --decimation?")
  }

  /** Growing columns of the records received. */
  private final class Columns {
    val sin = ArrayBuffer.empty[Int]; val cos = ArrayBuffer.empty[Int]
    val extra: Map[String, ArrayBuffer[Double]] = (RecordColumns.extra :+ RecordColumns.ref).map(_ -> ArrayBuffer.empty[Double]).toMap
    private var lastRaw = -1L; private var unwrapped = 0L
    def rows: Int = sin.length
    /** The last record's sample index, unwrapped past 2^32. */
    def lastIndex: Long = unwrapped
    def add(r: Record): Unit = {
      if (lastRaw < 0) unwrapped = r.index
      else { val d = (r.index - lastRaw) & StreamV1.MaxU32; unwrapped += (if (d >= (1L << 31)) d - (1L << 32) else d) }
      lastRaw = r.index
      sin += r.sin; cos += r.cos
      RecordColumns.values(r, unwrapped).foreach { case (k, v) => extra(k) += v }
      r.ref.foreach(v => extra(RecordColumns.ref) += v)
    }
    /** The columns; the reference count only when every record carried it (boards of version 2). */
    def recording(s: BoardSetup, meta: Map[String, String]): Recording =
      Recording(s.sampleRateHz, Adc(12, s.adc), sin.toArray, cos.toArray, meta,
        extra.collect { case (k, v) if k != RecordColumns.ref || v.length == rows => k -> v.toArray })
  }

  /** What `capture` got: the records, their figures and seconds, the link's failure when it failed on the way (what
    * arrived before it is kept), whether Ctrl-C ended it, and the arrivals that time the sample index.
    */
  private final case class Captured(cols: Columns, stats: StreamStats, elapsed: Double, failed: Option[StreamError],
                                    interrupted: Boolean, span: Option[ClockCheck.Span])

  /** Reads for `seconds` (or until `stop` is requested), then to the end of the frame in progress (at most 1 s more). */
  private def capture(link: ByteLink, o: RecordOptions, s: BoardSetup, first: Array[Byte], stop: moire.files.Interrupts.Stop): Captured = {
    val t0 = System.nanoTime()
    val dec = new Decoder(s.decimation)
    val cols = new Columns
    var span: Option[ClockCheck.Span] = None
    def take(fs: Vector[Frame]): Unit = fs.foreach {
      case f: RecordFrame if f.records.nonEmpty =>
        f.records.foreach(cols.add)
        val now = System.nanoTime()
        if (now - t0 >= ClockCheck.SkipSeconds * 1e9)
          span = Some(span.fold(ClockCheck.Span.first(now, cols.lastIndex))(_.next(now, cols.lastIndex)))
      case _ =>
    }
    val buf = new Array[Byte](4096)
    val deadline = t0 + (o.seconds * 1e9).toLong
    // in a log or a pipe a line every 10 s at most, not one each tenth of a short recording
    val bar = if (o.quiet) None else Some(new moire.progress.Bar("record", math.ceil(o.seconds * 10).toLong, " s", 10,
      plainGapS = moire.progress.Bar.CaptureGapS))
    var failed: Option[StreamError] = None
    try try {
      take(dec.feed(first))
      while (System.nanoTime() < deadline && !stop.requested) {
        val n = link.read(buf)
        if (n > 0) take(dec.feed(buf, 0, n))
        bar.foreach { b =>
          b.stepTo(math.min(b.getMax, (System.nanoTime() - t0) / 100000000L))
          val st = dec.stats
          b.setExtraMessage(s" ${st.frames} frames, ${st.records} records" + (if (st.lost) " (losses, see summary)" else ""))
        }
      }
      val grace = System.nanoTime() + 1000000000L
      var done = dec.buffered == 0
      while (!done && System.nanoTime() < grace) {
        val n = link.read(buf)
        var i = 0
        while (i < n && !done) { val fs = dec.feed(buf, i, 1); take(fs); done = fs.nonEmpty || dec.buffered == 0; i += 1 }
      }
      take(dec.finish())
    } catch {
      // a port that fails as the JVM ends was closed by its library's own hook: Ctrl-C, not a cable pulled
      case e: StreamError => if (!stop.requested && !moire.files.Interrupts.shuttingDown) failed = Some(e); take(dec.finish())
    }
    finally bar.foreach(_.close())
    val elapsed = (System.nanoTime() - t0) / 1e9
    val interrupted = failed.isEmpty && (stop.requested || moire.files.Interrupts.shuttingDown) && elapsed < o.seconds
    Captured(cols, dec.stats, elapsed, failed, interrupted, span)
  }
}

/** The extra columns of a board recording, in one place (names fixed by stream format v1). */
object RecordColumns {
  val extra: Seq[String] = Seq("sample_index", "position", "otr_sin", "otr_cos", "present", "over_range", "step_fault", "direction")
  /** The reference encoder's count (records of frame type 0x05): the reference trajectory for explain. */
  val ref: String = "ref_counts"
  private def b(f: Boolean): Double = if (f) 1.0 else 0.0
  /** Values of the extra columns; `index` is the sample index unwrapped past 2^32. */
  def values(r: Record, index: Long): Seq[(String, Double)] = Seq("sample_index" -> index.toDouble, "position" -> r.position.toDouble,
    "otr_sin" -> b(r.otrSin), "otr_cos" -> b(r.otrCos), "present" -> b(r.present), "over_range" -> b(r.overRange),
    "step_fault" -> b(r.stepFault), "direction" -> b(r.direction))
}
