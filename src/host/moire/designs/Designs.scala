package moire.designs

import chisel3.RawModule
import moire.adapt.{AdaptParams, AdaptiveCorrector}
import moire.board.{Board, BoardParams, Boards, Mhz}
import moire.chain.{CorrectedSubdivParams, CorrectedSubdivider}
import moire.cordic.{Cordic, CordicParams}
import moire.emit.{Emit, Latency, Target}
import moire.harmonic.{HarmonicCompensator, HarmonicParams, TurntableCompensator}
import moire.io.{QuadratureCounter, QuadratureParams}
import moire.quadcomp.{QuadComp, QuadCompParams}
import moire.signal.AdcFormat
import moire.subdiv.{SubdivAdc, SubdivParams}

/** One design: a name, a one-line description and its generator. The top's name and latency are
  * read from the elaborated module (elaborated once, on first use). `place` is the generator `timing`
  * places on the ECP5 (a DE2-115 top without its Cyclone IV PLL); the design itself elsewhere.
  */
final class Design(val name: String, val what: String, val gen: () => RawModule, val place: () => RawModule) {
  def this(name: String, what: String, gen: () => RawModule) = this(name, what, gen, gen)

  private var top: Option[RawModule] = None
  private def keep(m: RawModule): RawModule = { if (top.isEmpty) top = Some(m); m }

  /** The elaborated top (no lowering). */
  def module: RawModule = top.getOrElse(keep(Emit.module(gen())))
  /** The top module's name, as the Verilog declares it. */
  def topName: String = module.desiredName
  /** Clocks from input to output, when the top has one pipeline depth ([[moire.emit.Latency]]). */
  def latency: Option[Int] = module match { case l: Latency => Some(l.latency); case _ => None }

  /** The Verilog text for `target` (design first, black boxes appended). */
  def verilog(target: Target): String = { val (m, text) = Emit.elaborate(gen(), target); keep(m); text }
  /** Writes the Verilog files for `target` into `dir` (one per module); returns them, the top's first. */
  def write(dir: os.Path, target: Target): Seq[os.Path] = { val (m, files) = Emit.write(gen(), dir, target); keep(m); files }

  /** `name (what), top T, latency N clocks` for the command line. */
  def describe: String = s"$name ($what), top $topName" + latency.fold("")(n => s", latency $n clocks")
  override def toString: String = s"Design($name)"
}

/** The registry: every design the commands emit, cost, time, replay, bench and put on a board. */
object Designs {
  /** One CORDIC; `cordic` in the registry is this at the options `emit` and `cost` take. */
  def cordic(p: CordicParams): Design =
    new Design("cordic", s"one CORDIC (${p.mode.name}, n = ${p.iterations}, b = ${p.width})", () => new Cordic(p))
  /** ADC front end + subdivider (the board's datapath), at the options of emit-subdiv. */
  def subdiv(p: SubdivParams, f: AdcFormat): Design = new Design("subdiv",
    s"ADC front end + subdivider (${p.method.name}, M = ${p.counts}, ${p.inputBits}-bit ${f.name} ADC)", () => new SubdivAdc(p, f))
  def quadcomp(p: QuadCompParams): Design = new Design("quadcomp",
    s"quadrature-error compensation, n = ${p.iterations}, b = ${p.width} (seed 000)", () => new QuadComp(p))
  def adapt(p: AdaptParams): Design = new Design("adapt",
    s"adaptive offset/gain/phase/harmonic corrector, ${p.inputBits}-bit in, ${p.outputBits}-bit out", () => new AdaptiveCorrector(p))
  def corrected(p: CorrectedSubdivParams): Design = new Design("corrected",
    s"ADC front end + adaptive corrector + subdivider (M = ${p.subdiv.counts}, ${p.adapt.inputBits}-bit ${p.format.name} ADC)",
    () => new CorrectedSubdivider(p))
  def harmonic(p: HarmonicParams): Design = new Design("harmonic",
    s"turntable harmonic compensator, m = ${p.harmonics} parallel CORDICs (seed 001)", () => new HarmonicCompensator(p))
  def turntable(p: HarmonicParams): Design = new Design("turntable",
    s"A/B quadrature counter + harmonic compensator, m = ${p.harmonics} (seed 001)", () => new TurntableCompensator(p))
  /** The A/B quadrature counter that feeds the compensator. */
  def counter(p: QuadratureParams): Design =
    new Design("counter", s"A/B quadrature counter, ${p.countBits}-bit count", () => new QuadratureCounter(p))

  /** A board's top (what its vendor flow compiles); `timing` places it with [[Board.placeParams]]. */
  def boardTop(b: Board, name: String, p: BoardParams): Design = new Design(name,
    s"${b.title} board top: ${p.design.name} datapath, ${p.clockSource.name} clock, ADC at ${Mhz(p.adcClockHz)} MHz ${p.formatName}, " +
      "UART stream and registers, encoder I/O", () => b.top(p), () => b.top(b.placeParams(p)))

  /** Every design at its defaults; `cordic` at the given CORDIC options. */
  def all(cordicParams: CordicParams = CordicParams()): Seq[Design] = Seq(
    cordic(cordicParams),
    subdiv(SubdivParams(), AdcFormat.OffsetBinary),
    quadcomp(QuadCompParams()),
    adapt(AdaptParams()),
    corrected(CorrectedSubdivParams()),
    harmonic(HarmonicParams()),
    turntable(HarmonicParams()),
    counter(QuadratureParams(HarmonicParams().countBits))) ++
    // every board's tops: board-NAME (the subdivider), board-NAME-DESIGN
    (for (b <- Boards.all; d <- b.registryDesigns)
      yield boardTop(b, b.registryName(d), BoardParams(design = d)))

  lazy val names: Seq[String] = all().map(_.name)

  /** The design called `name`, or a one-line message naming the allowed ones. */
  def find(name: String, cordicParams: CordicParams = CordicParams()): Either[String, Design] =
    moire.choice.Choice(all(cordicParams), name, s"--design: '$name' is not a design")(_.name)
}
