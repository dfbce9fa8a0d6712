package moire.calibration

import moire.harmonic._

import moire.designs.Designs
import moire.emit.Target
import moire.io.QuadratureParams

/** Writes the SystemVerilog of a compensator (with its CORDICs) and, optionally, the quadrature counter. */
object HarmonicEmit {
  def apply(p: HarmonicParams, out: os.Path, counter: Boolean): Seq[os.Path] = {
    val comp = Designs.harmonic(p).write(out, Target.SystemVerilog)
    val q = if (counter) Designs.counter(QuadratureParams(p.countBits)).write(out, Target.SystemVerilog) else Nil
    comp ++ q
  }
}
