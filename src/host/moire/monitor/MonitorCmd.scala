package moire.monitor

import moire.recording.Recording

/** `moire monitor`: a source (board, replay or simulated board), the live state and the web page, until Ctrl-C. */
object MonitorCmd {
  final case class Options(port: Option[String], replay: Option[String], simulate: Boolean, effects: Seq[String], baud: Int,
                           decimation: Option[Long], bind: String, httpPort: Int, out: String, scale: Scale,
                           boardOptions: Seq[String] = Nil)

  def validate(o: Options): Unit = {
    val n = Seq(o.port.isDefined, o.replay.isDefined, o.simulate).count(identity)
    if (n != 1) throw new MonitorError("monitor: give one of --port DEV (a board), --replay FILE (a recording) or --simulate (a simulated board)")
    if (o.effects.nonEmpty && !o.simulate) throw new MonitorError("--effect belongs to --simulate")
    // the link's rate and the decimation written to a board: a replay or a simulated board would ignore them
    val board = (o.boardOptions ++ (if (o.decimation.isDefined) Seq("--decimation") else Nil)).distinct
    if (o.port.isEmpty && board.nonEmpty)
      throw new MonitorError(s"${board.mkString(" and ")} ${if (board.size == 1) "applies" else "apply"} to a board (--port DEV); " +
        s"${if (o.replay.isDefined) "a replay plays the file at its own rate" else "a simulated board has no link"}: leave ${if (board.size == 1) "it" else "them"} out")
    // what can never become a serial port is refused now (record refuses it too); it was tried every second, for ever
    o.port.foreach { p =>
      if (p.trim.isEmpty) throw new MonitorError("--port is empty: name a serial port, e.g. /dev/ttyUSB0")
      val f = java.nio.file.Paths.get(p)
      if (java.nio.file.Files.isDirectory(f)) throw new MonitorError(s"$p: is a folder, not a serial port")
      if (java.nio.file.Files.isRegularFile(f)) throw new MonitorError(s"$p: is a plain file, not a serial port")
    }
    if (o.httpPort < 0 || o.httpPort > 65535) throw new MonitorError(s"--http-port must be in 0..65535, got ${o.httpPort}")
    if (o.baud < 300 || o.baud > 12000000) throw new MonitorError(s"--baud must be in 300..12000000, got ${o.baud}")
    o.decimation.foreach(d => if (d < 1 || d > moire.protocol.Registers.MaxDecimation)
      throw new MonitorError(s"--decimation must be in 1..${moire.protocol.Registers.MaxDecimation}, got $d"))
    for ((k, v) <- Seq("--counts-per-period" -> o.scale.countsPerPeriod, "--period-um" -> o.scale.periodUm,
      "--lines-per-rev" -> o.scale.linesPerRev, "--full-scale-v" -> o.scale.fullScaleV); x <- v)
      if (!(x > 0) || x.isInfinite) throw new MonitorError(s"$k must be a positive finite number, got $x")
    // a board's M (the simulated one's too) is a power of two, as record and board take it; a grating has whole lines
    if (o.replay.isEmpty) o.scale.countsPerPeriod.filterNot(m => m == math.rint(m) && moire.stream.Recorder.countsOk(m.toLong)).foreach(m =>
      throw new MonitorError(s"--counts-per-period must be a power of two from 4 to 65536 (a board's M, counts per grating period), got $m"))
    o.scale.linesPerRev.filter(l => l != math.rint(l)).foreach(l => throw new MonitorError(s"--lines-per-rev counts a grating's lines on a turn: a whole number, got $l"))
    if (o.bind.trim.isEmpty) throw new MonitorError("--bind: the address is empty; give one of this computer's (127.0.0.1 by default, 0.0.0.0 for all)")
    val notHere = new MonitorError(s"--bind '${o.bind}' is not an address of this computer")
    val a = try java.net.InetAddress.getByName(o.bind) catch { case _: java.net.UnknownHostException => throw notHere }
    if (!a.isAnyLocalAddress && !a.isLoopbackAddress && java.net.NetworkInterface.getByInetAddress(a) == null) throw notHere
    moire.files.SafeWrite.checkFolder(os.Path(o.out, os.pwd))
  }

  /** The source the options name (a replayed file is read and checked first). */
  def source(o: Options, warn: String => Unit = _ => ()): Source = (o.port, o.replay) match {
    case (Some(p), _) => new BoardSource(p, o.baud, o.decimation, o.scale)
    case (_, Some(f)) =>
      val p = os.Path(f, os.pwd)
      moire.files.PathKind.notAFile(p).foreach(m => throw new MonitorError(m))
      val rec = Recording.read(p)
      rec.warnings.foreach(w => warn(s"WARNING: $f: $w"))
      moire.explain.ExplainCmd.checkSignals(p, rec, "monitor --replay (its bursts are explained)")
      // a scale the file states that is no number above 0 is refused as explain refuses it, not played at another
      moire.recording.Reference.of(rec).left.foreach(m => throw new MonitorError(s"$p: $m"))
      new ReplaySource(rec, s"replay of ${p.last}", o.scale)
    case _ => new ReplaySource(SimBoard.recording(if (o.effects.isEmpty) SimBoard.DefaultEffects else o.effects), "simulated board", o.scale)
  }

  /** Starts everything; the caller closes the result (the server, the source, the work folder). `tell` hears a board's
    * connection when it changes (up or not, and why).
    */
  def start(o: Options, warn: String => Unit, tell: String => Unit = _ => ()): (MonitorServer, AutoCloseable) = {
    validate(o)
    val loopback = try java.net.InetAddress.getByName(o.bind).isLoopbackAddress catch { case _: Exception => false }
    if (!loopback) warn(s"WARNING: the monitor listens on ${o.bind}: anyone who reaches this computer there can watch the board, capture bursts and save files")
    val src = source(o, warn)
    // a board's connection said in the terminal too, when it changes (the page shows it all the time)
    val live = o.port.fold(new Live()) { p =>
      new Live(said = (up, why) => tell(s"monitor: board on $p: ${if (up) why else s"not connected: $why (tried again every second)"}"))
    }
    val work = os.temp.dir(prefix = "moire-monitor")
    val app = new Monitor(live, src, os.Path(o.out, os.pwd), work)
    src.start(live)
    val server = try new MonitorServer(app, o.bind, o.httpPort) catch { case e: Throwable => src.close(); throw e }
    (server, () => { server.close(); src.close(); os.remove.all(work) })
  }

  def run(o: Options, say: String => Unit, warn: String => Unit): Unit = {
    val (server, all) = start(o, warn, warn)
    sys.addShutdownHook(all.close())
    say(s"monitor: ${server.url} (Ctrl-C stops)")
    Thread.currentThread().join()
  }
}
