package moire.cordic

import org.scalatest.flatspec.AnyFlatSpec

class FixedSpec extends AnyFlatSpec {
  "Fixed.shift" should "floor or round half to even, for every shift up to 70 bits" in {
    val rnd = new scala.util.Random(7)
    val values = Seq(0L, 1L, -1L, 5L, -5L, 6L, -6L, 7L, (1L << 59) - 1, -(1L << 59)) ++ Seq.fill(200)(rnd.nextLong() >> 5)
    for (v <- values; s <- 0 to 70) {
      val exact = BigDecimal(v) / BigDecimal(2).pow(s)
      val floor = exact.setScale(0, BigDecimal.RoundingMode.FLOOR).toLong
      val even = exact.setScale(0, BigDecimal.RoundingMode.HALF_EVEN).toLong
      assert(Fixed.shift(v, s, Rounding.Truncate) == floor, s"floor($v / 2^$s)")
      assert(Fixed.shift(v, s, Rounding.HalfEven) == even, s"rne($v / 2^$s)")
      assert(Fixed.shift(BigInt(v), s, Rounding.HalfEven) == BigInt(even))
    }
  }

  "Angles" should "wrap modulo one turn" in {
    assert(Fixed.radToAngle(math.Pi, 16) == -32768)
    assert(Fixed.angleDiff(math.Pi - 1e-9, -math.Pi + 1e-9).abs < 1e-8)
  }
}
