package moire.adapt

import moire.emit.{Emit, Target}

/** Writes the corrector's SystemVerilog: `./sbt "runMain moire.adapt.AdaptEmit <dir>"` (default parameters). */
object AdaptEmit {
  def emit(p: AdaptParams, out: String): os.Path =
    Emit.write(new AdaptiveCorrector(p), os.Path(out, os.pwd), Target.SystemVerilog)._2.head
  def main(args: Array[String]): Unit = println(emit(AdaptParams(), args.headOption.getOrElse("generated")))
}
