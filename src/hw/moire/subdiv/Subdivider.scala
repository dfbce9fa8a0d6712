package moire.subdiv

import chisel3._
import chisel3.util._
import moire.cordic.{Cordic, FixedHw}

/** One sample of the two channels: signed ADC values and the ADC over-range flags. */
class SubdivIn(p: SubdivParams) extends Bundle {
  val sin = SInt(p.inputBits.W)
  val cos = SInt(p.inputBits.W)
  val otrSin = Bool()
  val otrCos = Bool()
}

/** One result (formats in [[SubdivParams]]). While the signal is absent the position holds. */
class SubdivOut(p: SubdivParams) extends Bundle {
  /** periods * M + m. */
  val position = SInt(p.positionWidth.W)
  val periods = SInt(p.periodBits.W)
  val m = UInt(p.countBits.W)
  /** Phase of this sample, one turn = 2^phaseBits (raw, also while the signal is absent). */
  val phase = UInt(p.angleBits.W)
  /** sqrt(sin^2 + cos^2) >= presentThreshold. */
  val present = Bool()
  /** Either ADC flagged over-range on this sample. */
  val overRange = Bool()
  /** The phase moved more than maxStepTurns since the last present sample: the count may be wrong. */
  val stepFault = Bool()
}

/** Sticky flags (cleared by clearStatus) and the A/B output backlog. */
class SubdivStatus(p: SubdivParams) extends Bundle {
  /** position minus the count the A/B output shows (signed; 0 until the first result). */
  val backlog = SInt(p.positionWidth.W)
  /** The backlog exceeded backlogLimit: the A/B output lags (no count is dropped). */
  val overspeed = Bool()
  val stepFault = Bool()
  val signalLost = Bool()
  val overRange = Bool()
}

/** Digital subdivider: two ADC channels -> phase (CORDIC atan2 or double-rotation arcsine) ->
  * period counter -> position = periods * M + m, plus an incremental A/B/Z output.
  *
  * One sample per clock, never stalls; `latency` clocks from in.valid to out.valid.
  * A/B: quadrature (Gray) code of the output count, which steps by one towards the position at
  * most once every minEdgeClocks clocks; Z is high while that count is 0 modulo M.
  * Bit- and clock-exact with [[SubdivModel]].
  */
class Subdivider(val p: SubdivParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new SubdivIn(p)))
    val out = Valid(new SubdivOut(p))
    val a = Output(Bool())
    val b = Output(Bool())
    val z = Output(Bool())
    val status = Output(new SubdivStatus(p))
    val clearStatus = Input(Bool())
  })
  val latency: Int = p.latency
  private val pb = p.angleBits
  private val ib = p.inputBits

  // ---- stage 1: input register (scaling, octant choice, the squares of the signal-present test) ----
  private val sn = io.in.bits.sin
  private val cs = io.in.bits.cos
  private val sqS1 = RegNext((sn * sn).asUInt)
  private val sqC1 = RegNext((cs * cs).asUInt)
  private val otr1 = RegNext(io.in.bits.otrSin || io.in.bits.otrCos)
  private val valid1 = RegNext(io.in.valid, false.B)
  private val x1 = Reg(SInt(p.width.W)).suggestName("cordic_x")
  private val y1 = Reg(SInt(p.width.W)).suggestName("cordic_y")
  private val useSin1 = Reg(Bool())
  private val sNeg1 = RegNext(sn < 0.S)
  private val cNeg1 = RegNext(cs < 0.S)
  private def up(v: SInt): SInt = (if (p.inputShift == 0) v else Cat(v, 0.U(p.inputShift.W)).asSInt).pad(p.width)
  if (!p.isAsin) {
    x1 := up(cs); y1 := up(sn); useSin1 := false.B
  } else {
    val absS = Mux(sn < 0.S, -sn.pad(ib + 1), sn.pad(ib + 1))
    val absC = Mux(cs < 0.S, -cs.pad(ib + 1), cs.pad(ib + 1))
    val useSin = absS <= absC
    val sel = Mux(useSin, sn, cs)
    val prod = sel * p.kConst.S((p.kFrac + 4).W)
    x1 := 0.S
    y1 := FixedHw.saturate(FixedHw.shift(prod, p.kShift, p.rounding), p.width)
    useSin1 := useSin
  }

  // ---- CORDIC ----
  private val cordic = Module(new Cordic(p.cordic))
  cordic.io.in.valid := valid1
  cordic.io.in.bits.x := x1
  cordic.io.in.bits.y := y1
  cordic.io.in.bits.z := 0.S
  private val lc = cordic.latency
  require(lc >= 1, "the signal-present test takes a clock of the CORDIC's latency")
  // the amplitude compare in the first CORDIC clock, then delayed beside the CORDIC
  private val present2d = ShiftRegister(RegNext(sqS1 +& sqC1 >= p.presentSq.U), lc - 1)
  private val otr2d = ShiftRegister(otr1, lc)
  private val useSin2d = ShiftRegister(useSin1, lc)
  private val sNeg2d = ShiftRegister(sNeg1, lc)
  private val cNeg2d = ShiftRegister(cNeg1, lc)

  // ---- stage 2: phase from the CORDIC angle (octant mapping for the arcsine) ----
  private val z = cordic.io.out.bits.z
  private def lit(v: Long): SInt = v.S((pb + 1).W)
  private val phaseFull: SInt =
    if (!p.isAsin) z
    else Mux(useSin2d, Mux(cNeg2d, lit(1L << (pb - 1)) - z, z.pad(pb + 1)),
      Mux(sNeg2d, z -& lit(1L << (pb - 2)), lit(1L << (pb - 2)) - z))
  private val u2 = RegNext(phaseFull(pb - 1, 0)).suggestName("phase")
  private val present2 = RegNext(present2d)
  private val otr2 = RegNext(otr2d)
  private val valid2 = RegNext(cordic.io.out.valid, false.B)

  // ---- stage 3: period counter and output register ----
  private val started = RegInit(false.B)
  private val prevU = RegInit(0.U(pb.W))
  private val periods = RegInit(0.S(p.periodBits.W))
  private val d = (u2 - prevU)(pb - 1, 0).asSInt
  private val absD = Mux(d < 0.S, -d.pad(pb + 1), d.pad(pb + 1)).asUInt
  private val fwd = started && d > 0.S && u2 < prevU
  private val bwd = started && d < 0.S && u2 > prevU
  private val update = valid2 && present2
  private val nPeriods = Mux(started, periods + Mux(fwd, 1.S, Mux(bwd, -1.S, 0.S)), 0.S)(p.periodBits - 1, 0).asSInt
  private val nStarted = started || update
  private val curPeriods = Mux(update, nPeriods, periods)
  private val curU = Mux(update, u2, prevU)
  when(update) { started := true.B; prevU := u2; periods := nPeriods }

  private val out = Reg(new SubdivOut(p))
  private val outValid = RegNext(valid2, false.B)
  private val m = curU(pb - 1, pb - p.countBits)
  when(valid2) {
    out.periods := curPeriods
    out.m := m
    out.position := Cat(curPeriods, m).asSInt
    out.phase := u2
    out.present := present2
    out.overRange := otr2
    out.stepFault := update && started && absD > p.stepLimit.U
  }
  io.out.valid := outValid
  io.out.bits := out

  // ---- A/B/Z generator and sticky flags ----
  private val genStarted = RegInit(false.B)
  private val outPos = RegInit(0.S(p.positionWidth.W))
  // outPos + 1 and outPos - 1, kept beside it so that a step is a choice, not an add after the compare
  private val outPosUp = RegInit(1.S(p.positionWidth.W))
  private val outPosDn = RegInit(-1.S(p.positionWidth.W))
  private def wrapPos(v: SInt): SInt = v(p.positionWidth - 1, 0).asSInt
  private val waitW = log2Ceil(p.minEdgeClocks + 1)
  private val waitCnt = RegInit(0.U(waitW.W))
  private val pending = (out.position - outPos)(p.positionWidth - 1, 0).asSInt
  when(!genStarted) {
    when(outValid) {
      outPos := out.position; genStarted := true.B
      outPosUp := wrapPos(out.position + 1.S); outPosDn := wrapPos(out.position - 1.S)
    }
  }.elsewhen(waitCnt === 0.U && out.position =/= outPos) { // pending =/= 0 as an equality, beside the subtract
    val up = !pending(p.positionWidth - 1) // pending > 0 here: its sign bit alone
    outPos := Mux(up, outPosUp, outPosDn)
    outPosUp := Mux(up, wrapPos(outPosUp + 1.S), outPos)
    outPosDn := Mux(up, outPos, wrapPos(outPosDn - 1.S))
    waitCnt := (p.minEdgeClocks - 1).U
  }.elsewhen(waitCnt =/= 0.U) {
    waitCnt := waitCnt - 1.U
  }
  private def sticky(event: Bool): Bool = {
    val r = RegInit(false.B)
    r := (r && !io.clearStatus) || event
    r
  }
  // |pending| > limit as two compares of pending (no negation in the path)
  private val w1 = p.positionWidth + 1
  io.status.overspeed := sticky(genStarted && (pending > p.backlogLimit.S(w1.W) || pending < (-p.backlogLimit).S(w1.W)))
  io.status.stepFault := sticky(outValid && out.stepFault)
  io.status.signalLost := sticky(outValid && !out.present)
  io.status.overRange := sticky(outValid && out.overRange)
  io.status.backlog := Mux(genStarted, pending, 0.S)
  private val q = outPos(1, 0)
  io.a := q === 1.U || q === 2.U
  io.b := q(1)
  io.z := genStarted && outPos(p.countBits - 1, 0) === 0.U
}
