package moire.adapt

import chisel3._
import chisel3.util.{Cat, Fill}
import moire.emit.Unused

/** Short-path arithmetic for a loop that closes in one clock, all modulo 2^w (two's complement words of w bits). */
object PllMath {
  /** a - b - c: a carry-save layer, then one adder (-x = ~x + 1, the two ones enter as carry-ins). */
  def sub2(a: SInt, b: SInt, c: SInt, w: Int): SInt = {
    val (x, y, z) = (a.asUInt.pad(w)(w - 1, 0), (~b.asUInt.pad(w))(w - 1, 0), (~c.asUInt.pad(w))(w - 1, 0))
    val s = x ^ y ^ z
    val cy = Cat(((x & y) | (x & z) | (y & z))(w - 2, 0), 1.U(1.W))
    carryIn(Cat(s, 1.U(1.W)) +% Cat(cy, 1.U(1.W)), w)
  }

  /** a + b - c exactly (two bits wider than the widest): a carry-save layer, then one adder. */
  def addSub(a: SInt, b: SInt, c: SInt): SInt = {
    val w = Seq(a, b, c).map(_.getWidth).max + 2
    val (x, y, z) = (a.pad(w).asUInt, b.pad(w).asUInt, (~c.pad(w).asUInt)(w - 1, 0))
    val s = x ^ y ^ z
    val cy = Cat(((x & y) | (x & z) | (y & z))(w - 2, 0), 0.U(1.W))
    carryIn(Cat(s, 1.U(1.W)) +% Cat(cy, 1.U(1.W)), w)
  }

  /** v limited to w bits: the bits above w - 1 equal to the sign where it fits (no comparator). */
  def saturate(v: SInt, w: Int): SInt =
    if (v.getWidth <= w) v.pad(w)
    else {
      val top = v(v.getWidth - 1, w - 1)
      val fits = top.andR || !top.orR
      val neg = v(v.getWidth - 1)
      Mux(fits, v(w - 1, 0), Cat(neg, Fill(w - 1, !neg))).asSInt
    }

  /** a + v / 2^s rounded half to even, with the rounding's +1 as the adder's carry-in. */
  def addShR(a: SInt, v: SInt, s: Int, w: Int): SInt = {
    require(s >= 1)
    val x = if (v.getWidth < s + 1) v.pad(s + 1) else v
    val q = (x >> s).asSInt.pad(w)(w - 1, 0)
    val rest = if (s >= 2) x(s - 2, 0).orR else false.B
    val up = x(s - 1) && (rest || x(s))
    carryIn(Cat(a.asUInt.pad(w)(w - 1, 0), 1.U(1.W)) +% Cat(q, up), w)
  }

  /** The w bits above bit 0 of a sum whose bit 0 only carried the carry-in. */
  private def carryIn(sum: UInt, w: Int): SInt = {
    Unused("carry_in", sum(0))
    sum(w, 1).asSInt
  }

  /** |v| < 2^k for a w-bit v: the bits above k - 1 all equal, and v is not -2^k. */
  def absBelow(v: SInt, k: Int): Bool = {
    require(k >= 1 && k < v.getWidth)
    val hi = v(v.getWidth - 1, k)
    !hi.orR || (hi.andR && v(k - 1, 0).orR)
  }
}
