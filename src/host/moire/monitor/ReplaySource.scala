package moire.monitor

import moire.recording.Recording
import moire.stream.BurstOptions

/** Plays a recording at its own sample rate, over and over (the position carries on across the loops).
  * The page gets at most [[ReplaySource.PerTick]] records per 50 ms tick (evenly spread); a burst is the next N
  * samples at the full rate. A position column is used as it is; without one the position is the unwrapped
  * fringe phase of the raw codes times the counts per period.
  */
final class ReplaySource(rec: Recording, label: String, user: Scale) extends Source {
  private val scale0 = Scale.of(rec.meta, user)
  private val m = scale0.countsPerPeriod.getOrElse(ReplaySource.QuadratureCounts)
  private val scale = scale0.copy(countsPerPeriod = Some(m))
  private val n = rec.length
  private val position: Array[Double] = rec.extra.getOrElse("position", ReplaySource.unwrapped(rec).map(p => math.floor(p * m)))
  private val span = position(n - 1) - position(0) + (if (n > 1) position(n - 1) - position(n - 2) else 0)
  @volatile private var stop = false
  @volatile private var cursor = 0L // samples played since the start
  private var thread: Thread = _
  private val rnd = new scala.util.Random(1)

  private def pos(k: Long): Long = (position((k % n).toInt) + (k / n) * span).toLong

  def start(live: Live): Unit = {
    live.setup(SourceSetup(rec.sampleRateHz, rec.adc, scale, rec.meta ++ Map("source" -> s"monitor ($label)"), label, Some(n.toLong)))
    live.connection(up = true, "streaming")
    live.link(ujson.Obj("kind" -> "replay", "samples" -> n, "sample_rate_hz" -> rec.sampleRateHz))
    thread = new Thread(() => {
      val t0 = System.nanoTime()
      while (!stop) {
        val now = ((System.nanoTime() - t0) / 1e9 * rec.sampleRateHz).toLong
        val from = cursor
        if (now > from) {
          // at most PerTick records, at random places (an even stride would strobe the fringe: a few dots, no figure)
          val ks = if (now - from <= ReplaySource.PerTick) (from until now).toArray
            else Array.fill(ReplaySource.PerTick)(from + (rnd.nextDouble() * (now - from)).toLong).sorted
          val rs = ks.toSeq.map { k =>
            val i = (k % n).toInt
            LiveRecord(rec.sin(i), rec.cos(i), k, pos(k), LiveRecord.Present)
          }
          live.add(rs)
          cursor = now
          live.link(ujson.Obj("kind" -> "replay", "samples" -> n, "sample_rate_hz" -> rec.sampleRateHz, "played" -> now.toDouble, "loops" -> (now / n).toDouble))
        }
        Thread.sleep(50)
      }
    }, s"monitor-replay")
    thread.setDaemon(true)
    thread.start()
  }

  override def refuses(b: BurstOptions): Option[String] =
    if (b.trigger != "now") Some(s"trigger '${b.trigger}': the $label has no trigger hardware; use now")
    else if (b.samples < ExplainMin || b.samples > n) Some(s"samples must be in $ExplainMin..$n (the recording's length), got ${b.samples}")
    else None

  def burst(b: BurstOptions, file: os.Path): Recording = {
    refuses(b).foreach(m => throw new MonitorError(m))
    val start = math.max(0L, cursor - b.pre)
    val ks = (start until start + b.samples).map(k => (k % n).toInt).toArray
    val out = Recording(rec.sampleRateHz, rec.adc, ks.map(rec.sin), ks.map(rec.cos),
      rec.meta ++ Map("source" -> s"monitor burst ($label)", "captured_utc" -> java.time.Instant.now().toString,
        "counts_per_period" -> moire.stream.Recorder.num(m)),
      rec.extra.map { case (k, v) => k -> ks.map(v) } ++ Map("position" -> (start until start + b.samples).map(k => pos(k).toDouble).toArray))
    Recording.write(file, out)
    out
  }

  private def ExplainMin = moire.explain.ExplainCmd.MinSamples

  def close(): Unit = { stop = true; if (thread != null) thread.join(1000) }
}

object ReplaySource {
  /** Records per tick sent on to the page (the ellipse fit needs no more; the position is exact regardless). */
  val PerTick = 400
  /** Counts per period assumed when a recording does not say: the quadrature edges. */
  val QuadratureCounts = 4.0

  /** Fringe periods of each sample from the raw codes (atan2 about the codes' mid-range), unwrapped. */
  def unwrapped(r: Recording): Array[Double] = {
    val s = r.values(r.sin); val c = r.values(r.cos)
    def mid(a: Array[Double]) = (a.min + a.max) / 2
    val ms = mid(s); val mc = mid(c)
    val out = new Array[Double](r.length); var acc = 0.0; var last = 0.0
    for (i <- 0 until r.length) {
      val p = math.atan2(s(i) - ms, c(i) - mc) / (2 * math.Pi)
      if (i > 0) { var d = p - last; d -= math.rint(d); acc += d } else acc = p
      last = p; out(i) = acc
    }
    out
  }
}
