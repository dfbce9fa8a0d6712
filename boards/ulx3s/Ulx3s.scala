package moire.board.ulx3s

import chisel3.RawModule
import moire.board.{Board, BoardDesign, BoardParams, ClockSource}
import moire.emit.Target

/** The ULX3S top, its .lpf and the open-flow build script (the Verilog comes from the design registry, moire.designs). */
object Ulx3s extends Board {
  val name = "ulx3s"
  val title = "ULX3S"
  val target: Target = Target.Verilog
  val oscillatorHz: Int = 25000000
  val projectName: String = "moire_ulx3s"
  def topName(p: BoardParams): String = s"Ulx3s_${p.tag}"

  /** The PLL's dividers for the system clock, or an IllegalArgumentException saying why there are none. */
  def pll(p: BoardParams): Ecp5PllParams =
    Ecp5Pll.solve(oscillatorHz, p.clockHz).fold(e => throw new IllegalArgumentException(s"clock-hz: $e"), identity)

  def top(p: BoardParams): RawModule = new Ulx3sTop(p)
  /** Placed out of context by `timing` with its clock from the pin of the 25 MHz oscillator (the PLL is a primitive
    * out-of-context synthesis does not know; `build.sh` places it with the PLL at its clock).
    */
  def placeParams(p: BoardParams): BoardParams = p.copy(clockSource = ClockSource.Logic, clockHz = oscillatorHz, adcClockHz = oscillatorHz)
  val registryDesigns: Seq[BoardDesign] = Seq(BoardDesign.Subdiv, BoardDesign.Compensated)

  def pins: Seq[String] = Ulx3sPins.all.map(p => s"${p.port} ${p.site} ${p.ioType} PULLMODE=${p.pull}")

  override def notes(p: BoardParams): Seq[String] = if (p.clockSource == ClockSource.Pll) Seq(pll(p).toString) else Nil
  def nextStep(p: BoardParams, dir: os.Path): String =
    s"next: ${buildScript(dir)}  (yosys and nextpnr, speed ${Ulx3sProject.speed}, exit 1 on a timing miss), " +
      s"then openFPGALoader -b ulx3s -m ${bitstream(dir)}"

  /** Why this board cannot run its system clock at `clockHz` (None: it can). */
  def clockProblem(clockHz: Int, source: ClockSource): Option[String] = source match {
    case ClockSource.Logic => Option.when(clockHz != oscillatorHz)(
      s"--clock-hz: with --clock-source logic the ULX3S runs on its $oscillatorHz Hz oscillator, got $clockHz" +
        (if (clockHz == 50000000) s" (the default): give --clock-hz $oscillatorHz and an --adc-clock-hz that divides it, e.g. $oscillatorHz" else ""))
    case _ => Ecp5Pll.solve(oscillatorHz, clockHz).left.toOption.map(e => s"--clock-hz: $e")
  }

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
