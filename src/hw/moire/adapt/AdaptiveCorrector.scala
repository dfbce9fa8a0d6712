package moire.adapt

import chisel3._
import chisel3.util._
import moire.cordic.{Cordic, FixedHw, Rounding}

/** One sample of the two Moire channels (signed) and the ADC over-range flags (AD9226 OTR). */
class AdaptSample(w: Int) extends Bundle {
  val sin = SInt(w.W)
  val cos = SInt(w.W)
  val otrSin = Bool()
  val otrCos = Bool()
}

/** Continuously adapting corrector of offset, gain, phase (Heydemann class) and harmonics.
  *
  * in: ADC samples, `inputBits` signed, one per clock (Valid). out: corrected samples, `outputBits`
  * signed, amplitude 2^(outputBits-1)/sqrt 2, `latency` clocks later; the OTR flags pass through
  * with the same delay. Same shape as the input, so it chains in front of the subdivision datapath. Formats and rates in [[AdaptParams]]; algorithm
  * in docs/adaptive-correction.md. Bit-exact with [[AdaptModel]].
  *
  * 12 multipliers (default widths, counted in the emitted Verilog): gains 18x24 (2), phase term
  * 16x18, statistics 16x16 (3), interpolation 23x8, radians 25x17 (constant 2 pi), rotation 18x16 (2),
  * table update 28x9 (2): at most 18 of the EP4CE115's 266 embedded 18x18 multipliers.
  */
class AdaptiveCorrector(val p: AdaptParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new AdaptSample(p.inputBits)))
    val out = Valid(new AdaptSample(p.outputBits))
  })
  val latency: Int = p.latency

  private val F = p.fineBits
  private def shR(v: SInt, s: Int): SInt = FixedHw.shift(v, s, Rounding.HalfEven)
  private def sat(v: SInt, w: Int): SInt = FixedHw.saturate(v, w)
  private def fit(v: SInt, w: Int): SInt = if (v.getWidth >= w) v(w - 1, 0).asSInt else v.pad(w)
  /** (v + 2^(s-1)) >> s for a run-time s >= 1. */
  private def shUp(v: SInt, s: UInt): SInt = {
    val half = (1.U(1.W) << (s - 1.U)).asUInt
    ((v +& Cat(0.U(1.W), half).asSInt) >> s).asSInt
  }
  /** A register of v's exact type (RegNext would forget the width). */
  private def reg[T <: Data](v: T): T = { val r = Reg(chiselTypeOf(v)); r := v; r }
  private def lit(v: Long, w: Int): SInt = v.S(w.W)
  private def abs(v: SInt): SInt = Mux(v < 0.S, 0.S -& v, v.pad(v.getWidth + 1))

  // ---- input register ----
  private val inV = RegNext(io.in.valid, false.B)
  private val inS = reg(io.in.bits.sin)
  private val inC = reg(io.in.bits.cos)

  // ---- offset, gain and phase estimates ----
  private val os = RegInit(0.S(p.offsetWidth.W))
  private val oc = RegInit(0.S(p.offsetWidth.W))
  private val ks = RegInit(p.startGain.S(p.gainBits.W))
  private val kc = RegInit(p.startGain.S(p.gainBits.W))
  private val t = RegInit(0.S(p.phaseBits.W))

  // ---- correction: sp = (s - os) ks, cp = (c - oc) kc + sp t ----
  private val s1 = fit((inS << p.offsetFrac).asSInt -& os, p.diffWidth)
  private val c1 = fit((inC << p.offsetFrac).asSInt -& oc, p.diffWidth)
  private val s1r = fit(shR(s1, p.offsetFrac - p.mulFrac), p.mulWidth)
  private val c1r = fit(shR(c1, p.offsetFrac - p.mulFrac), p.mulWidth)
  private val spW = sat(shR(s1r * ks, p.mulFrac + p.gainFrac), p.outputBits)
  private val cpW = sat(shR(c1r * kc, p.mulFrac + p.gainFrac) +& shR(spW * t, p.phaseFrac), p.outputBits)
  private val hV = RegNext(inV, false.B)
  private val hSp = reg(spW)
  private val hCp = reg(cpW)
  private val hS1 = reg(s1)
  private val hC1 = reg(c1)

  // ---- per-window statistics of the corrected signals ----
  private val target = lit(1L << p.targetSquareLog2, 2 * p.outputBits)
  private val aS = Reg(SInt(p.sumOffsetWidth.W)); private val aC = Reg(SInt(p.sumOffsetWidth.W))
  private val bS = Reg(SInt(p.sumSquareWidth.W)); private val bC = Reg(SInt(p.sumSquareWidth.W))
  private val cX = Reg(SInt(p.sumSquareWidth.W))
  private val n = RegInit(0.U(p.periodBits.W))
  private val prevQ = RegInit(0.U(2.W))
  private val seen = RegInit(0.U(4.W))
  private val q = Mux(hSp >= 0.S, Mux(hCp >= 0.S, 0.U(2.W), 1.U), Mux(hCp < 0.S, 2.U, 3.U))
  private val start = q === 0.U && prevQ =/= 0.U
  private val whole = (seen & 0xE.U) === 0xE.U && n < p.countMax.U
  private val restart = start && !(whole && n < (1L << p.windowBits).U)
  private val ds = target -& hSp * hSp
  private val dc = target -& hCp * hCp
  private val xc = hSp * hCp
  when(hV) {
    when(restart) {
      aS := fit(hS1, p.sumOffsetWidth); aC := fit(hC1, p.sumOffsetWidth)
      bS := fit(ds, p.sumSquareWidth); bC := fit(dc, p.sumSquareWidth); cX := fit(xc, p.sumSquareWidth)
      n := 1.U; seen := 0.U
    }.elsewhen(n < p.countMax.U) {
      aS := fit(aS +& hS1, p.sumOffsetWidth); aC := fit(aC +& hC1, p.sumOffsetWidth)
      bS := fit(bS +& ds, p.sumSquareWidth); bC := fit(bC +& dc, p.sumSquareWidth); cX := fit(cX +& xc, p.sumSquareWidth)
      n := n + 1.U
      seen := Mux(start, 0.U, seen) | UIntToOH(q, 4)
    }
    prevQ := q
  }
  when(hV && restart && whole) {
    val l = Log2(n) +& 1.U
    val gMax = lit((1L << (p.gainBits - 1)) - 1, p.gainBits)
    def gain(k: SInt, b: SInt): SInt = {
      val v = k +& shUp(b, l + (p.gainRate + p.gainShift).U)
      Mux(v < 1.S, 1.S(p.gainBits.W), Mux(v > gMax, gMax, fit(v, p.gainBits)))
    }
    os := sat(os +& shUp(aS, l + p.offsetRate.U), p.offsetWidth)
    oc := sat(oc +& shUp(aC, l + p.offsetRate.U), p.offsetWidth)
    ks := gain(ks, bS)
    kc := gain(kc, bC)
    t := sat(t -& shUp(cX, l + (p.phaseRate + p.phaseShift).U), p.phaseBits)
  }

  // ---- vectoring CORDIC (reused), data delayed beside it ----
  private val cordic = Module(new Cordic(p.cordic))
  cordic.io.in.valid := hV
  cordic.io.in.bits.x := hCp
  cordic.io.in.bits.y := hSp
  cordic.io.in.bits.z := 0.S
  private val lc = p.cordic.latency
  private val dSp = (0 until lc).foldLeft(hSp)((x, _) => reg(x))
  private val dCp = (0 until lc).foldLeft(hCp)((x, _) => reg(x))
  private val phi1 = cordic.io.out.bits.z

  // ---- harmonic table: read and interpolate ----
  private val entries = math.max(p.harmonicEntries, 1)
  private val ib = math.max(p.tableIndexBits, 1)
  private val table = RegInit(VecInit(Seq.fill(entries)(0.S(p.tableBits.W))))
  private val tableSum = RegInit(0.S((p.tableBits + p.tableIndexBits).W))
  private val u = phi1.asUInt
  private val aw = p.angleBits
  private val idx: UInt = if (p.harmonicEntries > 0) u(aw - 1, aw - p.tableIndexBits) else 0.U(ib.W)
  private val frac: UInt = u(aw - p.tableIndexBits - 1, aw - p.tableIndexBits - p.interpBits)
  private val delta: SInt = if (p.harmonicEntries > 0) {
    val a = table(idx); val b = table(idx +% 1.U)
    a +& shR((b -& a) * frac.zext, p.interpBits) -& shR(tableSum, p.tableIndexBits)
  } else 0.S(2.W)
  private val dw = p.tableBits + 3
  private val p1V = RegNext(cordic.io.out.valid, false.B)
  private val p1Sp = reg(dSp); private val p1Cp = reg(dCp); private val p1Phi = reg(phi1)
  private val p1Idx = reg(idx); private val p1Frac = reg(frac); private val p1Delta = reg(fit(delta, dw))

  // ---- P2: rotation angle in radians, corrected fine phase ----
  private val dr = sat(shR(p1Delta * lit(p.twoPi, p.twoPiFrac + 4), p.twoPiFrac + F - p.rotFrac), p.rotWidth)
  private val phic = fit((p1Phi << p.fineGuard).asSInt -& p1Delta, F)
  private val p2V = RegNext(p1V, false.B)
  private val p2Sp = reg(p1Sp); private val p2Cp = reg(p1Cp); private val p2Dr = reg(dr)
  private val p2Idx = reg(p1Idx); private val p2Frac = reg(p1Frac); private val p2Phic = reg(phic)

  // ---- output: small rotation by -delta ----
  private val outV = RegNext(p2V, false.B)
  private val outCos = reg(sat(p2Cp +& shR(p2Dr * p2Sp, p.rotFrac), p.outputBits))
  private val outSin = reg(sat(p2Sp -& shR(p2Dr * p2Cp, p.rotFrac), p.outputBits))
  io.out.valid := outV
  io.out.bits.sin := outSin
  io.out.bits.cos := outCos
  // the over-range flags travel beside the data, unchanged
  io.out.bits.otrSin := ShiftRegister(io.in.bits.otrSin, latency)
  io.out.bits.otrCos := ShiftRegister(io.in.bits.otrCos, latency)

  // ---- PLL (smoothed phase) and LMS update of the table ----
  private val theta = RegInit(0.S(F.W))
  private val vel = RegInit(0.S(F.W))
  private val prevPhic = RegInit(0.S(F.W))
  private val lockMax = (1L << p.lockBits) - 1
  private val lockCnt = RegInit(0.U(p.lockBits.W))
  when(p2V) {
    val pred = fit(theta +& vel, F)
    val e = fit(p2Phic -& pred, F)
    val d = fit(p2Phic -& prevPhic, F)
    theta := fit(pred +& shR(e, p.pllKp), F)
    vel := fit(vel +& shR(e, p.pllKv) +& shR(d -& vel, p.pllKf), F)
    prevPhic := p2Phic
    lockCnt := Mux(abs(e) < lit(1L << (F - p.lockShift), F + 1), Mux(lockCnt === lockMax.U, lockCnt, lockCnt + 1.U), 0.U)
    if (p.harmonicEntries > 0) {
      val enable = lockCnt === lockMax.U && abs(vel) >= lit(1L << (F - p.minSpeedShift), F + 1)
      when(enable) {
        val sh = p.interpBits + p.harmonicRate
        val j = p2Idx +% 1.U
        val leak = shR(tableSum, p.tableIndexBits + p.meanShift)
        val w0 = ((1 << p.interpBits).U -& p2Frac).zext
        val t0 = sat(table(p2Idx) +& shR(e * w0, sh) -& leak, p.tableBits)
        val t1 = sat(table(j) +& shR(e * p2Frac.zext, sh) -& leak, p.tableBits)
        tableSum := fit(tableSum +& (t0 -& table(p2Idx)) +& (t1 -& table(j)), tableSum.getWidth)
        table(p2Idx) := t0
        table(j) := t1
      }
    }
  }
}
