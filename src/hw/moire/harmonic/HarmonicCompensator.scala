package moire.harmonic

import chisel3._
import chisel3.util._
import moire.cordic.{Cordic, FixedHw, Rounding}

/** Register write port: `data` lands in register `addr` on a clock edge with `we` high.
  * Address = slot * 4 + field; field 0 = order k (unsigned), 1 = c_k (two's complement, low coefWidth
  * bits used), 2 = phi_k (binary angle, low countBits bits used). Other addresses are ignored.
  */
class HarmonicRegPort(p: HarmonicParams) extends Bundle {
  val we = Bool()
  val addr = UInt(p.addrBits.W)
  val data = UInt(p.regWidth.W)
}

class HarmonicResult(p: HarmonicParams) extends Bundle {
  /** theta - f(theta): counts with outFrac fractional bits, modulo one turn. */
  val theta = UInt(p.outWidth.W)
  /** f(theta): counts with outFrac fractional bits. */
  val f = SInt(p.fWidth.W)
}

/** Turntable harmonic compensation (seed 001 fig. 5): m parallel sine CORDICs compute
  * f(theta) = sum_k c_k sin(k theta + phi_k), the output is theta - f(theta).
  * Latency `p.latency` clocks, one angle per clock; formats in [[HarmonicParams]].
  * Coefficient writes take effect on the next clock; results in flight during a write may mix
  * old and new coefficients (load them while in.valid is low, or discard `latency` results).
  * Bit-exact with [[HarmonicModel]].
  */
class HarmonicCompensator(val p: HarmonicParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val reg = Input(new HarmonicRegPort(p))
    val in = Flipped(Valid(UInt(p.countBits.W)))
    val out = Valid(new HarmonicResult(p))
  })
  val latency: Int = p.latency

  // ---- coefficient registers ----
  private val orders = RegInit(VecInit(Seq.fill(p.harmonics)(0.U(p.orderBits.W))))
  private val coefs = RegInit(VecInit(Seq.fill(p.harmonics)(0.S(p.coefWidth.W))))
  private val phases = RegInit(VecInit(Seq.fill(p.harmonics)(0.U(p.countBits.W))))
  orders.suggestName("order"); coefs.suggestName("coef"); phases.suggestName("phase")
  private val slot = io.reg.addr >> 2
  moire.emit.Unused("reg_data", io.reg.data) // each field takes the low bits it needs
  private val field = io.reg.addr(1, 0)
  for (j <- 0 until p.harmonics) when(io.reg.we && slot === j.U) {
    switch(field) {
      is(0.U) { orders(j) := io.reg.data(p.orderBits - 1, 0) }
      is(1.U) { coefs(j) := io.reg.data(p.coefWidth - 1, 0).asSInt }
      is(2.U) { phases(j) := io.reg.data(p.countBits - 1, 0) }
    }
  }

  // ---- angle stage, two clocks: k theta modulo one turn (a multiplier block), then + phi_k ----
  private val kTheta = reg(Vec(p.harmonics, UInt(p.countBits.W)), VecInit((0 until p.harmonics).map { j =>
    (io.in.bits * orders(j))(p.countBits - 1, 0)
  }), "k_theta")
  private val angles = reg(Vec(p.harmonics, UInt(p.countBits.W)), VecInit((0 until p.harmonics).map { j =>
    (kTheta(j) + phases(j))(p.countBits - 1, 0)
  }), "angle")
  private val angleValid = ShiftRegister(io.in.valid, 2, false.B, true.B)

  // ---- m parallel sine CORDICs ----
  private val sines = (0 until p.harmonics).map { j =>
    val c = Module(new Cordic(p.cordic))
    c.io.in.valid := angleValid
    c.io.in.bits.x := 0.S
    c.io.in.bits.y := 0.S
    c.io.in.bits.z := angles(j).asSInt
    c.io.out.bits.y
  }

  // ---- products (PieceMul, three clocks each), sum, scale to counts, rounding, subtract ----
  private def reg[T <: Data](t: T, v: T, name: String): T = { val r = Reg(t); r := v; r.suggestName(name); r }
  private val prods = sines.zip(coefs).zipWithIndex.map { case ((s, c), j) => PieceMul(c, s, s"prod_$j") }
  private val sum = reg(SInt(p.sumWidth.W), VecInit(prods.map(_.pad(p.sumWidth))).reduceTree(_ + _), "sum")
  private val scaled = PieceMul(sum, p.kConst.S((p.kBits + 1).W), "k_product")
  private val f = reg(SInt(p.fWidth.W), FixedHw.shift(scaled, p.fShift, Rounding.HalfEven), "f_counts")
  private val thetaLate = ShiftRegister(io.in.bits, latency - 1)
  private val result = Wire(new HarmonicResult(p))
  result.f := f
  private val thetaFix = if (p.outFrac == 0) thetaLate else Cat(thetaLate, 0.U(p.outFrac.W))
  result.theta := (thetaFix - f.pad(p.outWidth).asUInt)(p.outWidth - 1, 0)
  io.out.bits := RegNext(result)
  io.out.valid := ShiftRegister(io.in.valid, latency, false.B, true.B)
}
