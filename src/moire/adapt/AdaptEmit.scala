package moire.adapt

import circt.stage.ChiselStage
import moire.cli.Emit

/** Writes the corrector's SystemVerilog: `./sbt "runMain moire.adapt.AdaptEmit <dir>"` (default parameters). */
object AdaptEmit {
  def emit(p: AdaptParams, out: String): os.Path = {
    val dir = os.Path(out, os.pwd)
    os.makeDir.all(dir)
    ChiselStage.emitSystemVerilogFile(new AdaptiveCorrector(p), Array("--target-dir", dir.toString), Emit.firtoolOpts)
    dir / s"${p.moduleName}.sv"
  }
  def main(args: Array[String]): Unit = println(emit(AdaptParams(), args.headOption.getOrElse("generated")))
}
