package moire.harmonic

import chisel3._

/** A signed product a * b for 18x18 multiplier blocks in `latency` = 3 clocks: each operand cut into
  * 17-bit unsigned pieces (low first) and a signed top piece, every piece product registered (one block
  * each), then each row (one piece of a times all pieces of b) summed and registered, then the rows.
  * Exact: the result is a * b, width a.getWidth + b.getWidth.
  */
object PieceMul {
  val latency: Int = 3
  private val piece = 17

  /** Pieces of x with their shifts: unsigned 17-bit pieces widened to signed, the top piece signed. */
  def pieces(x: SInt): Seq[(SInt, Int)] = {
    val w = x.getWidth
    if (w <= piece + 1) Seq(x -> 0)
    else {
      val n = (w - 1) / piece // the top piece keeps 1 .. 17 bits and the sign
      (0 until n).map(i => x(piece * i + piece - 1, piece * i).zext -> piece * i) :+ (x(w - 1, piece * n).asSInt -> piece * n)
    }
  }

  def apply(a: SInt, b: SInt, name: String): SInt = {
    def reg[T <: Data](v: T, n: String): T = { val r = Reg(chiselTypeOf(v)); r := v; r.suggestName(n); r }
    val width = a.getWidth + b.getWidth
    val rows = pieces(a).zipWithIndex.map { case ((pa, sa), i) =>
      val prods = pieces(b).zipWithIndex.map { case ((pb, sb), j) => reg(pa * pb, s"${name}_p${i}_$j") -> sb }
      val rowWidth = width - sa // the bits that land in the product after the row's shift
      val row = prods.map { case (v, s) => (v.pad(rowWidth) << s).asSInt }.reduce(_ + _)
      reg(row(rowWidth - 1, 0).asSInt, s"${name}_row$i") -> sa
    }
    reg(rows.map { case (v, s) => (v << s).asSInt }.reduce(_ + _)(width - 1, 0).asSInt, name)
  }
}
