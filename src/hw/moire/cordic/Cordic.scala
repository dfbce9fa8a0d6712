package moire.cordic

import chisel3._
import chisel3.util._
import moire.emit.Unused
import CordicMode._

class CordicIn(p: CordicParams) extends Bundle {
  /** x of the vector (rotate, atan2); data format. */
  val x = SInt(p.width.W)
  /** y of the vector (rotate, atan2), or the sine value (asin, acos); data format. */
  val y = SInt(p.width.W)
  /** Angle to rotate by (sincos, rotate); binary angle. */
  val z = SInt(p.angleBits.W)
}

class CordicOut(p: CordicParams) extends Bundle {
  /** cos or rotated x (sincos, rotate), magnitude (atan2); `outWidth` bits, data fraction. */
  val x = SInt(p.outWidth.W)
  /** sin or rotated y (sincos, rotate). */
  val y = SInt(p.outWidth.W)
  /** atan2, asin or acos; binary angle. */
  val z = SInt(p.angleBits.W)
}

/** Pipelined CORDIC for every mode of [[CordicMode]]; one result per clock, `latency` clocks after
  * the input. Bit-exact with [[CordicModel]]; number formats in [[CordicParams]].
  */
class Cordic(val p: CordicParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val in = Flipped(Valid(new CordicIn(p)))
    val out = Valid(new CordicOut(p))
  })
  val latency: Int = p.latency

  private val w = p.innerWidth
  private val zw = p.zWidth
  private val r = p.rounding
  private val isAsin = p.mode.isAsin

  private def fit(v: SInt, width: Int): SInt =
    if (v.getWidth >= width) v(width - 1, 0).asSInt else v.pad(width)
  private def sh(v: SInt, s: Int): SInt = fit(FixedHw.shift(v, s, r), w)
  private def lit(v: Long, width: Int): SInt = v.S(width.W)
  /** v * 2^g as a w-bit word. */
  private def lsh(v: SInt, g: Int): SInt = fit(if (g == 0) v else Cat(v, 0.U(g.W)).asSInt, w)

  /** Iteration state: vector, angle and (arcsine) the target. */
  private class State extends Bundle {
    val x = SInt(w.W)
    val y = SInt(w.W)
    val z = SInt(zw.W)
    val t = SInt(w.W)
  }

  if (p.taper) CordicTaper.build(p, io.in, io.out) else conventional()

  /** The datapath as the papers draw it: pre-rotation register, one register group per k iterations, output. */
  private def conventional(): Unit = {
    // ---- input stage: coarse pre-rotation / start vector ----
    val s0 = Wire(new State)
    val inX = io.in.bits.x
    val inY = io.in.bits.y
    val inZ = io.in.bits.z
    p.mode match { // the ports a mode does not read
      case SinCos => Unused("in_xy", inX, inY)
      case Rotate =>
      case Atan2 => Unused("in_z", inZ)
      case _ => Unused("in_xz", inX, inZ)
    }
    /** The arcsine input clamped to [-1.0, 1.0], one bit wider than the port. */
    lazy val sineIn: SInt = {
      val oneIn = 1L << p.dataFrac
      Mux(inY > lit(oneIn, p.width + 1), lit(oneIn, p.width + 1),
        Mux(inY < lit(-oneIn, p.width + 1), lit(-oneIn, p.width + 1), inY.pad(p.width + 1)))
    }
    s0.t := 0.S
    p.mode match {
      case SinCos | Rotate =>
        val quarter = 1L << (p.angleBits - 2)
        val fold = inZ >= lit(quarter, p.angleBits + 1) || inZ < lit(-quarter, p.angleBits + 1)
        val folded = Cat(~inZ(p.angleBits - 1), inZ(p.angleBits - 2, 0)).asSInt
        val a = Mux(fold, folded, inZ)
        s0.z := (if (p.zGuard == 0) a else Cat(a, 0.U(p.zGuard.W)).asSInt)
        val (x0, y0) =
          if (p.mode == SinCos) (lit(p.startX, w), 0.S(w.W))
          else (lsh(inX, p.guardBits), lsh(inY, p.guardBits))
        s0.x := Mux(fold, fit(-x0, w), x0)
        s0.y := Mux(fold, fit(-y0, w), y0)
      case Atan2 =>
        val xi = lsh(inX, p.guardBits)
        val yi = lsh(inY, p.guardBits)
        val fold = xi < 0.S
        s0.x := Mux(fold, fit(-xi, w), xi)
        s0.y := Mux(fold, fit(-yi, w), yi)
        s0.z := Mux(fold, lit(-(1L << (zw - 1)), zw), 0.S(zw.W))
      case _ =>
        val a = sineIn
        s0.t := lsh(a, p.guardBits)
        if (p.isDouble) {
          val pos = a >= 0.S
          s0.x := 0.S
          s0.y := Mux(pos, lit(1L << p.innerFrac, w), lit(-(1L << p.innerFrac), w))
          s0.z := Mux(pos, lit(1L << (zw - 2), zw), lit(-(1L << (zw - 2)), zw))
        } else {
          s0.x := lit(p.startX, w)
          s0.y := 0.S
          s0.z := 0.S
        }
    }

    // Peak lookup table: hit, sign and entry index resolved in the input stage and registered; the entry read in
    // the next stage (a ROM of its final values for either sign, no adder after the read), then carried beside the
    // iterations.
    val table: Option[(Bool, Bool, UInt)] = if (p.peakTableSize > 0) {
      val pt = PeakTable(p)
      val a = sineIn
      val mag = Mux(a < 0.S, -a, a)
      val hit = mag >= lit(pt.start, p.width + 2)
      val offset = (mag - lit(pt.start, p.width + 2)).asUInt
      Unused("lut_offset", offset) // the bits below an entry's bin pick nothing; `hit` covers those above
      val idx = if (pt.size == 1) 0.U(1.W) else (offset >> pt.binShift)(log2Ceil(pt.size) - 1, 0)
      Some((hit, a < 0.S, idx))
    } else None
    /** The table's angle for a registered sign and index: entry e as e or -e, and for arccos 90 degrees minus that. */
    def tableAngle(neg: Bool, idx: UInt): SInt = {
      val pt = PeakTable(p)
      val quarter = 1L << (p.angleBits - 2)
      def angle(e: Long): Long = if (p.mode.isAcos) quarter - e else e
      // z keeps angleBits: 180 degrees wraps to -180 here as it does at the output
      val (turn, half) = (1L << p.angleBits, 1L << (p.angleBits - 1))
      def wrap(v: Long): Long = Math.floorMod(v + half, turn) - half
      def rom(sign: Long) = VecInit(pt.entries.map(e => lit(wrap(angle(sign * e)), p.angleBits)))
      val (pos, negs) = (rom(1), rom(-1))
      if (pt.size == 1) Mux(neg, negs(0), pos(0)) else Mux(neg, negs(idx), pos(idx))
    }

    def stage[T <: Data](v: T, name: String): T = { val reg = Reg(chiselTypeOf(v)); reg := v; reg.suggestName(name); reg }

    // ---- iterations ----
    def step(s: State, i: Int, k: Long): State = {
      val n = Wire(new State)
      val kz = lit(k, zw)
      n.t := s.t
      p.mode match {
        case SinCos | Rotate =>
          val up = s.z >= 0.S
          val sx = sh(s.x, i); val sy = sh(s.y, i)
          n.x := Mux(up, s.x - sy, s.x + sy)
          n.y := Mux(up, s.y + sx, s.y - sx)
          n.z := Mux(up, s.z - kz, s.z + kz)
        case Atan2 =>
          val down = s.y >= 0.S
          val sx = sh(s.x, i); val sy = sh(s.y, i)
          n.x := Mux(down, s.x + sy, s.x - sy)
          n.y := Mux(down, s.y - sx, s.y + sx)
          n.z := Mux(down, s.z + kz, s.z - kz)
        case _ if p.isDouble =>
          val ccw = Mux(s.x < 0.S, s.y < 0.S, s.y <= s.t)
          val sx2 = sh(s.x, 2 * i); val sy2 = sh(s.y, 2 * i)
          val sx1 = sh(s.x, i - 1); val sy1 = sh(s.y, i - 1)
          n.x := Mux(ccw, s.x - sx2 - sy1, s.x - sx2 + sy1)
          n.y := Mux(ccw, s.y - sy2 + sx1, s.y - sy2 - sx1)
          n.z := Mux(ccw, s.z + kz, s.z - kz)
          n.t := s.t + sh(s.t, 2 * i)
        case _ =>
          val ccw = s.t >= s.y
          val sx = sh(s.x, i); val sy = sh(s.y, i)
          n.x := Mux(ccw, s.x - sy, s.x + sy)
          n.y := Mux(ccw, s.y + sx, s.y - sx)
          n.z := Mux(ccw, s.z + kz, s.z - kz)
      }
      n
    }

    var state: State = stage(s0, "pre")
    var tableState = table.map { case (h, n, i) => (stage(h, "lut_hit_0"), tableAngle(stage(n, "lut_neg_0"), stage(i, "lut_idx_0"))) }
    for (((i, k), idx) <- p.steps.zip(p.angleTable).zipWithIndex) {
      val next = step(state, i, k)
      if ((idx + 1) % p.pipelineEvery == 0 || idx == p.iterations - 1) {
        state = stage(next, s"iter_$i")
        tableState = tableState.map { case (h, v) => (stage(h, s"lut_hit_$i"), stage(v, s"lut_val_$i")) }
      } else state = next
    }

    // ---- output stage ----
    def outData(v: SInt): SInt = {
      val scaled =
        if (p.postScale) FixedHw.shift(stage(v * lit(p.invGainConst, p.kFrac + 2), "scaled"), p.kFrac + p.guardBits, r)
        else FixedHw.shift(v, p.guardBits, r)
      FixedHw.saturate(scaled, p.outWidth)
    }
    def outAngle(z: SInt): SInt = fit(FixedHw.shift(z, p.zGuard, r), p.angleBits)

    val result = Wire(new CordicOut(p))
    result.x := 0.S
    result.y := 0.S
    result.z := 0.S
    p.mode match {
      case SinCos | Rotate =>
        result.x := outData(state.x)
        result.y := outData(state.y)
      case Atan2 =>
        result.x := outData(state.x)
        result.z := outAngle(if (p.postScale) stage(state.z, "z_scaled") else state.z)
      case _ =>
        val z = if (p.mode.isAcos) lit(1L << (zw - 2), zw) - state.z else state.z
        if (p.mode.isAcos) Unused("acos_z", z) // outAngle keeps the angle word: truncation drops the guard bits
        val cordicAngle = outAngle(z)
        result.z := (tableState match {
          case Some((hit, v)) => Mux(hit, v, cordicAngle)
          case None => cordicAngle
        })
    }
    io.out.bits := stage(result, "out")
    io.out.valid := ShiftRegister(io.in.valid, latency, false.B, true.B)
  }
}

/** Hardware twins of [[Fixed]]'s integer helpers. */
object FixedHw {
  /** v / 2^s, floor or round half to even; the result is one bit wider than v >> s. */
  def shift(v: SInt, s: Int, r: Rounding): SInt =
    if (s <= 0) v
    else {
      val vp = if (v.getWidth < s + 1) v.pad(s + 1) else v
      val q = (vp >> s).asSInt
      r match {
        case Rounding.Truncate => q
        case Rounding.HalfEven =>
          val rem = vp(s - 1, 0)
          val half = (BigInt(1) << (s - 1)).U(s.W)
          val up = rem > half || (rem === half && q(0))
          q +& Mux(up, 1.S(2.W), 0.S(2.W))
      }
    }

  def saturate(v: SInt, width: Int): SInt = {
    if (v.getWidth <= width) v.pad(width)
    else {
      val hi = ((BigInt(1) << (width - 1)) - 1).S(v.getWidth.W)
      val lo = (-(BigInt(1) << (width - 1))).S(v.getWidth.W)
      Mux(v > hi, hi, Mux(v < lo, lo, v))(width - 1, 0).asSInt
    }
  }
}
