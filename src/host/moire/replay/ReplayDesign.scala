package moire.replay

import chisel3.RawModule
import moire.chain.{AdcPinCodes, CorrectedSubdivModel, CorrectedSubdivParams, CorrectedSubdivider}
import moire.emit.{Emit, Target}
import moire.options.SubdivConfig
import moire.signal.{Adc, AdcFormat}
import moire.subdiv.{SubdivAdc, SubdivCycle, SubdivModel, SubdivParams, SubdivSample}

/** The clock-level model of a replayable design: one clock with the pins as driven, what the outputs show. */
trait PinModel {
  def clock(valid: Boolean, sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean): SubdivCycle
}

/** A design that replay can run: ADC pin codes in (Valid(AdcPins)), SubdivOut, A/B/Z and status out.
  * `out` gives the output formats (position width, phase bits, M); `latency` is pins -> out.
  */
sealed trait ReplayDesign {
  def name: String
  def inputBits: Int
  def format: AdcFormat
  def out: SubdivParams
  def latency: Int
  def topName: String
  def gen(): RawModule
  /** A fresh clock-level model, from reset. */
  def model(): PinModel
  /** The subdivider's own model when its period counter can be seeded mid-run (windows of a long replay). */
  def subdivModel: Option[SubdivParams]
  def describe: String
  /** SystemVerilog of the whole design as one text (the same lowering as emit-subdiv). */
  def verilog(): String = Emit.elaborate(gen(), Target.Verilog)._2
}

object ReplayDesign {
  val names: Seq[String] = Seq("subdiv", "corrected")

  /** `subdiv` takes the emit-subdiv options; `corrected` is the corrected chain at its defaults (M = 1024). */
  def apply(name: String, config: SubdivConfig): ReplayDesign = name match {
    case "subdiv" => Subdiv(config.params, config.format)
    case "corrected" => Corrected(CorrectedSubdivParams(format = config.format))
    case other => throw new ReplayError(s"--design: '$other' is not a replayable design; allowed: ${names.mkString(", ")}")
  }

  final case class Subdiv(p: SubdivParams, format: AdcFormat) extends ReplayDesign {
    def name = "subdiv"
    def inputBits: Int = p.inputBits
    def out: SubdivParams = p
    def latency: Int = 1 + p.latency
    def topName = s"${p.moduleName}_${moire.subdiv.AdcFrontEnd.tag(format)}"
    def gen(): RawModule = new SubdivAdc(p, format)
    def subdivModel: Option[SubdivParams] = Some(p)
    def describe = s"subdiv $topName (${p.method.name}, M = ${p.counts}, ${p.inputBits}-bit ${format.name} ADC)"
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
    def latency: Int = p.latency
    def topName: String = p.moduleName
    def gen(): RawModule = new CorrectedSubdivider(p)
    def subdivModel: Option[SubdivParams] = None
    def describe = s"corrected $topName (adaptive corrector + subdivider, M = ${p.subdiv.counts}, ${inputBits}-bit ${format.name} ADC)"
    def model(): PinModel = new PinModel {
      private val m = new CorrectedSubdivModel(p)
      def clock(valid: Boolean, sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean): SubdivCycle =
        m.clock(valid, AdcPinCodes(sin, cos, otrSin, otrCos))
    }
  }
}
