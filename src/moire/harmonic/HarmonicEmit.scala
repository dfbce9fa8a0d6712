package moire.harmonic

import circt.stage.ChiselStage

/** Writes the SystemVerilog of a compensator (with its CORDICs) and, optionally, the quadrature counter. */
object HarmonicEmit {
  def apply(p: HarmonicParams, out: os.Path, counter: Boolean): Seq[os.Path] = {
    os.makeDir.all(out)
    val opts = moire.cli.Emit.firtoolOpts
    ChiselStage.emitSystemVerilogFile(new HarmonicCompensator(p), Array("--target-dir", out.toString), opts)
    val q = QuadratureParams(p.countBits)
    if (counter) ChiselStage.emitSystemVerilogFile(new QuadratureCounter(q), Array("--target-dir", out.toString), opts)
    Seq(out / s"${p.moduleName}.sv") ++ (if (counter) Seq(out / s"${q.moduleName}.sv") else Nil)
  }
}
