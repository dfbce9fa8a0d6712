package moire.cost

import chisel3.RawModule
import moire.emit.{Emit, Target}

/** Elaborates a module and writes plain Verilog that yosys reads; returns the top module's name and
  * every Verilog file in `dir` (the design plus black-box resources).
  */
object Synth {
  def emit(gen: () => RawModule, dir: os.Path): (String, Seq[os.Path]) = {
    val (top, files) = Emit.write(gen(), dir, Target.Verilog)
    (top.desiredName, files)
  }
}
