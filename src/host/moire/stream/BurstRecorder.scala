package moire.stream

import moire.protocol.{BurstLayout, Registers, StreamV1}
import moire.signal.AdcFormat

/** A burst request: N samples, the trigger, the samples before it, how long to wait for the trigger.
  * @param trigger `now`, `speed:T` (|speed| rises to T counts per [[Registers.SpeedWindow]] samples), `z` (the
  *                reference encoder's Z), `position:P` (the position crosses P counts)
  */
final case class BurstOptions(samples: Long, trigger: String = "now", pre: Long = 0, waitSeconds: Double = 10)

/** The trigger as register values: mode, threshold, target. */
final case class BurstTrigger(mode: Int, threshold: Long, target: Long)

object BurstTrigger {
  private val Speed = """speed:(\d+)""".r
  private val Position = """position:(-?\d+)""".r
  val help: String = "now, speed:T (counts per 1024 samples), z, or position:P (counts)"
  def parse(s: String): Either[String, BurstTrigger] = s.trim match {
    case "now" => Right(BurstTrigger(BurstLayout.Trigger.Immediate, 0, 0))
    case "z" => Right(BurstTrigger(BurstLayout.Trigger.RefZ, 0, 0))
    case Speed(t) if t.length <= 10 && t.toLong <= StreamV1.MaxU32 => Right(BurstTrigger(BurstLayout.Trigger.Speed, t.toLong, 0))
    case Position(p) if p.length <= 11 && p.toLong >= Int.MinValue && p.toLong <= Int.MaxValue =>
      Right(BurstTrigger(BurstLayout.Trigger.Position, 0, p.toLong & StreamV1.MaxU32))
    case other => Left(s"--trigger '$other' is not one of: $help")
  }
}

/** `moire record --burst N`: arm the board's burst capture, wait for the trigger, have the burst sent, write a
  * full-rate moire-recording v1 (sample rate = ADC clock) with the reference count of every sample
  * (docs/recording.md). Losses on the link are counted in the summary and the metadata; a burst with
  * missing samples is not written (the error says how many are missing).
  */
object BurstRecorder {
  def validate(o: RecordOptions, b: BurstOptions): Unit = {
    if (o.listenOnly) throw new StreamError("--burst needs commands to the board; it cannot be combined with --listen-only")
    if (b.samples < 1 || b.samples > (1L << 20)) throw new StreamError(s"--burst must be in 1..${1 << 20} samples, got ${b.samples}")
    if (b.pre < 0 || b.pre >= b.samples) throw new StreamError(s"--pre must be in 0..${b.samples - 1} (below --burst), got ${b.pre}")
    if (!(b.waitSeconds > 0) || b.waitSeconds > 86400) throw new StreamError(s"--seconds (the time to wait for the trigger) must be in (0, 86400], got ${b.waitSeconds}")
    BurstTrigger.parse(b.trigger).left.foreach(e => throw new StreamError(e))
  }

  def run(o: RecordOptions, b: BurstOptions, say: String => Unit, warn: String => Unit): RecordResult = {
    validate(o, b)
    Recorder.validate(o)
    val link = SerialLink.open(o.port, o.baud)
    try record(link, o, b, say, warn) finally link.close()
  }

  def record(link: ByteLink, o: RecordOptions, b: BurstOptions, say: String => Unit, warn: String => Unit): RecordResult = {
    validate(o, b)
    val file = os.Path(o.out, os.pwd)
    moire.files.SafeWrite.checkFile(file)   // before the burst, which may never come again
    val c = new BoardClient(link, o.timeoutMs)
    BoardClient.check(c, o.baud, "")
    def ask(f: => Long): Long = try f catch { case e: NoAnswer => throw new StreamError(e.getMessage) }
    val version = ask(c.read(Registers.Version))
    if (version < 2) throw new StreamError(s"${o.port}: the board speaks stream format version $version, which has no burst capture; rebuild it with this moire")
    val depth = ask(c.read(Registers.BurstDepth))
    if (b.samples > depth) throw new StreamError(s"--burst ${b.samples}: the board holds at most $depth samples")
    val (clk, fmt, m) = Recorder.adcSetup(c, o, ask(_))
    val t = BurstTrigger.parse(b.trigger).toOption.get
    for ((r, v) <- Seq(Registers.BurstLength -> b.samples, Registers.BurstPre -> b.pre, Registers.BurstTrigger -> t.mode.toLong,
      Registers.BurstThreshold -> t.threshold, Registers.BurstTarget -> t.target)) {
      val got = ask(c.write(r.addr, v))
      if (got != v) throw new StreamError(s"${o.port}: wrote ${r.name} $v, the board kept $got")
    }
    ask(c.write(Registers.BurstControl.addr, 1L << Registers.BurstControlBit.Arm))
    say(s"armed: ${b.samples} samples at ${Recorder.num(clk)} Hz, ${b.pre} before the trigger (${b.trigger}); waiting up to ${b.waitSeconds} s")
    val t0 = System.nanoTime()
    var state = ask(c.read(Registers.BurstState))
    while ((state & 3) != moire.io.BurstState.Done) {
      if (System.nanoTime() - t0 > b.waitSeconds * 1e9) {
        val what = Seq("idle", "waiting for the trigger", "capturing", "done")((state & 3).toInt)
        throw new StreamError(f"${o.port}: no burst within ${b.waitSeconds}%.1f s (state: $what); check the trigger (${b.trigger}) or give more --seconds")
      }
      Thread.sleep(20)
      state = ask(c.read(Registers.BurstState))
    }
    c.takeBurstFrames()
    val before = c.decoder.stats
    ask(c.write(Registers.BurstControl.addr, 1L << Registers.BurstControlBit.Send))
    val (info, samples) = collect(c, o, b)
    val st = c.decoder.stats
    val lost = Seq(st.crcErrors - before.crcErrors -> "frame(s) failed the CRC", st.seqMissing - before.seqMissing -> "frame(s) missing (seq gaps)",
      st.burstMissing - before.burstMissing -> "burst samples missing").collect { case (n, w) if n > 0 => s"$n $w" }
    val meta = Map("source" -> "board burst", "adc" -> "AD9226", "adc_clock_hz" -> Recorder.num(clk), "counts_per_period" -> m.toString,
      "burst_trigger" -> b.trigger, "port" -> o.port, "baud" -> o.baud.toString,
      "crc_errors" -> (st.crcErrors - before.crcErrors).toString, "missing_frames" -> (st.seqMissing - before.seqMissing).toString,
      "captured_utc" -> java.time.Instant.now().toString) ++ Recorder.refMeta(o)
    val (rec, check) = try BurstAssembler.recording(info, samples, clk, fmt, meta) catch {
      case e: StreamError => throw new StreamError(e.getMessage + (if (lost.nonEmpty) s" (${lost.mkString(", ")})" else ""))
    }
    val saved = KeepRecording(file, rec, "moire-burst")
    val elapsed = (System.nanoTime() - t0) / 1e9
    say(f"wrote ${saved.file}: burst of ${rec.length} samples at ${Recorder.num(clk)} Hz (${b.pre} before the trigger at sample index ${info.trigger.index}) in $elapsed%.2f s")
    say(s"reference count: ${check.refSkips} A/B steps skipped" + check.triggerError.fold("")(e => s", rebuilt minus board count at the trigger $e"))
    val warnings = (if (lost.nonEmpty) Seq(s"WARNING: data lost on the link: ${lost.mkString(", ")}") else Nil) ++
      (if (check.refSkips > 0 || check.triggerError.exists(_ != 0)) Seq("WARNING: the reference count rebuilt from the A/B pins disagrees with the board's counter (see ref_skips, ref_trigger_error in the file)") else Nil)
    warnings.foreach(warn)
    saved.failure.foreach(f => throw new StreamError(s"$f; the burst of ${rec.length} samples is in ${saved.file} instead"))
    RecordResult(file, rec.length, st, BoardSetup(1, clk, fmt, m, None, fromBoard = true), rec.meta, warnings)
  }

  /** The info frame and sample frames until the burst is complete, or the time the link needs plus 2 s. */
  private def collect(c: BoardClient, o: RecordOptions, b: BurstOptions): (BurstInfo, Seq[BurstSamples]) = {
    val buf = new Array[Byte](4096)
    var info: Option[BurstInfo] = None
    val samples = scala.collection.mutable.ArrayBuffer.empty[BurstSamples]
    def take(fs: Seq[Frame]): Unit = fs.foreach {
      case i: BurstInfo => info = Some(i); samples.clear()
      case s: BurstSamples => samples += s
      case _ =>
    }
    take(c.takeBurstFrames())
    val bytes = StreamV1.BurstInfoBytes + b.samples * 4 + (b.samples / StreamV1.BurstFrameWords + 1) * StreamV1.burstFrameBytes(0)
    val limit = System.nanoTime() + ((bytes * 10.0 / o.baud * 1.5 + 2) * 1e9).toLong
    val bar = if (o.quiet) None else Some(new moire.progress.Bar("burst", b.samples, " samples", 10, plainGapS = moire.progress.Bar.CaptureGapS))
    def got = samples.map(_.words.size.toLong).sum
    try {
      while (System.nanoTime() < limit && !(info.isDefined && got >= info.get.length)) {
        val n = c.link.read(buf)
        if (n > 0) take(c.decoder.feed(buf, 0, n))
        bar.foreach(_.stepTo(math.min(got, b.samples)))
      }
    } finally bar.foreach(_.close())
    val i = info.getOrElse(throw new StreamError(s"${o.port}: the board sent no burst info frame (${c.decoder.stats.bytes} bytes received)"))
    (i, samples.toSeq)
  }
}
