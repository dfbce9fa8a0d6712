package moire.cli

import circt.stage.ChiselStage
import moire.cordic.{Cordic, CordicParams}

/** Writes SystemVerilog through firtool (fetched by Chisel's own resolver). */
object Emit {
  val firtoolOpts: Array[String] = Array("-disable-all-randomization", "-strip-debug-info")

  def cordic(p: CordicParams, out: String): os.Path = {
    val dir = os.Path(out, os.pwd)
    os.makeDir.all(dir)
    ChiselStage.emitSystemVerilogFile(new Cordic(p), Array("--target-dir", dir.toString), firtoolOpts)
    dir / s"${p.moduleName}.sv"
  }
}
