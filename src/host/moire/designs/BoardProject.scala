package moire.designs

import moire.board.{Board, BoardCmd, BoardParams, Boards, Mhz}

/** `board NAME`: the board's top from the registry, emitted into `rtl/`, inside its vendor project (Quartus for
  * the DE2-115, the open ECP5 flow for the ULX3S: each board's [[Board]] says which).
  */
object BoardProject {
  /** The board called `name`, or a [[BoardCmd.BadOption]] naming the boards there are. */
  def board(name: String): Board = Boards.find(name).fold(e => throw new BoardCmd.BadOption(e), identity)

  /** The registry entry of `board`'s top with these parameters. */
  def design(board: Board, p: BoardParams): Design = Designs.boardTop(board, s"board-${board.name}", p)

  /** Writes the project into `dir` (its rtl/ folder and project files replaced as one); returns every file, the Verilog first. */
  def write(name: String, p: BoardParams, dir: os.Path): Seq[os.Path] = {
    val b = board(name)
    moire.files.SafeWrite.checkFolder(dir)   // before the elaboration, not after it
    val d = design(b, p)
    // written whole into a fresh folder, then swapped in: a failed or interrupted run leaves the old project whole
    moire.files.SafeWrite.project(dir)(stage => b.writeProject(p, stage, BoardCmd.checked(d.write(b.rtlDir(stage), b.target))))
  }

  /** Writes the project and returns the lines to print: the files, the top, and the next command. */
  def run(name: String, p: BoardParams, dir: os.Path): Seq[String] = {
    val b = board(name)
    val files = write(name, p, dir)
    val summary = s"${p.design.name}, system clock ${Mhz(p.clockHz)} MHz, ADC ${p.adcClockHz} Hz ${p.formatName}, " +
      f"decimation ${p.decimation} (${p.recordRate}%.1f records/s; the UART carries ${p.uartRecordRate}%.0f at ${p.baud} baud)"
    val latency = s"datapath latency ${p.datapathLatency} clocks after the capture register"
    // a default decimation whose records the link cannot carry: the board would drop records from its first stream
    val carries = if (p.recordRate <= p.uartRecordRate) Nil else Seq(f"WARNING: decimation ${p.decimation} makes ${p.recordRate}%.0f records/s and " +
      f"${p.baud} baud carries at most ${p.uartRecordRate}%.0f: the board drops records until a larger one is written " +
      f"(board-reg --write decimation=N); --decimation ${math.ceil(p.adcClockHz / p.uartRecordRate).toLong} or more streams every record")
    files.map(f => s"wrote $f") ++ Seq(s"top ${b.topName(p)}: $summary") ++ carries ++ b.notes(p) ++ Seq(latency, b.nextStep(p, dir))
  }
}
