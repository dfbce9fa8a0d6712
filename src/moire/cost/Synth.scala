package moire.cost

import chisel3.RawModule
import circt.stage.ChiselStage

/** Elaborates a module and writes plain Verilog that yosys 0.23 reads (no automatic locals, no
  * packed arrays); returns the top module's name and every Verilog file in `dir` (the design plus
  * black-box resources).
  */
object Synth {
  val firtoolOpts: Array[String] = moire.cli.SubdivCmd.firtoolOpts

  def emit(gen: () => RawModule, dir: os.Path): (String, Seq[os.Path]) = {
    var top = ""
    val sv = ChiselStage.emitSystemVerilog({ val m = gen(); top = m.desiredName; m }, Array.empty[String], firtoolOpts)
    (top, moire.cli.Emit.writeSplit(sv, s"$top.sv", dir))
  }
}
