package moire.harmonic

import moire.cordic.{CordicModel, CordicWord, Fixed, Rounding}

/** One harmonic as the registers hold it: order k, c_k word (arcsec, coefFrac bits), phi_k binary angle. */
final case class HarmonicSlot(order: Int, c: Long, phi: Long)

object HarmonicSlot {
  val off: HarmonicSlot = HarmonicSlot(0, 0, 0)
  /** Slot from c_k in arcsec and phi_k in degrees. */
  def of(p: HarmonicParams, order: Int, cArcsec: Double, phiDeg: Double): HarmonicSlot = {
    require(order >= 0 && order <= p.maxOrder, s"order $order out of 0..${p.maxOrder}")
    HarmonicSlot(order, p.coefWord(cArcsec), p.phaseWord(phiDeg))
  }
}

/** Result of one angle: f(theta) in counts (outFrac bits, signed) and theta - f(theta) modulo one turn. */
final case class HarmonicOut(f: Long, out: Long)

/** Bit-accurate model of [[HarmonicCompensator]]: same angle arithmetic, CORDIC model, exact products
  * and sum, one round-half-even when scaling arcsec to counts, wrap of the compensated angle.
  */
class HarmonicModel(val p: HarmonicParams) {
  private val cordic = new CordicModel(p.cordic)
  private val turnMask = (1L << p.countBits) - 1

  /** The angle word k theta + phi_k (mod one turn), signed as the CORDIC port reads it. */
  def angle(theta: Long, s: HarmonicSlot): Long =
    Fixed.wrap(((theta & turnMask) * s.order + s.phi) & turnMask, p.countBits)

  /** The CORDIC sine of a slot, b fractional bits. */
  def sine(theta: Long, s: HarmonicSlot): Long = cordic(CordicWord(0, 0, angle(theta, s))).y

  /** sum_k c_k sin(k theta + phi_k), arcsec with coefFrac + b fractional bits. */
  def sum(theta: Long, slots: Seq[HarmonicSlot]): BigInt = {
    require(slots.size == p.harmonics, s"${slots.size} slots given, the compensator has ${p.harmonics}")
    slots.map(s => BigInt(Fixed.wrap(s.c, p.coefWidth)) * BigInt(sine(theta, s))).sum
  }

  def apply(theta: Long, slots: Seq[HarmonicSlot]): HarmonicOut = {
    val f = Fixed.shift(sum(theta, slots) * BigInt(p.kConst), p.fShift, Rounding.HalfEven).toLong
    require(Fixed.fits(f, p.fWidth), s"${p.moduleName}: f = $f overflows ${p.fWidth} bits")
    val outMask = (1L << p.outWidth) - 1
    HarmonicOut(f, (((theta & turnMask) << p.outFrac) - f) & outMask)
  }

  /** f(theta) in arcsec read back from the compensated output (what a user of the output sees). */
  def fArcsec(theta: Long, out: Long): Double = {
    val d = Fixed.wrap(((theta & turnMask) << p.outFrac) - out, p.outWidth)
    d.toDouble / math.pow(2, p.outFrac) * p.arcsecPerCount
  }
}

/** A priori error bound of the compensator. */
object HarmonicBound {
  /** Largest |f read from the output - f in double precision| in arcsec, for coefficients with
    * sum |c_k| = `sumAbsC` arcsec, the reference using the same coefficient and phase words:
    * each CORDIC sine within its bound (CordicBound.rotation), the counts-per-arcsec constant's
    * rounding, and half an output LSB.
    */
  def arcsec(p: HarmonicParams, sumAbsC: Double): Double = {
    val sine = moire.cordic.CordicBound.rotation(p.cordic).total
    val kErr = math.abs(p.kConst * math.pow(2, -p.kFrac) - p.countsPerArcsec)
    sumAbsC * sine + (sumAbsC * (1 + sine) * kErr + 0.5 * math.pow(2, -p.outFrac)) * p.arcsecPerCount
  }
}

/** The double-precision reference: f(theta) = sum c_k sin(k theta + phi_k), theta a count, c in arcsec,
  * phi in degrees.
  */
object HarmonicReference {
  def f(p: HarmonicParams, theta: Long, harmonics: Seq[(Int, Double, Double)]): Double = {
    val th = theta.toDouble / p.countsPerTurn * 2 * math.Pi
    harmonics.map { case (k, c, phi) => c * math.sin(k * th + math.toRadians(phi)) }.sum
  }

  /** The reference for register words: c_k and phi_k exactly as the slots hold them. */
  def ofSlots(p: HarmonicParams, theta: Long, slots: Seq[HarmonicSlot]): Double =
    f(p, theta, slots.map(s => (s.order, Fixed.wrap(s.c, p.coefWidth) * math.pow(2, -p.coefFrac), s.phi * 360.0 / p.countsPerTurn)))
}
