package moire.board

import moire.board.de2115.De2115
import moire.board.ulx3s.{Ulx3s, Ulx3sProject}
import moire.signal.AdcFormat

/** `board NAME`: options -> [[BoardParams]] -> a project folder for the DE2-115 (Quartus) or the
  * ULX3S (open ECP5 flow). Errors are one-line messages.
  */
object BoardCmd {
  final class BadOption(msg: String) extends Exception(msg)
  val boards: Seq[String] = Seq("de2-115", "ulx3s")

  private def bad(m: String) = throw new BadOption(m)
  private def fromRequire[T](body: => T): T =
    try body catch { case e: IllegalArgumentException => bad("--" + e.getMessage.stripPrefix("requirement failed: ")) }

  def params(design: String, adcClockHz: Int, adcFormat: String, decimation: Int, baud: Int, frameRecords: Int,
             fifoDepth: Int, glitchFilter: Int, counts: Int, clockSource: String, clockHz: Int = 50000000,
             lines: Int = 16384, harmonics: Int = 4): BoardParams = {
    val d = BoardDesign.parse(design).fold(bad, identity)
    val f = AdcFormat.parse(adcFormat).fold(e => bad(s"--adc-format: $e"), identity)
    val c = ClockSource.parse(clockSource).fold(bad, identity)
    fromRequire {
      val base = BoardParams()
      val sub = base.subdiv.copy(counts = counts)
      val cor = base.corrected.copy(subdiv = base.corrected.subdiv.copy(counts = counts))
      val harm = try base.harmonic.copy(lines = lines, harmonics = harmonics, subdivision = counts) catch {
        case e: IllegalArgumentException => bad("--" + e.getMessage.stripPrefix("requirement failed: ").replace("lines must", "lines (fringe periods per turn) must"))
      }
      BoardParams(d, sub, cor, adcClockHz, f, decimation, baud, frameRecords, fifoDepth, glitchFilter, c, clockHz, harmonic = harm)
    }
  }

  /** Writes the project of `board`; returns the lines to print. */
  def run(board: String, p: => BoardParams, out: String): Seq[String] = {
    if (!boards.contains(board)) bad(s"board '$board' is unknown; allowed: ${boards.mkString(", ")}")
    val params = p
    val dir = os.Path(out, os.pwd)
    val summary = s"${params.design.name}, system clock ${Mhz(params.clockHz)} MHz, ADC ${params.adcClockHz} Hz ${params.formatName}, " +
      f"decimation ${params.decimation} (${params.recordRate}%.1f records/s; the UART carries ${params.uartRecordRate}%.0f at ${params.baud} baud)"
    val latency = s"datapath latency ${params.datapathLatency} clocks after the capture register"
    board match {
      case "de2-115" =>
        val files = fromRequire(De2115.writeProject(params, dir))
        files.map(f => s"wrote $f") ++ Seq(s"top ${De2115.topName(params)}: $summary", s"$latency; build and load: ${dir / "flash.sh"}")
      case _ =>
        val files = fromRequire(Ulx3s.writeProject(params, dir))
        val pll = if (params.clockSource == ClockSource.Pll) Seq(Ulx3s.pll(params).toString) else Nil
        files.map(f => s"wrote $f") ++ Seq(s"top ${Ulx3s.topName(params)}: $summary") ++ pll ++ Seq(
          s"$latency; build (speed ${Ulx3sProject.speed}, exit 1 on a timing miss): ${Ulx3s.buildScript(dir)}",
          s"load: openFPGALoader -b ulx3s -m ${Ulx3s.bitstream(dir)}")
    }
  }
}
