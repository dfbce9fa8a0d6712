package moire.cordic

/** Integer helpers shared by the bit-accurate models, and conversions between doubles and fixed point. */
object Fixed {
  /** v / 2^s rounded as the hardware does: floor for truncate, round half to even otherwise.
    * (A Long twin of the BigInt version below, for speed in the models' inner loops.)
    */
  def shift(v: Long, s: Int, r: Rounding): Long =
    if (s <= 0) v
    else if (s >= 62) { // |v| < 2^60 here: the quotient is 0 or -1 (JVM shifts are taken mod 64)
      require(math.abs(v) < (1L << 60), s"shift: $v too wide")
      if (r == Rounding.Truncate && v < 0) -1L else 0L
    }
    else {
      val q = v >> s
      r match {
        case Rounding.Truncate => q
        case Rounding.HalfEven =>
          val rem = v - (q << s)
          val half = 1L << (s - 1)
          if (rem > half || (rem == half && (q & 1L) == 1L)) q + 1 else q
      }
    }

  def shift(v: BigInt, s: Int, r: Rounding): BigInt =
    if (s <= 0) v
    else {
      val q = v >> s
      r match {
        case Rounding.Truncate => q
        case Rounding.HalfEven =>
          val rem = v - (q << s)
          val half = BigInt(1) << (s - 1)
          if (rem > half || (rem == half && q.testBit(0))) q + 1 else q
      }
    }

  def minOf(width: Int): Long = -(1L << (width - 1))
  def maxOf(width: Int): Long = (1L << (width - 1)) - 1
  def saturate(v: Long, width: Int): Long = math.max(minOf(width), math.min(maxOf(width), v))
  /** Wrap to a signed word of `width` bits (two's complement). */
  def wrap(v: Long, width: Int): Long = (v << (64 - width)) >> (64 - width)
  def fits(v: Long, width: Int): Boolean = v >= minOf(width) && v <= maxOf(width)

  /** A double in [-2^(w-1-f), 2^(w-1-f)) to the nearest code with f fractional bits, saturated. */
  def toFixed(d: Double, frac: Int, width: Int): Long = saturate(math.round(d * math.pow(2, frac)), width)
  def toDouble(v: Long, frac: Int): Double = v.toDouble / math.pow(2, frac)

  /** Radians to a binary angle of `width` bits (one turn = 2^width), wrapped to the signed word. */
  def radToAngle(rad: Double, width: Int): Long = wrap(math.round(rad / (2 * math.Pi) * math.pow(2, width)), width)
  def angleToRad(a: Long, width: Int): Double = a.toDouble / math.pow(2, width) * 2 * math.Pi

  /** Difference a - b of two angles in radians, reduced to (-pi, pi]. */
  def angleDiff(a: Double, b: Double): Double = {
    val d = (a - b) % (2 * math.Pi)
    if (d > math.Pi) d - 2 * math.Pi else if (d <= -math.Pi) d + 2 * math.Pi else d
  }
}
