package moire.board.ulx3s

import chisel3.RawModule
import moire.board.BoardParams

/** The ULX3S top, its .lpf and the open-flow build script (the Verilog comes from the design registry, moire.designs). */
object Ulx3s {
  val oscillatorHz: Int = 25000000
  val projectName: String = "moire_ulx3s"
  def topName(p: BoardParams): String = s"Ulx3s_${p.tag}"

  /** The PLL's dividers for the system clock, or an IllegalArgumentException saying why there are none. */
  def pll(p: BoardParams): Ecp5PllParams =
    Ecp5Pll.solve(oscillatorHz, p.clockHz).fold(e => throw new IllegalArgumentException(s"clock-hz: $e"), identity)

  def top(p: BoardParams): RawModule = new Ulx3sTop(p)

  /** Why this board cannot run its system clock at `clockHz` (None: it can). */
  def clockProblem(clockHz: Int, source: moire.board.ClockSource): Option[String] = source match {
    case moire.board.ClockSource.Logic => Option.when(clockHz != oscillatorHz)(
      s"--clock-hz: with --clock-source logic the ULX3S runs on its $oscillatorHz Hz oscillator, got $clockHz")
    case _ => Ecp5Pll.solve(oscillatorHz, clockHz).left.toOption.map(e => s"--clock-hz: $e")
  }

  /** Where [[writeProject]] expects the board's Verilog: `dir/rtl`. */
  def rtlDir(dir: os.Path): os.Path = dir / "rtl"
  /** The build script [[writeProject]] writes into `dir`. */
  def buildScript(dir: os.Path): os.Path = dir / "build.sh"
  /** The bitstream the build script makes in `dir`. */
  def bitstream(dir: os.Path): os.Path = dir / s"$projectName.bit"
  /** nextpnr's report (Fmax per clock, utilisation) after a build in `dir`. */
  def report(dir: os.Path): os.Path = dir / "report.json"

  /** Writes the project into `dir` around the board's Verilog files (already written into [[rtlDir]],
    * top first): moire_ulx3s.lpf, build.sh and ecp5-tools.sh. Returns every file, the Verilog first.
    */
  def writeProject(p: BoardParams, dir: os.Path, verilog: Seq[os.Path]): Seq[os.Path] = {
    val files = Seq(
      dir / s"$projectName.lpf" -> Ulx3sProject.lpf(p),
      buildScript(dir) -> Ulx3sProject.build(p, verilog.map(_.relativeTo(dir).toString)),
      dir / "ecp5-tools.sh" -> Ulx3sProject.toolsScript)
    for ((f, text) <- files) moire.files.SafeWrite.text(f, text)
    Seq(buildScript(dir), dir / "ecp5-tools.sh").foreach(os.perms.set(_, "rwxr-xr-x"))
    verilog ++ files.map(_._1)
  }

  /** Runs the build script of a project written by [[writeProject]], each output line to `line`;
    * returns its exit status: 0 built, 1 timing failed (no bitstream), other: a tool failed.
    */
  def build(dir: os.Path, line: String => Unit, env: Map[String, String] = Map.empty): Int =
    os.proc(buildScript(dir)).call(cwd = dir, check = false, env = env, mergeErrIntoOut = true,
      stdout = os.ProcessOutput.Readlines(line)).exitCode
}
