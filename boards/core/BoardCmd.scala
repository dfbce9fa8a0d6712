package moire.board

import moire.signal.AdcFormat

/** `board NAME` options -> [[BoardParams]] (the project is written by moire.designs.BoardProject).
  * Errors are one-line messages.
  */
object BoardCmd {
  final class BadOption(msg: String) extends Exception(msg)

  private def bad(m: String) = throw new BadOption(m)
  /** `body`, its IllegalArgumentException (a failed `require`) as a [[BadOption]] naming the option. */
  def checked[T](body: => T): T =
    try body catch { case e: IllegalArgumentException => bad("--" + e.getMessage.stripPrefix("requirement failed: ")) }

  def params(board: String, design: String, adcClockHz: Int, adcFormat: String, decimation: Int, baud: Int, frameRecords: Int,
             fifoDepth: Int, glitchFilter: Int, counts: Int, clockSource: String, clockHz: Int = 50000000,
             lines: Int = 16384, harmonics: Int = 4): BoardParams = {
    val d = BoardDesign.parse(design).fold(bad, identity)
    Boards.find(board).toOption.filterNot(_.designs.contains(d)).foreach(b =>
      bad(s"--design: ${b.name} does not run '${d.name}'; allowed: ${b.designs.map(_.name).mkString(", ")}"))
    val f = AdcFormat.parse(adcFormat).fold(e => bad(s"--adc-format: $e"), identity)
    val c = ClockSource.parse(clockSource).fold(bad, identity)
    if (clockHz < 1000000 || clockHz > 200000000) bad(s"--clock-hz must be in 1000000..200000000, got $clockHz")
    // the host's record, board-reg and monitor take these rates only: a board at another could not be talked to
    if (baud < 300 || baud > 12000000) bad(s"--baud must be in 300..12000000, got $baud")
    Boards.find(board).toOption.flatMap(_.clockProblem(clockHz, c)).foreach(bad)   // the board's clock first: --adc-clock-hz derives from it
    checked {
      val base = BoardParams()
      val sub = base.subdiv.copy(counts = counts)
      val cor = base.corrected.copy(subdiv = base.corrected.subdiv.copy(counts = counts))
      val harm = try base.harmonic.copy(lines = lines, harmonics = harmonics, subdivision = counts) catch {
        case e: IllegalArgumentException => bad("--" + e.getMessage.stripPrefix("requirement failed: ").replace("lines must", "lines (fringe periods per turn) must"))
      }
      BoardParams(d, sub, cor, adcClockHz, f, decimation, baud, frameRecords, fifoDepth, glitchFilter, c, clockHz, harmonic = harm)
    }
  }

  /** Nothing, or a [[BadOption]] naming the boards there are. */
  def checkBoard(board: String): Unit = Boards.find(board).left.foreach(bad)
}
