package moire.cli

import circt.stage.ChiselStage
import mainargs.{arg, main}
import moire.cordic.Rounding
import moire.signal.AdcFormat
import moire.subdiv.{PhaseMethod, SubdivAdc, SubdivParams}

/** Options of the subdivider (see moire.subdiv.SubdivParams). */
@main
case class SubdivConfig(
  @arg(doc = "ADC bits, 4..16") inputBits: Int = 12,
  @arg(doc = "atan2 | asin-double") method: String = "atan2",
  @arg(doc = "M, counts per grating period: power of two, 4..65536") counts: Int = 1024,
  @arg(doc = "CORDIC iterations, 4..40") iterations: Int = 16,
  @arg(doc = "CORDIC data width (default input-bits + 6)") cordicWidth: Int = -1,
  @arg(doc = "extra fractional bits inside the CORDIC, 0..8") guardBits: Int = 2,
  @arg(doc = "phase word width (default max(cordic width, log2 M + 2))") phaseBits: Int = -1,
  @arg(doc = "position word width") positionWidth: Int = 32,
  @arg(doc = "A/B edges at least this many clocks apart") minEdgeClocks: Int = 1,
  @arg(doc = "counts the A/B output may lag before overspeed is flagged") backlogLimit: Int = 64,
  @arg(doc = "signal present when the amplitude is at least this (fraction of full scale)") presentThreshold: Double = 0.1,
  @arg(doc = "asin-double: nominal signal amplitude (fraction of full scale)") asinAmplitude: Double = 0.9,
  @arg(doc = "phase step (turns per sample) above which stepFault is set, <= 0.5") maxStepTurns: Double = 0.46875,
  @arg(doc = "truncate | half-even") rounding: String = "half-even",
  @arg(doc = "ADC pin format: offset-binary | twos-complement") adcFormat: String = "offset-binary"
) {
  def params: SubdivParams = {
    val m = PhaseMethod.parse(method).fold(e => throw new UsageError(e), identity)
    val r = Rounding.parse(rounding).fold(e => throw new UsageError(e), identity)
    try SubdivParams(inputBits, m, counts, iterations, cordicWidth, guardBits, phaseBits, positionWidth, minEdgeClocks,
      backlogLimit, presentThreshold, asinAmplitude, maxStepTurns, r)
    catch { case e: IllegalArgumentException => throw new UsageError("--" + e.getMessage.stripPrefix("requirement failed: ")) }
  }
  def format: AdcFormat = AdcFormat.parse(adcFormat).fold(e => throw new UsageError(s"--adc-format: $e"), identity)
}
object SubdivCmd {
  /** Plain Verilog-2001-style output (no automatic locals, no packed arrays), which yosys and
    * older Quartus releases read.
    */
  val firtoolOpts: Array[String] = Emit.firtoolOpts :+ "--lowering-options=disallowLocalVariables,disallowPackedArrays"

  /** Writes the board-facing subdivider (ADC front end + subdivider) as SystemVerilog; returns the file. */
  def emit(p: SubdivParams, format: AdcFormat, out: String): (os.Path, Int, String) = {
    val dir = os.Path(out, os.pwd)
    os.makeDir.all(dir)
    var top: SubdivAdc = null
    ChiselStage.emitSystemVerilogFile({ top = new SubdivAdc(p, format); top }, Array("--target-dir", dir.toString), firtoolOpts)
    (dir / s"${top.desiredName}.sv", top.latency, top.desiredName)
  }

  def run(c: SubdivConfig, out: String): Unit = {
    val p = c.params
    val (file, latency, name) = emit(p, c.format, out)
    println(s"wrote $file ($name, latency $latency clocks from ADC pins to position)")
  }
}
