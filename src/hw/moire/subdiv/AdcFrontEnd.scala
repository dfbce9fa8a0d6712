package moire.subdiv

import chisel3._
import chisel3.util._
import moire.signal.AdcFormat

/** Pin codes of the two ADCs as they arrive (AD9226: `bits` data lines plus OTR). */
class AdcPins(bits: Int) extends Bundle {
  val sin = UInt(bits.W)
  val cos = UInt(bits.W)
  val otrSin = Bool()
  val otrCos = Bool()
}

/** Converts ADC pin codes to signed values: offset binary inverts the MSB, two's complement is
  * read as it is (the same mapping as moire.signal.Adc.fromPins). Latency 1 clock (a register
  * that can sit in the I/O cells).
  */
class AdcFrontEnd(val p: SubdivParams, val format: AdcFormat) extends Module with moire.emit.Latency {
  override def desiredName: String = s"AdcFrontEnd_${p.inputBits}_${AdcFrontEnd.tag(format)}"
  val io = IO(new Bundle {
    val in = Flipped(Valid(new AdcPins(p.inputBits)))
    val out = Valid(new SubdivIn(p))
  })
  val latency: Int = AdcFrontEnd.latency
  private def conv(c: UInt): SInt = format match {
    case AdcFormat.OffsetBinary => Cat(~c(p.inputBits - 1), c(p.inputBits - 2, 0)).asSInt
    case AdcFormat.TwosComplement => c.asSInt
  }
  private val o = Wire(new SubdivIn(p))
  o.sin := conv(io.in.bits.sin)
  o.cos := conv(io.in.bits.cos)
  o.otrSin := io.in.bits.otrSin
  o.otrCos := io.in.bits.otrCos
  io.out.bits := RegNext(o)
  io.out.valid := RegNext(io.in.valid, false.B)
}

object AdcFrontEnd {
  /** Clocks through the front end: its one input register. */
  val latency: Int = 1
  def tag(f: AdcFormat): String = if (f == AdcFormat.OffsetBinary) "ob" else "tc"
}

/** The board-facing subdivider: [[AdcFrontEnd]] then [[Subdivider]], flat IO, pin codes in.
  * Latency [[SubdivAdc.latency]] clocks.
  */
class SubdivAdc(val p: SubdivParams, val format: AdcFormat) extends Module with moire.emit.Latency {
  override def desiredName: String = s"${p.moduleName}_${AdcFrontEnd.tag(format)}"
  val io = IO(new Bundle {
    val in = Flipped(Valid(new AdcPins(p.inputBits)))
    val out = Valid(new SubdivOut(p))
    val a = Output(Bool())
    val b = Output(Bool())
    val z = Output(Bool())
    val status = Output(new SubdivStatus(p))
    val clearStatus = Input(Bool())
  })
  private val fe = Module(new AdcFrontEnd(p, format))
  private val sd = Module(new Subdivider(p))
  val latency: Int = fe.latency + sd.latency
  fe.io.in := io.in
  sd.io.in := fe.io.out
  sd.io.clearStatus := io.clearStatus
  io.out := sd.io.out
  io.a := sd.io.a
  io.b := sd.io.b
  io.z := sd.io.z
  io.status := sd.io.status
}

object SubdivAdc {
  /** Clocks from the ADC pins to the position: the front end, then the subdivider. */
  def latency(p: SubdivParams): Int = AdcFrontEnd.latency + p.latency
}
