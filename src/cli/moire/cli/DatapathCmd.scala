package moire.cli

import chisel3.RawModule
import moire.emit.{Emit, Target}
import moire.adapt.{AdaptParams, AdaptiveCorrector}
import moire.chain.{CorrectedSubdivParams, CorrectedSubdivider}
import moire.quadcomp.{QuadComp, QuadCompParams}

/** `emit-datapath`: the SystemVerilog of a datapath at its default parameters. */
object DatapathCmd {
  final case class Design(name: String, what: String, latency: Int, gen: () => RawModule)
  val designs: Seq[Design] = Seq(
    Design("quadcomp", "quadrature-error compensation (seed 000)", QuadCompParams().latency, () => new QuadComp(QuadCompParams())),
    Design("adapt", "adaptive offset/gain/phase/harmonic corrector", AdaptParams().latency, () => new AdaptiveCorrector(AdaptParams())),
    Design("corrected", "ADC front end + adaptive corrector + subdivider (M = 1024)", CorrectedSubdivParams().latency,
      () => new CorrectedSubdivider(CorrectedSubdivParams())))

  def run(design: String, out: String): Unit = {
    val d = designs.find(_.name == design).getOrElse(throw new UsageError(
      s"--design: '$design' is not a datapath; allowed: ${designs.map(_.name).mkString(", ")}"))
    val file = Emit.write(d.gen(), os.Path(out, os.pwd), Target.SystemVerilog)._2.head
    println(s"wrote $file (${d.what}, latency ${d.latency} clocks)")
  }
}
