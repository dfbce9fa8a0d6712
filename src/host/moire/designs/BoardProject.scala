package moire.designs

import moire.board.{BoardCmd, BoardParams, ClockSource, Mhz}
import moire.board.de2115.De2115
import moire.board.ulx3s.{Ulx3s, Ulx3sProject}
import moire.emit.Target

/** `board NAME`: the board's top from the registry, emitted into `rtl/`, inside its vendor project:
  * Quartus for the DE2-115 (SystemVerilog), the open ECP5 flow for the ULX3S (Verilog for yosys).
  */
object BoardProject {
  /** The registry entry of `board`'s top with these parameters. */
  def design(board: String, p: BoardParams): Design = board match {
    case "de2-115" => Designs.de2115("board-de2-115", p)
    case _ => Designs.ulx3s("board-ulx3s", p)
  }

  /** Writes the project into `dir` (its rtl/ folder and project files replaced as one); returns every file, the Verilog first. */
  def write(board: String, p: BoardParams, dir: os.Path): Seq[os.Path] = {
    BoardCmd.checkBoard(board)
    moire.files.SafeWrite.checkFolder(dir)   // before the elaboration, not after it
    val d = design(board, p)
    // written whole into a fresh folder, then swapped in: a failed or interrupted run leaves the old project whole
    moire.files.SafeWrite.project(dir) { stage =>
      board match {
        case "de2-115" => De2115.writeProject(p, stage, BoardCmd.checked(d.write(De2115.rtlDir(stage), Target.SystemVerilog)))
        case _ => Ulx3s.writeProject(p, stage, BoardCmd.checked(d.write(Ulx3s.rtlDir(stage), Target.Verilog)))
      }
    }
  }

  /** Writes the project and returns the lines to print: the files, the top, and the next command. */
  def run(board: String, p: BoardParams, dir: os.Path): Seq[String] = {
    val files = write(board, p, dir)
    val summary = s"${p.design.name}, system clock ${Mhz(p.clockHz)} MHz, ADC ${p.adcClockHz} Hz ${p.formatName}, " +
      f"decimation ${p.decimation} (${p.recordRate}%.1f records/s; the UART carries ${p.uartRecordRate}%.0f at ${p.baud} baud)"
    val latency = s"datapath latency ${p.datapathLatency} clocks after the capture register"
    files.map(f => s"wrote $f") ++ (board match {
      case "de2-115" => Seq(s"top ${De2115.topName(p)}: $summary", latency,
        s"next: ${dir / "flash.sh"}  (compiles with quartus_sh and programs the board over USB-Blaster JTAG; " +
          s"or open ${dir / s"${De2115.projectName}.qpf"} in Quartus)")
      case _ =>
        val pll = if (p.clockSource == ClockSource.Pll) Seq(Ulx3s.pll(p).toString) else Nil
        Seq(s"top ${Ulx3s.topName(p)}: $summary") ++ pll ++ Seq(latency,
          s"next: ${Ulx3s.buildScript(dir)}  (yosys and nextpnr, speed ${Ulx3sProject.speed}, exit 1 on a timing miss), " +
            s"then openFPGALoader -b ulx3s -m ${Ulx3s.bitstream(dir)}")
    })
  }
}
