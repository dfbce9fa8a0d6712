package moire.timing

/** Runs one tool of the flow in a folder, its output into a log file, with a progress line every
  * minute and a time limit; low priority (`nice`) so that a long place and route shares the machine.
  */
object ToolRun {
  private lazy val nice: Seq[String] =
    try { if (os.proc("nice", "true").call(check = false).exitCode == 0) Seq("nice", "-n", "10") else Nil }
    catch { case _: Exception => Nil }

  /** Runs `cmd` in `cwd` with stdout and stderr into `log`; returns the seconds it took.
    * Throws a [[TimingError]] naming `what` and the log on a non-zero exit or the time limit.
    */
  def run(what: String, cmd: Seq[String], cwd: os.Path, log: os.Path, timeoutSeconds: Int, progress: String => Unit): Double = {
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
    while (proc.isAlive() && secs < timeoutSeconds) {
      proc.waitFor(1000L)
      if (proc.isAlive() && secs >= next) { progress(s"$what: ${next / 60} min"); next += 60 }
    }
    if (proc.isAlive()) {
      proc.destroy(); proc.waitFor(2000L); if (proc.isAlive()) proc.destroyForcibly()
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
