package moire.chain

import chisel3._
import chisel3.util._
import moire.adapt.{AdaptiveCorrector, AdaptModel, AdaptParams}
import moire.signal.{Adc, AdcFormat}
import moire.subdiv._

/** ADC pins -> adaptive corrector -> subdivider: the full encoder datapath of issue 3.
  *
  * @param adapt  the corrector; its `outputBits` is the subdivider's `inputBits`
  * @param subdiv the subdivider (its `asinAmplitude` should be 1/sqrt 2, the corrector's output amplitude)
  * @param format how the ADC pins code the samples
  */
final case class CorrectedSubdivParams(
  adapt: AdaptParams = AdaptParams(),
  subdiv: SubdivParams = SubdivParams(inputBits = 16, asinAmplitude = math.sqrt(0.5)),
  format: AdcFormat = AdcFormat.OffsetBinary
) {
  require(adapt.outputBits == subdiv.inputBits,
    s"the corrector's output bits (${adapt.outputBits}) must equal the subdivider's input bits (${subdiv.inputBits})")
  /** Front end + corrector + subdivider, clocks. */
  val latency: Int = AdcFrontEnd.latency + adapt.latency + subdiv.latency
  val moduleName: String = s"Corrected_${adapt.moduleName}_${subdiv.moduleName}_${AdcFrontEnd.tag(format)}"
  /** The front end only reads the input width from its params. */
  private[chain] val frontEnd: SubdivParams = SubdivParams(inputBits = adapt.inputBits)
}

/** Pin codes in; the subdivider's outputs, A/B/Z and status out. Latency [[CorrectedSubdivParams.latency]].
  * `withReadBack`: the corrector's learned state out as `readBack` (the board's registers read it).
  */
class CorrectedSubdivider(val p: CorrectedSubdivParams, withReadBack: Boolean = false) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new AdcPins(p.adapt.inputBits)))
    val out = Valid(new SubdivOut(p.subdiv))
    val a = Output(Bool())
    val b = Output(Bool())
    val z = Output(Bool())
    val status = Output(new SubdivStatus(p.subdiv))
    val clearStatus = Input(Bool())
  })
  private val fe = Module(new AdcFrontEnd(p.frontEnd, p.format))
  private val ac = Module(new AdaptiveCorrector(p.adapt, withReadBack))
  private val sd = Module(new Subdivider(p.subdiv))
  val latency: Int = fe.latency + ac.latency + sd.latency
  require(latency == p.latency)
  fe.io.in := io.in
  ac.io.in.valid := fe.io.out.valid
  ac.io.in.bits.sin := fe.io.out.bits.sin
  ac.io.in.bits.cos := fe.io.out.bits.cos
  ac.io.in.bits.otrSin := fe.io.out.bits.otrSin
  ac.io.in.bits.otrCos := fe.io.out.bits.otrCos
  sd.io.in.valid := ac.io.out.valid
  sd.io.in.bits.sin := ac.io.out.bits.sin
  sd.io.in.bits.cos := ac.io.out.bits.cos
  sd.io.in.bits.otrSin := ac.io.out.bits.otrSin
  sd.io.in.bits.otrCos := ac.io.out.bits.otrCos
  sd.io.clearStatus := io.clearStatus
  io.out := sd.io.out
  io.a := sd.io.a
  io.b := sd.io.b
  io.z := sd.io.z
  io.status := sd.io.status
  val readBack: Option[moire.adapt.AdaptReadBackIO] = ac.readBack.map { rb =>
    val x = IO(new moire.adapt.AdaptReadBackIO(p.adapt))
    x <> rb
    x
  }
  val preset: Option[moire.adapt.AdaptPresetIO] = ac.preset.map { pr =>
    val x = IO(new moire.adapt.AdaptPresetIO(p.adapt))
    pr <> x
    x
  }
}

/** Codes on the ADC pins in one clock. */
final case class AdcPinCodes(sin: Int, cos: Int, otrSin: Boolean = false, otrCos: Boolean = false)

/** Clock-accurate model of [[CorrectedSubdivider]]: the corrector's and subdivider's models chained. */
final class CorrectedSubdivModel(val p: CorrectedSubdivParams) {
  private val adc = Adc(p.adapt.inputBits, p.format)
  val adapt = new AdaptModel(p.adapt)
  val subdiv = new SubdivModel(p.subdiv)
  private var feValid = false
  private var fe = (0L, 0L)
  private var feOtr = (false, false)

  /** One clock with the pins as driven (codes and OTR, meaningful when `valid`): what the outputs show. */
  def clock(valid: Boolean, pins: AdcPinCodes, clear: Boolean = false): SubdivCycle = {
    val a = adapt.step(if (feValid) Some(fe) else None, feOtr)
    val c = subdiv.clock(a.map(o => SubdivSample(o.sin.toInt, o.cos.toInt, o.otrSin, o.otrCos)), clear)
    feValid = valid
    fe = (adc.fromPins(pins.sin).toLong, adc.fromPins(pins.cos).toLong)
    feOtr = (pins.otrSin, pins.otrCos)
    c
  }
}
