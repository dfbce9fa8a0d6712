package moire.stream

/** The ADC clock a stream's own sample index shows: the index's advance between the first and the last record frame
  * over the wall time between their arrivals. A clock stated wrong (`--adc-clock-hz 1000` for a 50 MHz board) gives a
  * file whose sample rate and times are off by that factor (504 records at 0.01 Hz: 50,400 s for 1 s recorded), and
  * nothing in the file shows it later. A burst has no such check: it is captured into the board's memory and read out
  * afterwards, so its wall time says nothing of its clock.
  */
object ClockCheck {
  /** Frames that arrive this soon after the start are not timed: bytes that waited in the host's buffers (a pty holds
    * seconds of them) come in at once, and 1600 records in the first 0.1 s made a 2 s recording's clock 2.6 times too fast.
    */
  val SkipSeconds = 0.25
  /** The arrivals measured: below this time or these frames a frame's jitter on the link would count. */
  val MinSeconds = 0.5
  val MinFrames = 4
  /** A clock off by more than this factor either way is warned of (a board's FIFO draining at the link's pace after
    * the start makes records arrive up to about 1.7 times as fast as they are made, for a second or two).
    */
  val MaxFactor = 2.0

  /** The first and last record frame's arrival (System.nanoTime) and last record's sample index (unwrapped). */
  final case class Span(firstNs: Long, firstIndex: Long, lastNs: Long, lastIndex: Long, frames: Long) {
    def seconds: Double = (lastNs - firstNs) / 1e9
    /** ADC samples per second of wall time; None when too short to tell. */
    def clockHz: Option[Double] =
      if (seconds >= MinSeconds && frames >= MinFrames && lastIndex > firstIndex) Some((lastIndex - firstIndex) / seconds) else None
    def next(ns: Long, index: Long): Span = copy(lastNs = ns, lastIndex = index, frames = frames + 1)
  }
  object Span { def first(ns: Long, index: Long): Span = Span(ns, index, ns, index, 1) }

  /** The measured clock where it means something: the link kept up with the board (no record dropped, and they
    * arrived at under 90 % of what the link carries; a full FIFO holds records back for longer and longer).
    */
  def measured(span: Option[Span], st: StreamStats, baud: Int): Option[Double] = span.flatMap { sp =>
    val perFrame = math.max(1L, math.round(st.records.toDouble / math.max(1L, st.frames)))
    val arriving = (sp.frames - 1) * perFrame / math.max(sp.seconds, 1e-9)
    if (st.dropped > 0 || arriving > 0.9 * Recorder.linkRecordsPerSecond(baud, perFrame)) None else sp.clockHz
  }

  /** A WARNING when the measured clock is more than `MaxFactor` from the stated one, naming the value to give. */
  def warning(measuredHz: Option[Double], s: BoardSetup, byHand: Boolean): Option[String] = measuredHz.flatMap { m =>
    val f = m / s.adcClockHz
    if (f <= MaxFactor && f >= 1 / MaxFactor) None
    else {
      val stated = if (byHand) s"the ${Recorder.num(s.adcClockHz)} Hz of --adc-clock-hz" else s"the ${Recorder.num(s.adcClockHz)} Hz of the board's adc_clock_hz register"
      Some(s"WARNING: the sample index ran at about ${Recorder.num(round3(m))} ADC samples/s, not $stated: the file's sample rate " +
        s"(${Recorder.num(s.sampleRateHz)} Hz) and its times are off by a factor of ${Recorder.num(round3(f))}; record again with --adc-clock-hz ${Recorder.num(round3(m))}")
    }
  }

  /** Three significant digits: the measured clock is good to a few tenths of a percent at best. */
  def round3(x: Double): Double = BigDecimal(x).round(new java.math.MathContext(3)).toDouble
}
