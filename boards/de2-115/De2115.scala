package moire.board.de2115

import chisel3.RawModule
import moire.board.{Board, BoardDesign, BoardParams, ClockSource}
import moire.emit.Target

/** The DE2-115 board's top and its Quartus project (the Verilog comes from the design registry, moire.designs). */
object De2115 extends Board {
  val name = "de2-115"
  val title = "DE2-115"
  val target: Target = Target.SystemVerilog
  /** CLOCK_50, the only system clock of this board. */
  val clockHz: Int = 50000000
  val projectName: String = "moire_de2_115"
  def topName(p: BoardParams): String = s"De2115_${p.tag}"

  def top(p: BoardParams): RawModule = new De2115Top(p)
  /** Placed on the ECP5 by `timing` with its clock from the pin (no Cyclone IV PLL there). */
  def placeParams(p: BoardParams): BoardParams = p.copy(clockSource = ClockSource.Logic)
  val registryDesigns: Seq[BoardDesign] = Seq(BoardDesign.Subdiv, BoardDesign.Corrected, BoardDesign.Compensated)

  def pins: Seq[String] = De2115Pins.all.map(p => s"${p.port} ${p.ball} ${p.ioStandard}")

  /** Why this board cannot run its system clock at `clockHz` (None: it can). */
  def clockProblem(clockHz: Int, source: ClockSource): Option[String] =
    Option.when(clockHz != clockHz0)(s"--clock-hz: the DE2-115 runs at $clockHz0 Hz (CLOCK_50, no PLL for the system clock), got $clockHz")
  private def clockHz0 = De2115.clockHz

  def nextStep(p: BoardParams, dir: os.Path): String =
    s"next: ${dir / "flash.sh"}  (compiles with quartus_sh and programs the board over USB-Blaster JTAG; " +
      s"or open ${dir / s"$projectName.qpf"} in Quartus)"

  /** Writes the Quartus project into `dir` around the board's Verilog files (already written into
    * [[rtlDir]], top first): .qsf, .sdc, .qpf and flash.sh. Returns every file, the Verilog first.
    */
  def writeProject(p: BoardParams, dir: os.Path, verilog: Seq[os.Path]): Seq[os.Path] = {
    val files = Seq(
      dir / s"$projectName.qpf" -> QuartusProject.qpf(p),
      dir / s"$projectName.qsf" -> QuartusProject.qsf(p, verilog.map(_.relativeTo(dir).toString)),
      dir / s"$projectName.sdc" -> QuartusProject.sdc(p),
      dir / "flash.sh" -> QuartusProject.flash(p))
    for ((f, text) <- files) moire.files.SafeWrite.text(f, text)
    os.perms.set(dir / "flash.sh", "rwxr-xr-x")
    verilog ++ files.map(_._1)
  }
}
