package moire.quadcomp

import chisel3._
import chisel3.util._
import moire.cordic.{Cordic, FixedHw}

class QuadCompIn(p: QuadCompParams) extends Bundle {
  /** Signed ADC value of the sin channel. */
  val sin = SInt(p.inputBits.W)
  /** Signed ADC value of the cos channel. */
  val cos = SInt(p.inputBits.W)
}

class QuadCompOut(p: QuadCompParams) extends Bundle {
  /** Normalised sin channel, `width` bits, `dataFrac` fractional bits. */
  val sin = SInt(p.width.W)
  /** Rebuilt cos, same format. */
  val cos = SInt(p.width.W)
}

/** Real-time quadrature-error compensation (seed 000): phase resolution of both channels with the
  * double-rotation arcsine/arccosine and the peak table, phase difference at the sin channel's
  * 45 degree point once per period, full-period quadrant mapping (Table 2), correction applied to
  * the following samples, cos rebuilt by a rotation-mode CORDIC.
  * Latency `p.latency` clocks, one sample per clock; bit-exact with [[QuadCompModel]].
  * Formats in [[QuadCompParams]]. `diff` pulses with each raw measurement; `correction` is the
  * averaged correction now applied.
  */
class QuadComp(val p: QuadCompParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new QuadCompIn(p)))
    val gainSin = Input(UInt(p.gainBits.W))
    val gainCos = Input(UInt(p.gainBits.W))
    val out = Valid(new QuadCompOut(p))
    val diff = Valid(SInt(p.angleBits.W))
    val correction = Output(SInt(p.angleBits.W))
  })
  val latency: Int = p.latency

  private val a = p.angleBits
  private val r = p.rounding
  private def lit(v: Long, w: Int): SInt = v.S(w.W)

  // ---- normalise: code * gain, rounded to the data word ----
  private def normalise(code: SInt, gain: UInt): SInt =
    FixedHw.saturate(FixedHw.shift(code * Cat(0.U(1.W), gain).asSInt, p.normShift, r), p.width)
  private val nsReg = RegNext(normalise(io.in.bits.sin, io.gainSin)).suggestName("norm_sin")
  private val ncReg = RegNext(normalise(io.in.bits.cos, io.gainCos)).suggestName("norm_cos")
  private val normValid = RegNext(io.in.valid, false.B)

  // ---- phase resolution ----
  private val asin = Module(new Cordic(p.asinP))
  private val acos = Module(new Cordic(p.acosP))
  for ((c, v) <- Seq(asin -> nsReg, acos -> ncReg)) {
    c.io.in.valid := normValid
    c.io.in.bits.x := 0.S
    c.io.in.bits.y := v
    c.io.in.bits.z := 0.S
  }
  private val la = asin.latency
  private val ns = ShiftRegister(nsReg, la)
  private val nc = ShiftRegister(ncReg, la)
  private val valid = asin.io.out.valid

  // ---- quadrant mapping and correction (state advances on valid samples only) ----
  private val accBits = a + p.averageLog2 + 2
  private val acc = RegInit(0.S(accBits.W))
  private val pending = RegInit(0.S(a.W))
  private val flag = RegInit(false.B)
  private val first = RegInit(true.B)
  private val armed = RegInit(true.B)
  private val havePrev = RegInit(false.B)
  private val prevOctant = RegInit(0.U(3.W))
  private def rounded(v: SInt): SInt = FixedHw.shift(v, p.averageLog2, r)(a - 1, 0).asSInt
  // the averaged correction, acc / 2^averageLog2 rounded, registered beside acc from acc's next value (the
  // rounding is not in series with the quadrant tests that read it)
  private val corr = RegInit(0.S(a.W))
  private val d = corr.pad(a + 2)

  private val zs = asin.io.out.bits.z.pad(a + 2)
  private val zcRaw = acos.io.out.bits.z
  private val quarter = lit(1L << (a - 2), a + 2)
  private val zc = Mux(zcRaw < lit(-(1L << (a - 2)), a), zcRaw.pad(a + 2) + lit(1L << a, a + 2), zcRaw.pad(a + 2))
  private val incSin = Mux(ns >= 0.S, zc - d <= quarter, zc + d <= quarter)
  private val thetaSin = Mux(incSin, zs, lit(1L << (a - 1), a + 2) - zs)(a - 1, 0)
  private val posCos = Mux(nc >= 0.S, zs + d >= 0.S, zs - d >= 0.S)
  private val thetaCos = Mux(posCos, zc, -zc)(a - 1, 0)
  private val corrected = (thetaCos - corr.asUInt)(a - 1, 0).asSInt
  private val nearPeak = zc < lit(1L << (a - 3), a + 2) || zc > lit(3L << (a - 3), a + 2)
  private val psi = if (p.fusePeaks) Mux(nearPeak, thetaSin.asSInt, corrected) else corrected
  private val octant = thetaSin(a - 1, a - 3)
  private val trig = armed && havePrev &&
    ((prevOctant === 0.U && octant === 1.U) || (prevOctant === 1.U && octant === 0.U))
  private val meas = (thetaCos - thetaSin)(a - 1, 0).asSInt

  when(valid) {
    when(flag) {
      val next = Mux(first, (pending << p.averageLog2).pad(accBits),
        acc + pending.pad(accBits) - FixedHw.shift(acc, p.averageLog2, r))
      acc := next
      corr := rounded(next)
      first := false.B
    }
    flag := trig
    when(trig) { pending := meas }
    when(trig) { armed := false.B }.elsewhen(octant(2, 1) === 2.U) { armed := true.B }
    prevOctant := octant
    havePrev := true.B
  }
  io.diff.valid := RegNext(valid && trig, false.B)
  io.diff.bits := pending
  io.correction := corr

  // ---- signal reconstruction ----
  private val psiReg = RegNext(psi).suggestName("psi")
  private val sinReg = RegNext(ns).suggestName("sin_mapped")
  private val rebuild = Module(new Cordic(p.rebuildP))
  rebuild.io.in.valid := RegNext(valid, false.B)
  rebuild.io.in.bits.x := 0.S
  rebuild.io.in.bits.y := 0.S
  rebuild.io.in.bits.z := psiReg
  io.out.valid := rebuild.io.out.valid
  io.out.bits.cos := rebuild.io.out.bits.x
  io.out.bits.sin := ShiftRegister(sinReg, rebuild.latency)
}
