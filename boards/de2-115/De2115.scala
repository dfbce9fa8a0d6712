package moire.board.de2115

import chisel3.RawModule
import moire.board.BoardParams
import moire.emit.{Emit, Target}

/** Elaboration, Verilog emission and the Quartus project of the DE2-115 board in one place. */
object De2115 {
  /** CLOCK_50, the only system clock of this board. */
  val clockHz: Int = 50000000
  val projectName: String = "moire_de2_115"
  def topName(p: BoardParams): String = s"De2115_${p.tag}"

  def top(p: BoardParams): RawModule = new De2115Top(p)

  /** Writes the SystemVerilog of the board (and the PLL Verilog when used) into `dir`; returns the
    * Verilog files (top first).
    */
  def emitVerilog(p: BoardParams, dir: os.Path): Seq[os.Path] = Emit.write(top(p), dir, Target.Verilog)._2

  /** Writes a complete Quartus project into `dir`: Verilog, .qsf, .sdc, .qpf and flash.sh. */
  def writeProject(p: BoardParams, dir: os.Path): Seq[os.Path] = {
    val rtl = dir / "rtl"
    if (os.exists(rtl)) os.remove.all(rtl)
    val verilog = emitVerilog(p, rtl)
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
