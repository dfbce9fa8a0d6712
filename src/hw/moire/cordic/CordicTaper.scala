package moire.cordic

import chisel3._
import chisel3.util._
import moire.emit.Unused

/** The tapered sincos datapath of [[Cordic]] (`CordicParams.taper`). The arithmetic is the
  * conventional one, so the results equal those without taper bit for bit; only the hardware is leaner:
  *  - fold and iterations 0 and 1 are bit logic on the angle word (z after iteration 0 is the
  *    angle's low bits with one bit inverted; the first two directions are angle bits);
  *  - x, y of the first `taperTable` iterations come from a constant table indexed by those
  *    iterations' directions (the table is the model's own iterations); the quadrant fold, which
  *    negates the vector, is applied by the output rounding adder (round half to even) or is one
  *    more table address bit (truncation, which is not odd-symmetric);
  *  - x, y carry sign + one integer bit + fraction (|(x, y)| <= K < 2);
  *  - z after iteration i is only as wide as its proven interval `zRanges(i)`; z after the last
  *    iteration, which no output needs, is not built;
  *  - each iteration is one adder per word: the direction complements the operand and the rounding
  *    of the shifted operand enters as the carry in;
  *  - the output is rounded but not saturated (it cannot exceed the word when there is an integer bit).
  * Latency: `iterations` clocks (stages 1 .. n-1, then the output register).
  */
private[cordic] object CordicTaper {
  def build(p: CordicParams, in: Valid[CordicIn], out: Valid[CordicOut]): Unit = {
    val n = p.iterations
    val m = p.taperTable
    val w = p.innerWidth
    val ab = p.angleBits
    val table = new CordicModel(p).taperTable
    require(m >= 2, s"taper table depth must be at least 2, got $m")

    def reg[T <: Data](v: T, name: String): T = { val r = Reg(chiselTypeOf(v)); r := v; r.suggestName(name); r }

    // Fold and iterations 0, 1 on the angle bits (see CordicModel.rotation for the arithmetic).
    val a = in.bits.z.asUInt
    Unused("in_xy", in.bits.x, in.bits.y) // sincos reads only the angle
    val fold = a(ab - 1) ^ a(ab - 2)
    val low = Cat(~a(ab - 3), a(ab - 4, 0))
    val z1 = (if (p.zGuard == 0) low else Cat(low, 0.U(p.zGuard.W))).asSInt // z after iteration 0, zWidth - 2 bits

    var z: SInt = z1
    var folded: Bool = fold
    var ups: Seq[Bool] = Seq(!a(ab - 2))
    var xy: Option[(SInt, SInt)] = None
    for (s <- 1 until n) {
      val up = !z(z.getWidth - 1)
      ups = ups :+ up
      val nextXy: Option[(SInt, SInt)] =
        if (s == m - 1) {
          def bits(v: Long) = BigInt(v) & ((BigInt(1) << w) - 1)
          val e = lookup(table.map { case (x, y) => bits(x) << w | bits(y) }, if (p.taperFoldAtOutput) ups else folded +: ups, 2 * w)
          Some((e(2 * w - 1, w).asSInt, e(w - 1, 0).asSInt))
        } else if (s >= m) xy.map { case (x, y) => (addRounded(p, x, y, s, up), addRounded(p, y, x, s, !up)) }
        else None
      xy = nextXy.map { case (x, y) => (reg(x, s"x_$s"), reg(y, s"y_$s")) }
      if (s < n - 1) {
        val (lo, hi) = p.zRanges(s)
        val zw = p.signedBits(lo, hi)
        val k = p.angleTable(s)
        val mask = (BigInt(1) << zw) - 1
        val step = Mux(up, ((-BigInt(k)) & mask).U(zw.W), (BigInt(k) & mask).U(zw.W))
        z = reg((z.pad(zw).asUInt(zw - 1, 0) + step)(zw - 1, 0).asSInt, s"z_$s")
      }
      if (s < m - 1) ups = ups.zipWithIndex.map { case (u, j) => reg(u, s"up${j}_$s") } else ups = Nil
      if (s < m - 1 || p.taperFoldAtOutput) folded = reg(folded, s"fold_$s")
    }

    Unused("z_last", z) // the last angle word decides the last direction by its sign alone
    val (xn, yn) = xy.get
    def outData(v: SInt): SInt = {
      val rounded =
        if (p.taperFoldAtOutput) addRounded(p, 0.S((w - p.guardBits + 1).W), v, p.guardBits, folded) // +-round(v / 2^g)
        else FixedHw.shift(v, p.guardBits, p.rounding)
      if (p.dataInt >= 1) rounded.pad(p.outWidth)(p.outWidth - 1, 0).asSInt else FixedHw.saturate(rounded, p.outWidth)
    }
    val result = Wire(new CordicOut(p))
    result.x := outData(xn)
    result.y := outData(yn)
    result.z := 0.S
    out.bits := reg(result, "out")
    out.valid := ShiftRegister(in.valid, p.latency, false.B, true.B)
  }

  /** A constant table as a tree of multiplexers on the address bits (most significant first), so that
    * synthesis makes logic of it rather than a block RAM.
    */
  def lookup(entries: Seq[BigInt], addr: Seq[Bool], width: Int): UInt =
    if (addr.isEmpty) entries.head.U(width.W)
    else {
      val half = entries.size / 2
      Mux(addr.head, lookup(entries.drop(half), addr.tail, width), lookup(entries.take(half), addr.tail, width))
    }

  /** acc - round(v / 2^s) when `sub`, else acc + round(v / 2^s), in one adder: the direction complements
    * the floored operand and the rounding bit (xor the direction) is the carry in. Width of acc.
    */
  def addRounded(p: CordicParams, acc: SInt, v: SInt, s: Int, sub: Bool): SInt = {
    val w = acc.getWidth
    val vp = v.pad(math.max(w, s + 2))
    val q = (vp >> s).asSInt.pad(w).asUInt(w - 1, 0)
    val roundUp: Bool = p.rounding match {
      case Rounding.Truncate => false.B
      case Rounding.HalfEven =>
        if (s == 0) false.B
        else {
          val rest = if (s >= 2) vp(s - 2, 0).orR else false.B
          vp(s - 1) && (rest || vp(s)) // above half, or exactly half and the quotient odd
        }
    }
    val sum = Cat(acc.asUInt, 1.U(1.W)) + Cat(q ^ Fill(w, sub), roundUp ^ sub)
    Unused("carry_in", sum(0)) // bit 0 only carries the rounding in
    sum(w, 1).asSInt
  }
}
