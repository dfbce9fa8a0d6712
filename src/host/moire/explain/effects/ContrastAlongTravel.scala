package moire.explain.effects

import moire.explain._

/** Offsets and amplitudes changing with the position along the travel (beam walk, scale contamination): linear in the
  * position, or a piecewise-linear function of it with the number of knots chosen by the criterion (a local band).
  */
object ContrastAlongTravel extends Effect {
  val name = "contrast_along_travel"
  val params = Seq(Param("offset_sin_per_period", "full scale/period", "any"), Param("offset_cos_per_period", "full scale/period", "any"),
    Param("gain_sin_per_period", "1/period", "any"), Param("gain_cos_per_period", "1/period", "any"))
  val what = "offsets (full scale) and gains (relative) changing linearly with the position along the travel (beam walk, scale contamination), per fringe period from the start; explain also fits the amplitudes as a piecewise-linear function of the position (8..64 knots, by BIC) for a local band"
  val shows = "against position"
  override def example: Example = Example(EffectSpec(name, Map("gain_sin_per_period" -> 2e-5, "offset_cos_per_period" -> 1e-5)), "oscillate:400:300")
  val domain: Domain = Domain.Time
  override val plot: PlotKind = PlotKind.Position
  /** Knots of the smooth contrast candidates (equally spaced over the travel). */
  val Knots: Seq[Int] = Seq(8, 16, 32, 64)
  /** Position bins and the chi-square (in sd) of the residual's amplitude against the position above which the smooth
    * candidates are fitted (they are large: 2 columns per knot).
    */
  val Bins = 64
  val Z = 6.0
  /** Fringe periods between knots at least: closer knots would follow the fringe phase (a harmonic's shape). */
  val MinKnotPeriods = 4.0

  /** The residual's amplitude against the position in `Bins` bins (sum r u / sum u^2) less a quadratic in the position
    * (what a linear contrast change or a low-pass on a ramp makes), as a chi-square in sd: local structure only.
    */
  def amplitudeAlongTravel(e: SignalEngine): Double = {
    val x = e.travel; var lo = Double.MaxValue; var hi = -Double.MaxValue
    x.foreach { v => lo = math.min(lo, v); hi = math.max(hi, v) }
    if (!(hi > lo)) return 0.0
    val ru = new Array[Double](Bins); val uu = new Array[Double](Bins); var i = 0
    val vS = e.noise.varS; val vC = e.noise.varC
    while (i < e.n) {
      val b = math.min(Bins - 1, ((x(i) - lo) / (hi - lo) * Bins).toInt)
      ru(b) += e.resS(i) * e.us(i) / vS + e.resC(i) * e.uc(i) / vC; uu(b) += e.us(i) * e.us(i) / vS + e.uc(i) * e.uc(i) / vC; i += 1
    }
    val used = (0 until Bins).filter(uu(_) > 0)
    if (used.size <= 4) return 0.0
    // weighted least squares of the bin amplitudes a = ru / uu (weight uu) on 1, x, x^2
    val m = Array.ofDim[Double](3, 4)
    for (b <- used) {
      val x = (b + 0.5) / Bins - 0.5; val xs = Array(1.0, x, x * x); val a = ru(b) / uu(b)
      for (i <- 0 until 3) { for (j <- 0 until 3) m(i)(j) += uu(b) * xs(i) * xs(j); m(i)(3) += uu(b) * xs(i) * a }
    }
    val q = moire.explain.Trajectory.solve4(Array(Array(m(0)(0), m(0)(1), m(0)(2), 0, m(0)(3)), Array(m(1)(0), m(1)(1), m(1)(2), 0, m(1)(3)),
      Array(m(2)(0), m(2)(1), m(2)(2), 0, m(2)(3)), Array(0.0, 0, 0, 1, 0)))
    val chi2 = used.map { b =>
      val x = (b + 0.5) / Bins - 0.5; val d = ru(b) / uu(b) - (q(0) + q(1) * x + q(2) * x * x); uu(b) * d * d
    }.sum
    Locate.zOf(chi2, used.size - 3)
  }

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Contrast)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    (() => c.linear(Term.Contrast).map(_._1).toSeq) +:
      (if (c.engine.spec.terms.exists(_.effect == this) || amplitudeAlongTravel(c.engine) < Z) Nil
       else Knots.filter(k => travelSpan(c.engine) / (k - 1) >= MinKnotPeriods).map(k => () => c.linear(Term.ContrastSpline(k)).map(_._1).toSeq))

  /** The span of positions the record covers (fringe periods). */
  def travelSpan(e: SignalEngine): Double = { val x = e.travel; x.max - x.min }
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = t match {
    case Term.ContrastSpline(k) =>
      // knot j's coefficients: gain sin, gain cos (relative to the first knot's values); c = 2, 3 (0, 1: offsets, not fitted)
      def at(j: Int, c: Int) = if (j == 0 || c < 2) 0.0 else b(2 * (j - 1) + c - 2)
      def sdAt(j: Int, c: Int) = if (j == 0 || c < 2) 0.0 else sd(2 * (j - 1) + c - 2)
      val span = { val x = e.travel; x.max - x.min }
      def worst(c: Int): Int = (0 until k).maxBy(j => math.abs(at(j, c) - (0 until k).map(at(_, c)).sum / k))
      def range(c: Int) = { val v = (0 until k).map(at(_, c)); v.max - v.min }
      val g = if (range(2) >= range(3)) 2 else 3; val j = worst(g)
      (Map("knots" -> k.toDouble, "travel_periods" -> span, "gain_sin_range_rel" -> range(2), "gain_cos_range_rel" -> range(3),
        "band_at_periods" -> j * span / (k - 1), "band_gain_rel" -> at(j, g)),
        Map("knots" -> 0.0, "travel_periods" -> 0.0, "gain_sin_range_rel" -> sdAt(j, 2), "gain_cos_range_rel" -> sdAt(j, 3),
          "band_at_periods" -> span / (k - 1), "band_gain_rel" -> sdAt(j, g)),
        s"against position: offset and amplitude, $k knots", "both")
    case _ =>
      val names = params.map(_.name)
      val span = { val x = e.travel; x.max - x.min }
      (names.zip(b).toMap + ("travel_periods" -> span), names.zip(sd).toMap + ("travel_periods" -> 0.0), "against position: offset and amplitude", "both")
  }
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = TimeOrTravel.lookAlikes(e, Warmup.name + " or " + Drift.name)

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    val l = g("travel_periods")
    if (p.contains("knots"))
      f"contrast changes along the travel: amplitudes vary by ${100 * g("gain_sin_range_rel")}%.3g / ${100 * g("gain_cos_range_rel")}%.3g %% (sin/cos), " +
        f"most (${100 * g("band_gain_rel")}%.3g %%) near ${g("band_at_periods")}%.4g periods from the start of the ${l}%.0f travelled (${g("knots").toInt} knots)"
    else
      f"contrast changes along the travel: amplitudes ${100 * g("gain_sin_per_period") * l}%.3g / ${100 * g("gain_cos_per_period") * l}%.3g %%, offsets ${g("offset_sin_per_period") * l}%.3g / ${g("offset_cos_per_period") * l}%.3g full scale over the ${l}%.0f periods travelled (sin/cos)"
  }
}
