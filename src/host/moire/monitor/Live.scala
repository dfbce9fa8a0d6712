package moire.monitor

import moire.recording.Recording
import moire.lissajous.EllipseFit

/** The monitor's live state: the last [[Live.Window]] records of the source, the connection, link figures, board flags,
  * tolerances and the burst in progress. Sources write, the server reads [[state]] (the JSON of GET /api/state).
  * Thread-safe (one lock). `said` hears each change of the connection (up or not, and why).
  */
final class Live(staleSeconds: Double = 2.0, said: (Boolean, String) => Unit = (_, _) => ()) {
  import Live._
  private val sin = new Array[Int](Window); private val cos = new Array[Int](Window)
  private val index = new Array[Long](Window); private val pos = new Array[Long](Window); private val flags = new Array[Int](Window)
  private var count = 0L // records received since the setup
  private var setupNow: Option[SourceSetup] = None
  private var connected = false
  private var message = "starting"
  private var lastAt = 0L
  private var linkFigures = ujson.Obj()
  private var boardStatus: Option[Long] = None
  private var tol = Tolerances.defaults
  private var burstState: ujson.Obj = ujson.Obj("state" -> "idle")
  private var disconnects = 0L

  def setup(s: SourceSetup): Unit = synchronized { setupNow = Some(s); count = 0 }
  def currentSetup: Option[SourceSetup] = synchronized(setupNow)
  def add(rs: Iterable[LiveRecord]): Unit = synchronized {
    rs.foreach { r =>
      val k = (count % Window).toInt
      sin(k) = r.sin; cos(k) = r.cos; index(k) = r.index; pos(k) = r.position; flags(k) = r.flags; count += 1
    }
    if (rs.nonEmpty) lastAt = System.nanoTime()
  }
  def connection(up: Boolean, why: String): Unit = synchronized {
    if (connected && !up) disconnects += 1
    if (up != connected || why != message) said(up, why)
    connected = up; message = why
  }
  def link(figures: ujson.Obj): Unit = synchronized { linkFigures = figures }
  def status(v: Long): Unit = synchronized { boardStatus = Some(v) }
  def tolerances: Tolerances = synchronized(tol)
  def tolerances_=(t: Tolerances): Unit = synchronized { tol = t }
  def burst: ujson.Obj = synchronized(burstState)
  def burst_=(b: ujson.Obj): Unit = synchronized { burstState = b }

  /** Connected and records within the last `staleSeconds`. */
  def live: Boolean = synchronized(connected && count > 0 && (System.nanoTime() - lastAt) < staleSeconds * 1e9)

  /** The records held, oldest first, as a recording (metadata of the source plus what the monitor knows). */
  def window(extraMeta: Map[String, String] = Map.empty): Option[Recording] = synchronized {
    setupNow.filter(_ => count > 0).map { s =>
      val n = math.min(count, Window.toLong).toInt; val first = count - n
      def col[A: scala.reflect.ClassTag](a: Array[A]) = Array.tabulate(n)(j => a(((first + j) % Window).toInt))
      val f = col(flags)
      def bit(b: Int) = f.map(v => if ((v & b) != 0) 1.0 else 0.0)
      Recording(s.sampleRateHz, s.adc, col(sin), col(cos), s.meta ++ extraMeta,
        Map("sample_index" -> col(index).map(_.toDouble), "position" -> col(pos).map(_.toDouble), "present" -> bit(LiveRecord.Present),
          "over_range" -> bit(LiveRecord.OverRange), "step_fault" -> bit(LiveRecord.StepFault), "otr_sin" -> bit(LiveRecord.OtrSin),
          "otr_cos" -> bit(LiveRecord.OtrCos)))
    }
  }

  /** The JSON of GET /api/state (docs/monitor.md). */
  def state: ujson.Obj = {
    val (rec, s, up, why, age, lf, st, t, b, total, drops) = synchronized {
      (window(), setupNow, live, message, if (count > 0) (System.nanoTime() - lastAt) / 1e9 else Double.NaN, linkFigures, boardStatus,
        tol, burstState, count, disconnects)
    }
    val o = ujson.Obj("connected" -> up, "message" -> (if (!up && why == "streaming") f"no records for $age%.1f s" else why),
      "source" -> s.fold[ujson.Value](ujson.Null)(_.label), "records_total" -> total.toDouble, "disconnects" -> drops.toDouble,
      "tolerances" -> t.json, "link" -> lf, "burst" -> b)
    s.foreach { s0 => o("setup") = ujson.Obj("sample_rate_hz" -> s0.sampleRateHz, "adc_bits" -> s0.adc.bits, "scale" -> s0.scale.json,
      "burst_depth" -> s0.burstDepth.fold[ujson.Value](ujson.Null)(d => ujson.Num(d.toDouble))) }
    o("board_status") = st.fold[ujson.Value](ujson.Null)(v => ujson.Obj.from(
      moire.protocol.Registers.StatusBit.named.map { case (bit, n) => n -> ujson.Bool(((v >> bit) & 1) != 0) } :+ ("value" -> ujson.Num(v.toDouble))))
    o("ellipse") = ujson.Null; o("quality_pct") = 0 // until there are records
    for (r <- rec; s0 <- s) analyse(r, s0, t).foreach { case (k, v) => o(k) = v }
    o
  }
}

object Live {
  /** Records held: the ellipse is fitted to them, a save writes them. */
  val Window = 4096
  /** Points of the Lissajous figure sent to the page (the newest). */
  val PlotPoints = 1024
  /** The speed is measured over the newest records that span at least this time (or the whole window when shorter):
    * the position is whole counts, so a shorter span would read a count's step as a change of speed. */
  val SpeedSeconds = 0.1

  private def r4(v: Double): ujson.Value = if (v.isNaN || v.isInfinite) ujson.Null else ujson.Num(math.rint(v * 1e4) / 1e4)

  /** Points, ellipse, readouts, quality, position, speed and flags of a window of records. */
  def analyse(r: Recording, s: SourceSetup, t: Tolerances): Seq[(String, ujson.Value)] = {
    val x = r.values(r.cos); val y = r.values(r.sin); val n = r.length
    val from = math.max(0, n - PlotPoints)
    val out = Seq.newBuilder[(String, ujson.Value)]
    out += "points" -> ujson.Obj("cos" -> ujson.Arr.from(x.drop(from).map(r4)), "sin" -> ujson.Arr.from(y.drop(from).map(r4)))
    EllipseFit.fit(x, y, n) match {
      case Some(e) =>
        val items = Readout.items(e, t)
        val amp = math.sqrt(e.ampSin * e.ampCos)
        out += "ellipse" -> ujson.Obj("offset_cos" -> e.offsetCos, "offset_sin" -> e.offsetSin, "amp_cos" -> e.ampCos, "amp_sin" -> e.ampSin,
          "phase_error_deg" -> e.phaseErrorDeg, "ratio" -> e.ratio, "points" -> e.points, "rms_radial_pct" -> 100 * e.rmsRadial,
          "amp_sin_v" -> s.scale.fullScaleV.fold[ujson.Value](ujson.Null)(v => ujson.Num(e.ampSin * v)),
          "amp_cos_v" -> s.scale.fullScaleV.fold[ujson.Value](ujson.Null)(v => ujson.Num(e.ampCos * v)),
          "outline" -> ujson.Arr.from(e.outline(96).map { case (a, b) => ujson.Arr(r4(a), r4(b)) }), "ideal_radius" -> amp)
        out += "readouts" -> ujson.Arr.from(items.map(_.json))
        out += "quality_pct" -> Readout.quality(items)
      case None =>
        out += "ellipse" -> ujson.Null
        out += "quality_pct" -> 0
    }
    val p = r.extra("position"); val idx = r.extra("sample_index"); val last = p(n - 1)
    out += "position" -> ujson.Obj("counts" -> last, "um" -> s.scale.um(last).fold[ujson.Value](ujson.Null)(ujson.Num(_)),
      "degrees" -> s.scale.degrees(last).fold[ujson.Value](ujson.Null)(ujson.Num(_)))
    val span = (SpeedSeconds * s.sampleRateHz).toLong
    val k = { var j = n - 1; while (j > 0 && idx(n - 1) - idx(j) < span) j -= 1; j }
    val dt = (idx(n - 1) - idx(k)) / s.sampleRateHz
    val v = if (dt > 0) (p(n - 1) - p(k)) / dt else Double.NaN
    out += "speed" -> ujson.Obj("counts_per_s" -> r4(v), "um_per_s" -> s.scale.um(v).fold[ujson.Value](ujson.Null)(r4),
      "degrees_per_s" -> s.scale.degrees(v).fold[ujson.Value](ujson.Null)(r4),
      "fringe_hz" -> s.scale.countsPerPeriod.fold[ujson.Value](ujson.Null)(m => r4(v / m)))
    out += "flags" -> ujson.Obj.from(LiveRecord.names.collect { case (_, name) if r.extra.contains(name) =>
      name -> ujson.Bool(r.extra(name)(n - 1) != 0) })
    out.result()
  }
}
