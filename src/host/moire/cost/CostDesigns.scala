package moire.cost

import chisel3.RawModule
import moire.board.{BoardDesign, BoardParams}
import moire.board.de2115.De2115
import moire.adapt.{AdaptParams, AdaptiveCorrector}
import moire.chain.{CorrectedSubdivParams, CorrectedSubdivider}
import moire.cordic.{Cordic, CordicParams}
import moire.harmonic.{HarmonicCompensator, HarmonicParams}
import moire.quadcomp.{QuadComp, QuadCompParams}
import moire.signal.AdcFormat
import moire.subdiv.{SubdivAdc, SubdivParams}

/** A design `cost --design NAME` can synthesize. `gen` gets the CORDIC of the emit options
  * (only the `cordic` design uses it); `latency` in clocks where the design has one.
  */
final case class CostDesign(name: String, what: String, gen: CordicParams => RawModule, latency: CordicParams => Option[Int])

/** The registry of named designs: adding one is one line. */
object CostDesigns {
  val all: Seq[CostDesign] = Seq(
    CostDesign("cordic", "one CORDIC configured by the emit options", p => new Cordic(p), p => Some(p.latency)),
    CostDesign("subdiv", "ADC front end + subdivider (default SubdivParams)",
      _ => new SubdivAdc(SubdivParams(), AdcFormat.OffsetBinary), _ => Some(1 + SubdivParams().latency)),
    CostDesign("quadcomp", "quadrature-error compensation (seed 000)", _ => new QuadComp(QuadCompParams()), _ => Some(QuadCompParams().latency)),
    CostDesign("adapt", "adaptive offset/gain/phase/harmonic corrector", _ => new AdaptiveCorrector(AdaptParams()), _ => Some(AdaptParams().latency)),
    CostDesign("corrected", "ADC front end + adaptive corrector + subdivider (M = 1024)",
      _ => new CorrectedSubdivider(CorrectedSubdivParams()), _ => Some(CorrectedSubdivParams().latency)),
    CostDesign("harmonic", "turntable harmonic compensator, m = 4 parallel CORDICs (seed 001)",
      _ => new HarmonicCompensator(HarmonicParams()), _ => Some(HarmonicParams().latency)),
    CostDesign("board-de2-115", "DE2-115 board top: two AD9226 captures, subdivider, UART stream and registers, encoder I/O",
      _ => De2115.top(boards("board-de2-115")), _ => None),
    CostDesign("board-de2-115-corrected", "DE2-115 board top with the adaptive corrector before the subdivider",
      _ => De2115.top(boards("board-de2-115-corrected")), _ => None)
  )

  /** The board parameters of the board designs. */
  lazy val boards: Map[String, BoardParams] =
    Map("board-de2-115" -> BoardParams(), "board-de2-115-corrected" -> BoardParams(design = BoardDesign.Corrected))

  def find(name: String): Either[String, CostDesign] =
    all.find(_.name == name).toRight(s"--design: '$name' is not a design; allowed: ${all.map(_.name).mkString(", ")}")
}
