package moire.calibration

import moire.harmonic._

import org.hipparchus.linear.{Array2DRowRealMatrix, ArrayRealVector, QRDecomposition}

/** One harmonic c sin(k theta + phi): c in arcsec (>= 0), phi in degrees (-180, 180]. */
final case class Harmonic(order: Int, c: Double, phiDeg: Double) {
  def at(thetaDeg: Double): Double = c * math.sin(math.toRadians(order * thetaDeg + phiDeg))
}

/** A least-squares fit c0 + sum c_k sin(k theta + phi_k) and its residual. */
final case class HarmonicFitResult(offset: Double, harmonics: Seq[Harmonic], residuals: Seq[Double]) {
  def apply(thetaDeg: Double): Double = offset + harmonics.map(_.at(thetaDeg)).sum
  /** The part the compensator removes: harmonics only, no offset. */
  def harmonicPart(thetaDeg: Double): Double = harmonics.map(_.at(thetaDeg)).sum
  def rms: Double = math.sqrt(residuals.map(r => r * r).sum / residuals.size)
  def maxAbs: Double = residuals.map(math.abs).max
}

/** Harmonic analysis of turntable position errors (seed 001 sec. 1.1).
  * Linear least squares on c0 + sum a_k sin(k theta) + b_k cos(k theta) (Hipparchus QR), which equals the
  * DFT when the angles are evenly spaced; c_k = hypot(a_k, b_k), phi_k = atan2(b_k, a_k).
  */
object HarmonicFit {
  /** Fits the given orders (plus the offset) to the points. */
  def fit(anglesDeg: Seq[Double], errors: Seq[Double], orders: Seq[Int]): HarmonicFitResult = {
    require(anglesDeg.size == errors.size && orders.forall(_ >= 1) && orders.distinct.size == orders.size)
    val unknowns = 1 + 2 * orders.size
    if (anglesDeg.size < unknowns)
      throw new CalibrationError(s"${anglesDeg.size} points cannot determine ${orders.size} harmonics (need ${unknowns}); lower --max-order")
    val a = new Array2DRowRealMatrix(anglesDeg.size, unknowns)
    for ((t, i) <- anglesDeg.zipWithIndex) {
      a.setEntry(i, 0, 1.0)
      for ((k, j) <- orders.zipWithIndex) {
        val r = math.toRadians(k * t)
        a.setEntry(i, 1 + 2 * j, math.sin(r))
        a.setEntry(i, 2 + 2 * j, math.cos(r))
      }
    }
    val qr = new QRDecomposition(a, 1e-9)
    if (!qr.getSolver.isNonSingular)
      throw new CalibrationError(s"the angles do not separate harmonics up to order ${orders.max} (aliasing); lower --max-order")
    val x = qr.getSolver.solve(new ArrayRealVector(errors.toArray))
    val hs = orders.zipWithIndex.map { case (k, j) =>
      val s = x.getEntry(1 + 2 * j); val c = x.getEntry(2 + 2 * j)
      Harmonic(k, math.hypot(s, c), math.toDegrees(math.atan2(c, s)))
    }
    val res0 = HarmonicFitResult(x.getEntry(0), hs, Nil)
    res0.copy(residuals = anglesDeg.zip(errors).map { case (t, e) => e - res0(t) })
  }

  /** Fits orders 1..maxOrder, keeps the m largest amplitudes and refits with those orders only. */
  def analyse(anglesDeg: Seq[Double], errors: Seq[Double], maxOrder: Int, m: Int): HarmonicFitResult = {
    if (m < 1) throw new CalibrationError(s"--harmonics must be at least 1, got $m")
    if (maxOrder < m) throw new CalibrationError(s"--max-order $maxOrder is below --harmonics $m")
    val full = fit(anglesDeg, errors, 1 to maxOrder)
    val keep = full.harmonics.sortBy(h => -h.c).take(m).map(_.order).sorted
    fit(anglesDeg, errors, keep)
  }

  /** The largest order a set of points supports: (points - 1) / 2, at most 32. */
  def defaultMaxOrder(points: Int): Int = math.max(1, math.min(32, (points - 1) / 2))
}
