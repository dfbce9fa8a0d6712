package moire.timing

/** Runs one tool of the flow in a folder, its output into a log file, with a progress line every
  * minute and a time limit; low priority (`nice`) so that a long place and route shares the machine.
  */
object ToolRun {
  /** Reads a tool's log as it grows: a status for the progress line, and a reason to stop it early. */
  trait Watch {
    def line(l: String): Unit
    def status: Option[String]
    def abort: Option[String]
  }
  private object Silent extends Watch { def line(l: String): Unit = (); def status = None; def abort = None }

  /** A run that its [[Watch]] stopped, with the reason. */
  final class Stopped(val why: String, message: String) extends TimingError(message)

  private lazy val nice: Seq[String] =
    try { if (os.proc("nice", "true").call(check = false).exitCode == 0) Seq("nice", "-n", "10") else Nil }
    catch { case _: Exception => Nil }

  /** Runs `cmd` in `cwd` with stdout and stderr into `log`; returns the seconds it took.
    * Throws a [[TimingError]] naming `what` and the log on a non-zero exit or the time limit, and
    * [[Stopped]] when `watch` asks to stop.
    */
  def run(what: String, cmd: Seq[String], cwd: os.Path, log: os.Path, timeoutSeconds: Int, progress: String => Unit,
          watch: Watch = Silent): Double = {
    val exe = cmd.head
    val found = if (exe.contains('/')) os.isFile(os.Path(exe, os.pwd))
      else sys.env.getOrElse("PATH", "").split(':').exists(d => d.nonEmpty && os.isFile(os.Path(d, os.pwd) / exe))
    if (!found) throw new TimingError(s"$what: $exe not found; ${Ecp5Tools.installHint}")
    os.makeDir.all(cwd)
    val t0 = System.nanoTime()
    def secs = (System.nanoTime() - t0) / 1e9
    val proc = try os.proc(nice ++ cmd).spawn(cwd = cwd, stdout = log, stderr = os.Pipe, mergeErrIntoOut = true)
    catch { case e: java.io.IOException => throw new TimingError(s"$what: cannot start ${cmd.head}: ${e.getMessage}; ${Ecp5Tools.installHint}") }
    var next = 60
    val reader = new LogTail(log)
    def stop(): Unit = { proc.destroy(); proc.waitFor(2000L); if (proc.isAlive()) proc.destroyForcibly() }
    while (proc.isAlive() && secs < timeoutSeconds && watch.abort.isEmpty) {
      proc.waitFor(1000L)
      reader.lines().foreach(watch.line)
      if (proc.isAlive() && secs >= next) { progress(s"$what: ${next / 60} min${watch.status.map(", " + _).getOrElse("")}"); next += 60 }
    }
    watch.abort.foreach { why => if (proc.isAlive()) { stop(); throw new Stopped(why, s"$what: $why (log: $log)") } }
    if (proc.isAlive()) {
      stop()
      throw new TimingError(s"$what did not finish within $timeoutSeconds s (raise --timeout; log: $log)")
    }
    if (proc.exitCode() != 0) {
      val lines = if (os.exists(log)) os.read.lines(log) else Nil
      val err = lines.find(l => l.contains("ERROR")).getOrElse(s"exit code ${proc.exitCode()}").trim
      throw new TimingError(s"$what failed: $err (log: $log)")
    }
    secs
  }
}

/** The complete lines added to a file since the last call. */
private final class LogTail(file: os.Path) {
  private var pos = 0L
  private var partial = ""
  def lines(): Seq[String] = if (!os.isFile(file) || os.size(file) <= pos) Nil else {
    val raf = new java.io.RandomAccessFile(file.toIO, "r")
    try {
      raf.seek(pos)
      val buf = new Array[Byte]((os.size(file) - pos).min(1 << 20).toInt)
      raf.readFully(buf); pos += buf.length
      val text = partial + new String(buf, java.nio.charset.StandardCharsets.UTF_8)
      val parts = text.split("\n", -1)
      partial = parts.last
      parts.init.toSeq
    } finally raf.close()
  }
}
