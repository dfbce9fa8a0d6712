package moire.replay

import chisel3.RawModule
import moire.chain.{AdcPinCodes, CorrectedSubdivModel, CorrectedSubdivParams}
import moire.designs.{Design, Designs}
import moire.emit.Target
import moire.options.SubdivConfig
import moire.signal.{Adc, AdcFormat}
import moire.subdiv.{SubdivCycle, SubdivModel, SubdivParams, SubdivSample}

/** The clock-level model of a replayable design: one clock with the pins as driven, what the outputs show. */
trait PinModel {
  def clock(valid: Boolean, sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean): SubdivCycle
}

/** A design that replay can run: ADC pin codes in (Valid(AdcPins)), SubdivOut, A/B/Z and status out.
  * `out` gives the output formats (position width, phase bits, M). The RTL, its top name and its
  * latency (pins -> out) come from the design registry ([[moire.designs.Designs]]).
  */
sealed trait ReplayDesign {
  def name: String
  def inputBits: Int
  def format: AdcFormat
  def out: SubdivParams
  /** The registry entry: generator, top name and latency read from the elaborated module. */
  def design: Design
  def latency: Int = design.latency.get
  def topName: String = design.topName
  def gen(): RawModule = design.gen()
  /** A fresh clock-level model, from reset. */
  def model(): PinModel
  /** The subdivider's own model when its period counter can be seeded mid-run (windows of a long replay). */
  def subdivModel: Option[SubdivParams]
  def describe: String = s"$name $topName (${design.what})"
  /** The Verilog of the whole design as one text (what Verilator builds). */
  def verilog(): String = design.verilog(Target.Verilog)
}

object ReplayDesign {
  /** The registry's designs that have a pin-level model. */
  val names: Seq[String] = Seq("subdiv", "corrected")

  /** The emit-subdiv options the corrected chain takes (the rest of it is at its defaults; it reads 12-bit codes). */
  val correctedOptions: Seq[String] = Seq("--counts", "--adc-format", "--input-bits")

  /** `subdiv` takes the emit-subdiv options; `corrected` is the corrected chain at its defaults but for its counts per
    * period (M) and ADC format (`correctedOptions`).
    */
  def apply(name: String, config: SubdivConfig): ReplayDesign =
    moire.choice.Choice(names, name, s"--design: '$name' is not a replayable design")(identity).fold(e => throw new ReplayError(e), identity) match {
      case "subdiv" => Subdiv(config.params, config.format)
      case _ =>
        // as the board projects make it (`BoardCmd.params`): the default chain with its counts per period
        val sub = try CorrectedSubdivParams().subdiv.copy(counts = config.counts)
          catch { case e: IllegalArgumentException => throw new ReplayError("--" + e.getMessage.stripPrefix("requirement failed: ")) }
        Corrected(CorrectedSubdivParams(subdiv = sub, format = config.format))
    }

  final case class Subdiv(p: SubdivParams, format: AdcFormat) extends ReplayDesign {
    def name = "subdiv"
    def inputBits: Int = p.inputBits
    def out: SubdivParams = p
    lazy val design: Design = Designs.subdiv(p, format)
    def subdivModel: Option[SubdivParams] = Some(p)
    def model(): PinModel = new PinModel {
      private val m = new SubdivModel(p)
      private val adc = Adc(p.inputBits, format)
      private var prev: Option[SubdivSample] = None // the front end's register
      def clock(valid: Boolean, sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean): SubdivCycle = {
        val c = m.clock(prev)
        prev = if (valid) Some(SubdivSample(adc.fromPins(sin), adc.fromPins(cos), otrSin, otrCos)) else None
        c
      }
    }
  }

  final case class Corrected(p: CorrectedSubdivParams) extends ReplayDesign {
    def name = "corrected"
    def inputBits: Int = p.adapt.inputBits
    def format: AdcFormat = p.format
    def out: SubdivParams = p.subdiv
    lazy val design: Design = Designs.corrected(p)
    def subdivModel: Option[SubdivParams] = None
    def model(): PinModel = new PinModel {
      private val m = new CorrectedSubdivModel(p)
      def clock(valid: Boolean, sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean): SubdivCycle =
        m.clock(valid, AdcPinCodes(sin, cos, otrSin, otrCos))
    }
  }
}
