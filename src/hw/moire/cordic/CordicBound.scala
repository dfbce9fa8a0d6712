package moire.cordic

import CordicMode._

/** A priori error bound of one configuration, split into its terms (all in the output's unit:
  * radians for angles, full scale = 1.0 for data).
  *
  * Structure from the papers: approximation term (seed 001 eq. 9, seed 002 eq. 16), rounding
  * term propagated through the iterations as G(n) (seed 001 eqs. 10-11, seed 002 eq. 25), the
  * sine slope (seed 001 eq. 15) and the arcsine peak term (seed 002 eq. 27). Added here, because
  * the hardware has them and the papers do not: two rounded terms per double-rotation component,
  * the arcsine target's own rounding, the rounded arctan table, the rounded 1/K, and the final
  * rounding to the output word.
  */
final case class CordicBound(approx: Double, rounding: Double, table: Double, output: Double, extra: Double) {
  def total: Double = approx + rounding + table + output + extra
}

object CordicBound {
  private def pow2(e: Double): Double = math.pow(2, e)

  // The bounds at an input's radius ask for these at every input `CordicAccuracy.measure` takes (a pass over the
  // steps, each a product over the later ones): computed once per configuration (an atan2 sweep of `CordicBoundSpec` 24 -> 4 s)
  private val vectorMemo = new java.util.concurrent.ConcurrentHashMap[CordicParams, java.lang.Double]()
  private val tableMemo = new java.util.concurrent.ConcurrentHashMap[CordicParams, java.lang.Double]()
  private def memo(m: java.util.concurrent.ConcurrentHashMap[CordicParams, java.lang.Double], p: CordicParams)(f: CordicParams => Double): Double =
    m.computeIfAbsent(p, q => java.lang.Double.valueOf(f(q))).doubleValue

  /** One rounding's largest error, in units of the LSB it rounds to. */
  def roundingLsb(r: Rounding): Double = if (r == Rounding.Truncate) 1.0 else 0.5

  /** Largest propagated rounding error of the x/y vector after all iterations (full scale 1.0):
    * sum over steps j that round of |e_j| * prod_{i > j} ||P(i)||.
    */
  def vectorRounding(p: CordicParams): Double = memo(vectorMemo, p)(vectorRoundingOf)
  private def vectorRoundingOf(p: CordicParams): Double = {
    val eps = roundingLsb(p.rounding) * pow2(-p.innerFrac)
    val steps = p.steps.toIndexedSeq
    def norm(i: Int) = if (p.isDouble) 1 + pow2(-2 * i) else math.sqrt(1 + pow2(-2 * i))
    steps.indices.map { idx =>
      val i = steps(idx)
      val rounded = if (p.isDouble) (if (i - 1 > 0) 2 else 1) else (if (i > 0) 1 else 0)
      math.sqrt(2) * rounded * eps * steps.drop(idx + 1).map(norm).product
    }.sum
  }

  /** Rounding of the double-rotation target t = A prod (1 + 2^-2i). */
  def targetRounding(p: CordicParams): Double = {
    val eps = roundingLsb(p.rounding) * pow2(-p.innerFrac)
    val steps = p.steps.toIndexedSeq
    steps.indices.map(idx => eps * steps.drop(idx + 1).map(i => 1 + pow2(-2 * i)).product).sum
  }

  /** Sum of the arctan table's rounding errors, radians. */
  def tableError(p: CordicParams): Double = memo(tableMemo, p)(tableErrorOf)
  private def tableErrorOf(p: CordicParams): Double =
    p.steps.zip(p.angleTable).map { case (i, k) =>
      math.abs(k.toDouble / pow2(p.zWidth) * 2 * math.Pi - p.stepAngle(i))
    }.sum

  /** Rounding of z to the output angle word, radians. */
  def angleOutput(p: CordicParams): Double = roundingLsb(p.rounding) * pow2(-p.angleBits) * 2 * math.Pi
  /** Rounding to the output data word. */
  def dataOutput(p: CordicParams): Double = roundingLsb(p.rounding) * pow2(-p.dataFrac)

  /** Approximation error of the iterations: the last step's angle (seed 001 eq. 9 / seed 002 eq. 16). */
  def approx(p: CordicParams): Double = p.stepAngle(p.steps.last)

  /** Bound for sin/cos and vector rotation; `radius` is |(x, y)| of the input (1.0 for sincos). */
  def rotation(p: CordicParams, radius: Double = 1.0): CordicBound = {
    val f = vectorRounding(p)
    val k = p.gain
    if (p.mode == SinCos) {
      val start = if (p.gainCompensation) math.abs(p.startX * pow2(-p.innerFrac) - 1 / k) * k else 0.0
      val scale = if (p.gainCompensation) 1.0 else k
      // With no integer bit, +1.0 saturates to 1 - LSB.
      val clip = if (p.dataInt == 0) pow2(-p.dataFrac) else 0.0
      CordicBound(approx(p) * scale, f, tableError(p) * scale, dataOutput(p), start + clip)
    } else {
      val inv = if (p.postScale) p.invGainConst * pow2(-p.kFrac) else 1.0
      val invErr = if (p.postScale) math.abs(inv - 1 / k) * (k * radius + f) else 0.0
      val scale = if (p.gainCompensation) radius else radius * k
      CordicBound(approx(p) * scale, f * inv, tableError(p) * scale, dataOutput(p), invErr)
    }
  }

  /** Bound for the atan2 angle at an input of magnitude `radius` (full scale 1.0). */
  def atan2(p: CordicParams, radius: Double): CordicBound = {
    val f = vectorRounding(p)
    val r = math.max(radius - f, 1e-300)
    val roundingAngle = if (radius <= f) math.Pi else 2 * f / r
    CordicBound(approx(p), roundingAngle, tableError(p), angleOutput(p), 0.0)
  }

  /** Bound for the atan2 magnitude at an input of magnitude `radius`. */
  def magnitude(p: CordicParams, radius: Double): CordicBound = {
    val f = vectorRounding(p)
    val k = p.gain
    val inv = if (p.postScale) p.invGainConst * pow2(-p.kFrac) else 1.0
    val residual = approx(p) + (if (radius > f) 2 * f / (radius - f) else math.Pi)
    val cosine = k * radius * (1 - math.cos(math.min(residual, math.Pi / 2))) * inv
    val invErr = if (p.postScale) math.abs(inv - 1 / k) * (k * radius + f) else 0.0
    CordicBound(cosine, f * inv, 0.0, dataOutput(p), invErr)
  }

  /** Bound for the double-rotation arcsine over inputs |A| <= aMax (radians). */
  def asinDouble(p: CordicParams, aMax: Double = 1.0): CordicBound = {
    val eta = vectorRounding(p) + targetRounding(p)
    val rounding = asinBand(aMax, eta) + vectorRounding(p)
    val tbl = peakTableBound(p)
    tbl match {
      case Some((start, binErr)) =>
        val below = asinBand(math.min(aMax, start), eta) + vectorRounding(p)
        CordicBound(approx(p), below, tableError(p), angleOutput(p), binErr)
      case None => CordicBound(approx(p), rounding, tableError(p), angleOutput(p), 0.0)
    }
  }

  /** Largest |asin(clamp(A +- eta)) - asin(A)| over |A| <= aMax (seed 002 eq. 27 for aMax = 1). */
  def asinBand(aMax: Double, eta: Double): Double = {
    def clampAsin(v: Double) = math.asin(math.max(-1.0, math.min(1.0, v)))
    // asin is steepest at the top of the range: check the upper end.
    math.max(clampAsin(aMax + eta) - math.asin(aMax), math.asin(aMax) - clampAsin(aMax - eta))
  }

  /** Peak table: (first input handled by the table as a fraction of full scale, largest bin error + output rounding). */
  def peakTableBound(p: CordicParams): Option[(Double, Double)] =
    if (p.peakTableSize == 0) None
    else {
      val t = PeakTable(p)
      Some(((t.start - 1).toDouble / t.oneCode, t.binError + 0.5 * pow2(-p.angleBits) * 2 * math.Pi))
    }

  /** Conventional arcsine (seed 002 eq. 8): the misjudged rotation directions have no closed form, so the
    * algorithmic term is the exact worst error of the ideal recursion and the rounding term what the model's
    * rounded comparisons add to it, both by [[ArcsineSearch]] over every input up to the peak table.
    */
  def asinConventional(p: CordicParams): CordicBound = {
    val tbl = peakTableBound(p)
    val aMax = tbl.map(_._1).getOrElse(1.0)
    val ideal = ArcsineSearch.worst(p, aMax, rounded = false)
    val rounded = ArcsineSearch.worst(p, aMax, rounded = true)
    CordicBound(ideal, math.max(0.0, rounded - ideal), tableError(p), angleOutput(p), tbl.map(_._2).getOrElse(0.0))
  }

  /** The largest error of the best constant output, half the output's range: sine and cosine 1 full scale
    * (K without gain compensation), rotate the headline radius, atan2 pi, arcsine and arccosine pi/2.
    */
  def constantError(p: CordicParams): Double = p.mode match {
    case SinCos => if (p.gainCompensation) 1.0 else p.gain
    case Rotate => pow2(p.dataInt) * (if (p.gainCompensation) 1.0 else p.gain)
    case Atan2 => math.Pi
    case _ => math.Pi / 2
  }

  /** A bound a constant output would meet guarantees nothing: the rounding of n steps swamps b bits. */
  def vacuous(p: CordicParams, bound: Double): Boolean = bound >= constantError(p)

  /** The bound that a configuration's headline figure is checked against (angle in radians or data). */
  def headline(p: CordicParams): CordicBound = p.mode match {
    case SinCos => rotation(p)
    case Rotate => rotation(p, pow2(p.dataInt))
    case Atan2 => atan2(p, 0.5)
    case AsinDouble | AcosDouble => asinDouble(p)
    case Asin | Acos => asinConventional(p)
  }

  /** The papers' own bound for the same (n, b), where a paper has one: seed 001 eq. 15 for sines,
    * seed 002 eq. 28 for the double-rotation arcsine, with b the internal fractional bits.
    */
  def paper(p: CordicParams): Option[Double] = p.mode match {
    case SinCos => Some(PaperBounds.seed001Lmax(p.iterations, p.innerFrac))
    case AsinDouble | AcosDouble => Some(PaperBounds.seed002Oqe(p.iterations, p.innerFrac))
    case _ => None
  }
}
