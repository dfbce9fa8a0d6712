package moire.adapt

import chisel3._
import chisel3.util.{Cat, Fill}
import moire.emit.Unused

/** Short-path arithmetic for loops that close in one clock, all modulo 2^w (two's complement words of w bits).
  * Each sum is one carry-save layer and one adder; a rounding's +1 goes into the carry word's free bit 0 or
  * into the adder's carry-in, so no adder waits for another.
  */
object PllMath {
  /** a - b - c modulo 2^w (-x = ~x + 1, the two ones in bit 0 of the carry word and as the carry-in). */
  def sub2(a: SInt, b: SInt, c: SInt, w: Int): SInt = csa(word(a, w), inv(b, w), inv(c, w), true.B, true.B, w)

  /** a + b - c exactly (two bits wider than the widest). */
  def addSub(a: SInt, b: SInt, c: SInt): SInt = {
    val w = Seq(a, b, c).map(_.getWidth).max + 2
    csa(word(a, w), word(b, w), inv(c, w), false.B, true.B, w)
  }

  /** a + b + v / 2^s (rounded half to even) modulo 2^w. */
  def add2ShR(a: SInt, b: SInt, v: SInt, s: Int, w: Int): SInt = {
    val (q, up) = shR(v, s, w)
    csa(word(a, w), word(b, w), q, up, false.B, w)
  }

  /** a + v1 / 2^s1 + v2 / 2^s2 (each rounded half to even) modulo 2^w. */
  def addShR2(a: SInt, v1: SInt, s1: Int, v2: SInt, s2: Int, w: Int): SInt = {
    val (q1, up1) = shR(v1, s1, w)
    val (q2, up2) = shR(v2, s2, w)
    csa(word(a, w), q1, q2, up1, up2, w)
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

  /** |v| < 2^k for a w-bit v: the bits above k - 1 all equal, and v is not -2^k. */
  def absBelow(v: SInt, k: Int): Bool = {
    require(k >= 1 && k < v.getWidth)
    val hi = v(v.getWidth - 1, k)
    !hi.orR || (hi.andR && v(k - 1, 0).orR)
  }

  /** v / 2^s rounded half to even, as v >> s in w bits and the rounding's +1. */
  private def shR(v: SInt, s: Int, w: Int): (UInt, Bool) = {
    require(s >= 1)
    val x = if (v.getWidth < s + 1) v.pad(s + 1) else v
    val rest = if (s >= 2) x(s - 2, 0).orR else false.B
    (word((x >> s).asSInt, w), x(s - 1) && (rest || x(s)))
  }

  /** x + y + z + c0 + c1 modulo 2^w: a carry-save layer (c0 in the carry word's bit 0), then one adder
    * (c1 as its carry-in: bit 0 of the sum only carries it).
    */
  private def csa(x: UInt, y: UInt, z: UInt, c0: Bool, c1: Bool, w: Int): SInt = {
    val s = x ^ y ^ z
    val cy = if (w >= 2) Cat(((x & y) | (x & z) | (y & z))(w - 2, 0), c0) else c0.asUInt
    val sum = Cat(s, 1.U(1.W)) +% Cat(cy, c1)
    Unused("carry_in", sum(0))
    sum(w, 1).asSInt
  }

  private def word(v: SInt, w: Int): UInt = { val u = v.pad(w).asUInt; u(w - 1, 0) }
  private def inv(v: SInt, w: Int): UInt = (~word(v, w))(w - 1, 0)
}
