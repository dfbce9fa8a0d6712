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
  *
  * @param withReadBack adds `readBack` ([[AdaptReadBackIO]]): the learned state for a register file, each value a
  *                     registered copy, the table through copies of its banks with their own read port. Without it
  *                     (the datapath designs) the module is as before.
  */
class AdaptiveCorrector(val p: AdaptParams, withReadBack: Boolean = false) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new AdaptSample(p.inputBits)))
    val out = Valid(new AdaptSample(p.outputBits))
  })
  val readBack: Option[AdaptReadBackIO] = if (withReadBack) Some(IO(new AdaptReadBackIO(p))) else None
  /** With `withReadBack`: the preset port ([[AdaptPresetIO]]), to hold the loops and load learned values. */
  val preset: Option[AdaptPresetIO] = if (withReadBack) Some(IO(new AdaptPresetIO(p))) else None
  val latency: Int = p.latency

  private val F = p.fineBits
  private def shR(v: SInt, s: Int): SInt = FixedHw.shift(v, s, Rounding.HalfEven)
  private def sat(v: SInt, w: Int): SInt = FixedHw.saturate(v, w)
  private def fit(v: SInt, w: Int): SInt = if (v.getWidth >= w) v(w - 1, 0).asSInt else v.pad(w)
  /** A register of v's exact type (RegNext would forget the width). */
  private def reg[T <: Data](v: T): T = { val r = Reg(chiselTypeOf(v)); r := v; r }
  private def lit(v: Long, w: Int): SInt = v.S(w.W)

  /** v delayed by k clocks in registers of its exact type. */
  private def delay[T <: Data](v: T, k: Int): T = (0 until k).foldLeft(v)((x, _) => reg(x))
  private def valid(v: Bool): Bool = RegNext(v, false.B)

  // ---- preset port (with read-back): hold, and the load and table-write strobes, registered here ----
  private val hold: Option[Bool] = preset.map(x => valid(x.hold))
  private val load: Option[Bool] = preset.map(x => valid(x.load && x.hold))
  private val presetWrite: Option[Bool] = preset.map(x => valid(x.tableWrite && x.hold))
  /** v, and not held (v alone without the preset port). */
  private def running(v: Bool): Bool = hold.fold(v)(h => v && !h)

  // ---- input register ----
  private val inV = valid(io.in.valid)
  private val inS = reg(io.in.bits.sin)
  private val inC = reg(io.in.bits.cos)

  // ---- offset, gain and phase estimates ----
  private val os = RegInit(0.S(p.offsetWidth.W))
  private val oc = RegInit(0.S(p.offsetWidth.W))
  private val ks = RegInit(p.startGain.S(p.gainBits.W))
  private val kc = RegInit(p.startGain.S(p.gainBits.W))
  private val t = RegInit(0.S(p.phaseBits.W))

  // ---- correction in five clocks: sp = (s - os) ks, cp = (c - oc) kc + sp t ----
  /** x - offset (offsetFrac fractional bits) and that rounded to the multiplier operand. */
  private def offset(x: SInt, o: SInt): (SInt, SInt) = {
    val d = fit((x << p.offsetFrac).asSInt -& o, p.diffWidth)
    (d, fit(shR(d, p.offsetFrac - p.mulFrac), p.mulWidth))
  }
  private val (s1, sr) = offset(inS, os)
  private val (c1, cr) = offset(inC, oc)
  private val aV = valid(inV); private val aS1 = reg(s1); private val aC1 = reg(c1); private val aSr = reg(sr); private val aCr = reg(cr)
  private val bV = valid(aV); private val bMs = reg(aSr * ks); private val bMc = reg(aCr * kc)
  private val cV = valid(bV)
  private val cSp = reg(sat(shR(bMs, p.mulFrac + p.gainFrac), p.outputBits))
  private val cCa = reg(shR(bMc, p.mulFrac + p.gainFrac))
  private val dV = valid(cV); private val dPt = reg(cSp * t); private val dSp = reg(cSp); private val dCa = reg(cCa)
  private val hV = valid(dV)
  private val hSp = reg(dSp)
  private val hCp = reg(sat(dCa +& shR(dPt, p.phaseFrac), p.outputBits))
  private val hS1 = delay(aS1, p.correctionStages - 1)
  private val hC1 = delay(aC1, p.correctionStages - 1)

  // ---- per-window statistics of the corrected signals (products registered first) ----
  private val target = lit(1L << p.targetSquareLog2, 2 * p.outputBits)
  private val gV = valid(hV)
  private val gQ = reg(Mux(hSp >= 0.S, Mux(hCp >= 0.S, 0.U(2.W), 1.U), Mux(hCp < 0.S, 2.U, 3.U)))
  private val gDs = reg(target -& hSp * hSp)
  private val gDc = reg(target -& hCp * hCp)
  private val gXc = reg(hSp * hCp)
  private val gS1 = reg(hS1); private val gC1 = reg(hC1)
  private val aS = Reg(SInt(p.sumOffsetWidth.W)); private val aC = Reg(SInt(p.sumOffsetWidth.W))
  private val bS = Reg(SInt(p.sumSquareWidth.W)); private val bC = Reg(SInt(p.sumSquareWidth.W))
  private val cX = Reg(SInt(p.sumSquareWidth.W))
  private val n = RegInit(0.U(p.periodBits.W))
  private val prevQ = RegInit(0.U(2.W))
  private val seen = RegInit(0.U(4.W))
  private val start = gQ === 0.U && prevQ =/= 0.U
  private val whole = (seen & 0xE.U) === 0xE.U && n < p.countMax.U
  private val restart = start && !(whole && n < (1L << p.windowBits).U)
  when(running(gV)) {
    when(restart) {
      aS := fit(gS1, p.sumOffsetWidth); aC := fit(gC1, p.sumOffsetWidth)
      bS := fit(gDs, p.sumSquareWidth); bC := fit(gDc, p.sumSquareWidth); cX := fit(gXc, p.sumSquareWidth)
      n := 1.U; seen := 0.U
    }.elsewhen(n < p.countMax.U) {
      aS := fit(aS +& gS1, p.sumOffsetWidth); aC := fit(aC +& gC1, p.sumOffsetWidth)
      bS := fit(bS +& gDs, p.sumSquareWidth); bC := fit(bC +& gDc, p.sumSquareWidth); cX := fit(cX +& gXc, p.sumSquareWidth)
      n := n + 1.U
      seen := Mux(start, 0.U, seen) | UIntToOH(gQ, 4)
    }
    prevQ := gQ
  }
  // a closed window: snapshot of its sums, then the shifted steps, then the estimates move
  private val uV = valid(running(gV) && restart && whole)
  private val uL = reg(Log2(n) +& 1.U)
  private val uS = reg(aS); private val uC = reg(aC); private val uBs = reg(bS); private val uBc = reg(bC); private val uX = reg(cX)
  // w: the sums with half a step added (the rounding); v: shifted by the window's length and the rate
  private val wV = valid(uV); private val wL = reg(uL)
  private def up(v: SInt, k: Int): SInt = reg(v +& Cat(0.U(1.W), (1.U(1.W) << (uL + (k - 1).U)).asUInt).asSInt)
  private val wS = up(uS, p.offsetRate); private val wC = up(uC, p.offsetRate)
  private val wBs = up(uBs, p.gainRate + p.gainShift); private val wBc = up(uBc, p.gainRate + p.gainShift)
  private val wX = up(uX, p.phaseRate + p.phaseShift)
  private val vV = valid(wV)
  private val vOs = reg((wS >> (wL + p.offsetRate.U)).asSInt); private val vOc = reg((wC >> (wL + p.offsetRate.U)).asSInt)
  private val vKs = reg((wBs >> (wL + (p.gainRate + p.gainShift).U)).asSInt)
  private val vKc = reg((wBc >> (wL + (p.gainRate + p.gainShift).U)).asSInt)
  private val vT = reg((wX >> (wL + (p.phaseRate + p.phaseShift).U)).asSInt)
  when(running(vV)) {
    val gMax = lit((1L << (p.gainBits - 1)) - 1, p.gainBits)
    def gain(k: SInt, step: SInt): SInt = {
      val v = k +& step
      Mux(v < 1.S, 1.S(p.gainBits.W), Mux(v > gMax, gMax, fit(v, p.gainBits)))
    }
    os := sat(os +& vOs, p.offsetWidth)
    oc := sat(oc +& vOc, p.offsetWidth)
    ks := gain(ks, vKs)
    kc := gain(kc, vKc)
    t := sat(t -& vT, p.phaseBits)
  }
  for (x <- preset; ld <- load) when(ld) { os := x.offsetSin; oc := x.offsetCos; ks := x.gainSin; kc := x.gainCos; t := x.phase }

  // ---- vectoring CORDIC (reused), data delayed beside it ----
  private val cordic = Module(new Cordic(p.cordic))
  cordic.io.in.valid := hV
  cordic.io.in.bits.x := hCp
  cordic.io.in.bits.y := hSp
  cordic.io.in.bits.z := 0.S
  private val lc = p.cordic.latency
  private val phi = cordic.io.out.bits.z

  // ---- harmonic table: two banks (even, odd entries) in block RAM, read the clock the angle arrives ----
  private val entries = math.max(p.harmonicEntries, 1)
  private val ib = math.max(p.tableIndexBits, 1)
  private val tableSum = RegInit(0.S((p.tableBits + p.tableIndexBits).W))
  private val u = phi.asUInt
  private val aw = p.angleBits
  private val idx: UInt = if (p.harmonicEntries > 0) u(aw - 1, aw - p.tableIndexBits) else 0.U(ib.W)
  private val frac: UInt = u(aw - p.tableIndexBits - 1, aw - p.tableIndexBits - p.interpBits)
  private val q0V = valid(cordic.io.out.valid)
  private val q0Sp = delay(hSp, lc + 1); private val q0Cp = delay(hCp, lc + 1)
  private val q0Phi = reg(phi); private val q0Odd = reg(idx(0)); private val q0Frac = reg(frac)
  private val q0Mean = reg(shR(tableSum, p.tableIndexBits))
  private val dw = p.tableBits + 3
  /** q3: the interpolated table value less the table mean (fine angle). */
  private val tbl = if (p.harmonicEntries > 0) Some(new Table) else None
  private val q3Delta: SInt = tbl.map(_.delta).getOrElse(delay(0.S(dw.W), 3))

  // ---- q4: fine phase corrected by the table, rotation angle product ----
  private val q3Phi = delay(q0Phi, 3)
  private val q4V = delay(q0V, 4)
  private val q4Raw = reg(q3Delta * lit(p.twoPi, p.twoPiFrac + 4))
  private val q4Phic = reg(fit((q3Phi << p.fineGuard).asSInt -& q3Delta, F))
  // ---- q5: radians; q6: rotation products; q7 (output register): small rotation by -delta ----
  private val q5Dr = reg(sat(shR(q4Raw, p.twoPiFrac + F - p.rotFrac), p.rotWidth))
  private val q5Sp = delay(q0Sp, 5); private val q5Cp = delay(q0Cp, 5)
  private val q6RotS = reg(q5Dr * q5Cp); private val q6RotC = reg(q5Dr * q5Sp)
  private val q6Sp = reg(q5Sp); private val q6Cp = reg(q5Cp)
  private val outV = delay(q4V, 3)
  private val outSin = reg(sat(q6Sp -& shR(q6RotS, p.rotFrac), p.outputBits))
  private val outCos = reg(sat(q6Cp +& shR(q6RotC, p.rotFrac), p.outputBits))
  io.out.valid := outV
  io.out.bits.sin := outSin
  io.out.bits.cos := outCos
  // the over-range flags travel beside the data, unchanged
  io.out.bits.otrSin := ShiftRegister(io.in.bits.otrSin, latency)
  io.out.bits.otrCos := ShiftRegister(io.in.bits.otrCos, latency)

  // ---- PLL (smoothed phase) on q4's fine phase, the table's error signal ----
  // Each sample's errors are registered (eLast: phase, dvLast: increment less velocity), and theta, vel and the
  // lock counter move by the previous sample's: one carry-save layer and one adder per register (the model does the same).
  private val theta = RegInit(0.S(F.W))
  private val vel = RegInit(0.S(F.W))
  private val prevPhic = RegInit(0.S(F.W))
  private val eLast = RegInit(0.S(F.W))
  private val dvLast = RegInit(0.S(F.W))
  private val lockMax = (1L << p.lockBits) - 1
  private val lockCnt = RegInit(0.U(p.lockBits.W))
  when(running(q4V)) {
    eLast := PllMath.sub2(q4Phic, theta, vel, F)
    dvLast := PllMath.sub2(q4Phic, prevPhic, vel, F)
    theta := PllMath.add2ShR(theta, vel, eLast, p.pllKp, F)
    vel := PllMath.addShR2(vel, eLast, p.pllKv, dvLast, p.pllKf, F)
    prevPhic := q4Phic
    lockCnt := Mux(PllMath.absBelow(eLast, F - p.lockShift), Mux(lockCnt === lockMax.U, lockCnt, lockCnt + 1.U), 0.U)
  }
  private val q5E = eLast
  private val q5En = valid(running(q4V) && lockCnt === lockMax.U && !PllMath.absBelow(vel, F - p.minSpeedShift))
  tbl.foreach(_.update())
  for (x <- preset; ld <- load) when(ld) { tableSum := x.tableSum }

  // ---- read-back: registered copies (one more load on each register, no path back into the loops) ----
  readBack.foreach { rb =>
    val l = rb.learned
    l.offsetSin := reg(os); l.offsetCos := reg(oc); l.gainSin := reg(ks); l.gainCos := reg(kc); l.phase := reg(t)
    val updates = RegInit(0.U(32.W))
    when(running(vV) && updates =/= AdaptLearned.MaxUpdates.U) { updates := updates + 1.U }
    l.updates := updates
    l.locked := valid(lockCnt === lockMax.U)
    l.tableSum := reg(tableSum)
    l.tableData := tbl.map(_.readBack(rb.tableIndex)).getOrElse(0.S(p.tableBits.W))
  }

  /** The table: read (q0), interpolated (q1 to q3: `delta`), and updated by LMS at rmwStage
    * (`update`), forwarding the writes still in flight so that back-to-back updates of one entry add up exactly.
    */
  private class Table {
    val half = entries / 2
    val bw = ib - 1
    val banks = Seq.fill(2)(SyncReadMem(half, SInt(p.tableBits.W)))
    val written = Seq.fill(2)(RegInit(0.U(half.W)))
    private val next = idx +% 1.U
    moire.emit.Unused("next_index_lsb", next(0)) // the even bank is addressed by (idx + 1) / 2
    val rAddr = Seq(next(bw, 1), idx(bw, 1)) // even bank, odd bank
    // the write port: registered read-modify-write results (w), written one clock after the RMW
    val wV = RegInit(false.B)
    val wAddr = Seq.fill(2)(Reg(UInt(bw.W)))
    val wData = Seq.fill(2)(Reg(SInt(p.tableBits.W)))
    val wOld = Seq.fill(2)(Reg(SInt(p.tableBits.W)))
    val read = banks.indices.map { b =>
      val hit = valid(wV && wAddr(b) === rAddr(b))
      val known = reg(VecInit(written(b).asBools)(rAddr(b)))
      val data = banks(b).read(rAddr(b))
      when(wV) { banks(b).write(wAddr(b), wData(b)); written(b) := written(b) | UIntToOH(wAddr(b), half) }
      Mux(hit, reg(wData(b)), Mux(known, data, 0.S))
    }
    val q0R = rAddr.map(reg(_))
    // q1: entries idx (a) and idx + 1 (b) from the two banks
    val odd = q0Odd
    val a = Mux(odd, read(1), read(0))
    val b = Mux(odd, read(0), read(1))
    val q1A = reg(a); val q1Diff = reg(b -& a); val q1Frac = reg(q0Frac); val q1Mean = reg(q0Mean)
    val q1Read = read.map(reg(_))
    // q2: interpolation product; q3: delta
    val q2Prod = reg(q1Diff * q1Frac.zext); val q2A = reg(q1A); val q2Mean = reg(q1Mean)
    val delta: SInt = reg(fit(q2A +& shR(q2Prod, p.interpBits) -& q2Mean, dw))

    /** The entry at `index` as the read-back sees it: copies of both banks, written from registered copies of their
      * write port (a clock after the banks: the read-modify-write loop's registers get one load more, no more), read by
      * their own port; the words, `written` bit and bank select registered; the selected word registered again. Three
      * clocks from `index` to the word (an entry's first write shows a clock late); nothing here feeds the table's read or update.
      */
    def readBack(index: UInt): SInt = {
      val ra = index(bw, 1)
      val cV = valid(wV)
      val words = banks.indices.map { b =>
        val copy = SyncReadMem(half, SInt(p.tableBits.W))
        val (cAddr, cData) = (reg(wAddr(b)), reg(wData(b)))
        when(cV) { copy.write(cAddr, cData) }
        val word = reg(copy.read(ra))
        val known = delay(VecInit(written(b).asBools)(ra), 2)
        Mux(known, word, 0.S)
      }
      reg(Mux(delay(index(0), 2), words(1), words(0)))
    }

    def update(): Unit = {
      // q6: LMS products; q7: their rounded steps, the leak, and the youngest in-flight write of each entry
      val q5Odd = delay(q0Odd, 5); val q5Frac = delay(q0Frac, 5)
      val sh = p.interpBits + p.harmonicRate
      val q6P0 = reg(q5E * ((1 << p.interpBits).U -& q5Frac).zext); val q6P1 = reg(q5E * q5Frac.zext)
      val q6En = valid(q5En); val q6Odd = reg(q5Odd)
      val q6R = q0R.map(delay(_, 6)); val q6Read = q1Read.map(delay(_, 5))
      // writes not in the value read at q0: those of the rmwStage clocks since; q7 looks at all but the last
      val hist = (0 until p.rmwStage - 2).scanLeft((wV, wAddr, wData)) { case ((v, ad, da), _) =>
        (valid(v), ad.map(reg(_)), da.map(reg(_))) }
      val cand = banks.indices.map { b =>
        hist.foldRight(q6Read(b)) { case ((v, ad, da), older) => Mux(v && ad(b) === q6R(b), da(b), older) } }
      val q7V = valid(q6En)
      // each bank's step (entry idx, weight 1 - f, is in the odd bank when idx is odd) and the leak
      val inc = Seq(shR(q6P0, sh), shR(q6P1, sh))
      val q7Inc = banks.indices.map(b => reg(Mux(q6Odd, inc(1 - b), inc(b))))
      val q7Leak = reg(shR(tableSum, p.tableIndexBits + p.meanShift))
      val q7Cand = cand.map(reg(_)); val q7R = q6R.map(reg(_))
      // the write now at q7 is in the write port when this sample reaches q7: its address compared a clock early
      val q7Hit = banks.indices.map(b => valid(q7V && q7R(b) === q6R(b)))
      // q8: read-modify-write of entries idx and idx + 1 (one in each bank)
      val old = banks.indices.map(b => Mux(q7Hit(b), wData(b), q7Cand(b)))
      val t = banks.indices.map(b => PllMath.saturate(PllMath.addSub(old(b), q7Inc(b), q7Leak), p.tableBits))
      wV := q7V
      when(q7V) {
        for (bk <- banks.indices) { wAddr(bk) := q7R(bk); wOld(bk) := old(bk); wData(bk) := t(bk) }
      }
      when(wV) { tableSum := fit(tableSum +& (wData(0) -& wOld(0)) +& (wData(1) -& wOld(1)), tableSum.getWidth) }
      // the preset pair: one more registered source of the write port (its sum unchanged: the load sets the sum)
      for (x <- preset; pw <- presetWrite) {
        wV := q7V || pw
        when(pw) {
          for ((bk, v) <- banks.indices.zip(Seq(x.even, x.odd))) { wAddr(bk) := x.pair(bw - 1, 0); wOld(bk) := v; wData(bk) := v }
        }
      }
    }
  }
}
