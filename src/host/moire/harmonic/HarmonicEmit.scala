package moire.harmonic

import moire.emit.{Emit, Target}
import moire.io.{QuadratureCounter, QuadratureParams}

/** Writes the SystemVerilog of a compensator (with its CORDICs) and, optionally, the quadrature counter. */
object HarmonicEmit {
  def apply(p: HarmonicParams, out: os.Path, counter: Boolean): Seq[os.Path] = {
    val comp = Emit.write(new HarmonicCompensator(p), out, Target.SystemVerilog)._2
    val q = if (counter) Emit.write(new QuadratureCounter(QuadratureParams(p.countBits)), out, Target.SystemVerilog)._2 else Nil
    comp ++ q
  }
}
