package moire.board.de2115

import moire.signal.AdcFormat

/** `board de2-115`: options -> [[BoardParams]] -> Quartus project folder. Errors are one-line messages. */
object BoardCmd {
  final class BadOption(msg: String) extends Exception(msg)

  def params(design: String, adcClockHz: Int, adcFormat: String, decimation: Int, baud: Int, frameRecords: Int,
             fifoDepth: Int, glitchFilter: Int, counts: Int, clockSource: String): BoardParams = {
    def bad(m: String) = throw new BadOption(m)
    val d = BoardDesign.parse(design).fold(bad, identity)
    val f = AdcFormat.parse(adcFormat).fold(e => bad(s"--adc-format: $e"), identity)
    val c = ClockSource.parse(clockSource).fold(bad, identity)
    try {
      val base = BoardParams()
      val sub = base.subdiv.copy(counts = counts)
      val cor = base.corrected.copy(subdiv = base.corrected.subdiv.copy(counts = counts))
      BoardParams(d, sub, cor, adcClockHz, f, decimation, baud, frameRecords, fifoDepth, glitchFilter, c)
    } catch { case e: IllegalArgumentException => bad("--" + e.getMessage.stripPrefix("requirement failed: ")) }
  }

  /** Writes the project; returns the lines to print. */
  def run(board: String, p: => BoardParams, out: String): Seq[String] = {
    if (board != "de2-115") throw new BadOption(s"board '$board' is unknown; allowed: de2-115")
    val params = p
    val dir = os.Path(out, os.pwd)
    val files = De2115.writeProject(params, dir)
    files.map(f => s"wrote $f") ++ Seq(
      s"top ${params.topName}: ${params.design.name}, ADC ${params.adcClockHz} Hz ${De2115.formatTag(params.adcFormat)}, " +
        f"decimation ${params.decimation} (${params.recordRate}%.1f records/s; the UART carries ${params.uartRecordRate}%.0f at ${params.baud} baud)",
      s"datapath latency ${params.datapathLatency} clocks after the capture register; build and load: ${dir / "flash.sh"}")
  }
}
