package moire.monitor

import moire.stream.{BurstOptions, BurstTrigger}

/** The monitor's actions behind the web page: the live state, a burst (capture, explain, HTML report) and save.
  * Bursts and their reports are kept in `work` until a save copies the newest into `out`.
  */
final class Monitor(val live: Live, source: Source, out: os.Path, work: os.Path) {
  @volatile private var lastBurst: Option[(os.Path, os.Path, os.Path)] = None // recording, HTML, JSON
  private val busy = new java.util.concurrent.atomic.AtomicBoolean(false)

  /** Fewest and most samples a burst from the page may ask for. */
  val MinBurst: Int = moire.explain.ExplainCmd.MinSamples
  val MaxBurst: Int = 1 << 20

  /** Parses a burst request {"samples": N, "trigger": "now", "pre": P, "wait_seconds": S}; Left with a message. */
  /** A burst request's options, or why it is refused (a bad field, or what the source cannot capture). */
  def burstOptions(body: String): Either[String, BurstOptions] = burstFields(body).flatMap(b => source.refuses(b).toLeft(b))
  private def burstFields(body: String): Either[String, BurstOptions] = {
    val j = try moire.options.StrictJson.read(if (body.trim.isEmpty) "{}" else body) catch { case e: Exception => return Left(s"not JSON: ${e.getMessage.linesIterator.next().take(80)}") }
    val o = j.objOpt.getOrElse(return Left("expected a JSON object like {\"samples\": 16384, \"trigger\": \"now\"}"))
    val known = Set("samples", "trigger", "pre", "wait_seconds")
    o.keys.find(!known(_)).foreach(k => return Left(s"unknown field '$k'; known: ${known.mkString(", ")}"))
    // a whole number a double holds exactly (1e400 reads as Infinity, which toLong would make Long.MaxValue)
    def int(k: String, d: Long) = o.get(k).fold[Either[String, Long]](Right(d))(v => v.numOpt.filter(x => x == math.rint(x) && math.abs(x) <= 9.007199254740992e15).map(_.toLong)
      .toRight(s"$k must be an integer, got ${ujson.write(v).take(30)}"))
    for {
      n <- int("samples", 16384); pre <- int("pre", 0)
      t <- o.get("trigger").fold[Either[String, String]](Right("now"))(_.strOpt.toRight("trigger must be a string like \"now\" or \"z\""))
      w <- o.get("wait_seconds").fold[Either[String, Double]](Right(10))(_.numOpt.toRight("wait_seconds must be a number"))
      _ <- if (n < MinBurst || n > MaxBurst) Left(s"samples must be in $MinBurst..$MaxBurst, got $n") else Right(())
      _ <- if (pre < 0 || pre >= n) Left(s"pre must be in 0..${n - 1}, got $pre") else Right(())
      _ <- if (!(w > 0) || w > 600) Left(s"wait_seconds must be in (0, 600], got $w") else Right(())
      _ <- BurstTrigger.parse(t).map(_ => ()).left.map(_.replace("--trigger", "trigger"))
    } yield BurstOptions(n, t, pre, w)
  }

  /** Starts a burst in the background; false when one is already running. */
  def startBurst(b: BurstOptions): Boolean = {
    if (!busy.compareAndSet(false, true)) return false
    live.burst = ujson.Obj("state" -> "running", "message" -> s"capturing ${b.samples} samples (trigger ${b.trigger})", "samples" -> b.samples.toDouble)
    val t = new Thread(() => try runBurst(b) finally busy.set(false), "monitor-burst")
    t.setDaemon(true); t.start()
    true
  }

  private def runBurst(b: BurstOptions): Unit = {
    val stem = "burst-" + Monitor.stamp()
    val file = work / s"$stem.csv"; val html = work / s"$stem.html"
    try {
      val t0 = System.nanoTime()
      source.burst(b, file)
      live.burst = ujson.Obj("state" -> "running", "message" -> s"explaining ${b.samples} samples")
      val r = moire.explain.ExplainCmd.explain(Seq(file.toString), Some(work.toString), None, None, quiet = true, rtl = None, html = Some(html.toString)).head
      lastBurst = Some((file, html, work / s"$stem.json"))
      live.burst = ujson.Obj("state" -> "done", "file" -> file.last, "report" -> "/api/report", "seconds" -> (System.nanoTime() - t0) / 1e9,
        "findings" -> ujson.Arr.from(r.findings.map(f => ujson.Obj("effect" -> f.effect, "channel" -> f.channel, "summary" -> f.summary))),
        "unexplained" -> r.unexplained.size, "message" -> (if (r.findings.isEmpty) "no effect beyond the default model" else s"found: ${r.findings.map(_.effect).mkString(", ")}"))
    } catch {
      case e: moire.MoireError => live.burst = ujson.Obj("state" -> "failed", "message" -> e.getMessage)
      case e: java.io.IOException => live.burst = ujson.Obj("state" -> "failed", "message" -> moire.files.SafeWrite.reason(e))
    }
  }

  /** The newest burst's HTML report. */
  def report: Option[String] = lastBurst.map(b => os.read(b._2))

  /** Writes the records held, the state (readouts) and the newest burst with its report into `out`; the files written. */
  def save(): Seq[os.Path] = {
    val stamp = Monitor.stamp()
    val st = live.state
    val rec = live.window(Map("saved_utc" -> java.time.Instant.now().toString)).getOrElse(throw new MonitorError("nothing to save yet: no records received"))
    os.makeDir.all(out)
    val f = out / s"monitor-$stamp.csv"; val s = out / s"monitor-$stamp.state.json"
    moire.recording.Recording.write(f, rec)
    st.value.remove("points"); st.value.get("ellipse").flatMap(_.objOpt).foreach(_.value.remove("outline"))
    moire.files.SafeWrite.text(s, ujson.write(st, indent = 2))
    val burst = lastBurst.toSeq.flatMap { case (r, h, j) => Seq(r, h, j).filter(os.exists(_)).map { p => os.copy.over(p, out / p.last); out / p.last } }
    Seq(f, s) ++ burst
  }
}

object Monitor {
  def stamp(): String = java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS").withZone(java.time.ZoneOffset.UTC).format(java.time.Instant.now())
}
