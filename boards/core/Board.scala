package moire.board

import chisel3.RawModule
import moire.emit.Target

/** One FPGA board: its name, its top around the board core, its pins and clocks, the vendor project it is
  * written into and the command to run next. A new board is its own folder (this trait, the top, the pin
  * table, the project writer) and one line in [[Boards]].
  */
trait Board {
  /** As typed after `board`: `de2-115`. */
  def name: String
  /** As printed: `DE2-115`. */
  def title: String
  /** The Verilog flavour the vendor tools read. */
  def target: Target

  def topName(p: BoardParams): String
  def top(p: BoardParams): RawModule
  /** The parameters `timing` places the top with (its clock from a pin, no vendor PLL primitive). */
  def placeParams(p: BoardParams): BoardParams
  /** The datapaths `board` writes a project with (`--design`; its help lists them): all the core has. */
  def designs: Seq[BoardDesign] = BoardDesign.all
  /** Those of [[designs]] whose tops are in the design registry (`board-NAME`, `board-NAME-DESIGN`) for cost and timing. */
  def registryDesigns: Seq[BoardDesign]
  /** A top's name in the design registry: `board-NAME` (the subdivider), `board-NAME-DESIGN`. */
  def registryName(d: BoardDesign): String = s"board-$name" + (if (d == BoardDesign.Subdiv) "" else s"-${d.name}")

  /** The pin table, one line per pin as the vendor's constraint file has it. */
  def pins: Seq[String]
  /** Why the board cannot run its system clock at `clockHz` from `source` (None: it can). */
  def clockProblem(clockHz: Int, source: ClockSource): Option[String]

  /** Where the project expects the Verilog: `dir/rtl`. */
  def rtlDir(dir: os.Path): os.Path = dir / "rtl"
  /** Writes the vendor project into `dir` around the Verilog (already in [[rtlDir]], top first); every file, the Verilog first. */
  def writeProject(p: BoardParams, dir: os.Path, verilog: Seq[os.Path]): Seq[os.Path]
  /** Lines after the top's summary (the PLL setting, say). */
  def notes(p: BoardParams): Seq[String] = Nil
  /** The command to run next on the project in `dir`. */
  def nextStep(p: BoardParams, dir: os.Path): String
}

/** The registry of boards: `board`, the design registry and the help read it; nothing else names a board. */
object Boards {
  val all: Seq[Board] = Seq(
    moire.board.de2115.De2115,
    moire.board.ulx3s.Ulx3s)

  def names: Seq[String] = all.map(_.name)

  /** The board called `name`, or a one-line message naming the boards there are. */
  def find(name: String): Either[String, Board] =
    moire.choice.Choice(all, name, s"board '$name' is unknown")(_.name)
}
