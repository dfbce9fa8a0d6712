package moire.explain.effects

import moire.explain._

/** Offsets and amplitudes changing with the position along the travel (beam walk, scale contamination): linear in the
  * position, or the amplitudes as a piecewise-linear function of it with knots placed and counted by the criterion
  * (a local band).
  */
object ContrastAlongTravel extends Effect {
  val name = "contrast_along_travel"
  val params = Seq(Param("offset_sin_per_period", "full scale/period", "any"), Param("offset_cos_per_period", "full scale/period", "any"),
    Param("gain_sin_per_period", "1/period", "any"), Param("gain_cos_per_period", "1/period", "any"))
  override val needs: Seq[String] = params.map(_.name)
  val what = "offsets (full scale) and gains (relative) changing linearly with the position along the travel (beam walk, scale contamination), per fringe period from the start; explain also fits the amplitudes as a piecewise-linear function of the position with knots placed where the residual needs them (up to 64, by BIC) for a local band"
  val shows = "against position"
  override def example: Example = Example(EffectSpec(name, Map("gain_sin_per_period" -> 2e-5, "offset_cos_per_period" -> 1e-5)), "oscillate:400:300")
  val domain: Domain = Domain.Time
  override val plot: PlotKind = PlotKind.Position
  /** The most knots of the smooth candidate, and the most samples times its columns (its design is held in memory). */
  val MaxKnots = 64
  val MaxCells: Long = 1L << 25
  /** Position bins and the chi-square (in sd) of the residual's amplitude against the position above which the smooth
    * candidate is fitted (it is large: 3 parameters per knot).
    */
  val Bins = 64
  val Z = 6.0
  /** Fringe periods per bin of the knot search, and between knots at least: an amplitude averaged over whole periods
    * does not see a harmonic of the fringe (a hat function whose knots are one period apart has no part at one cycle
    * per period).
    */
  val MinKnotPeriods = 1.0
  /** Most bins of the knot search (a long travel gets wider bins). */
  val MaxSearchBins = 4096

  /** The residual's amplitude against the position in `Bins` bins (sum r u / sum u^2) less a quadratic in the position
    * (what a linear contrast change or a low-pass on a ramp makes), as a chi-square in sd: local structure only.
    */
  def amplitudeAlongTravel(e: SignalEngine): Double = {
    // the position along the travel read where it is needed (`e.travel` without its array)
    val mean = e.travelMean; val (lo, hi) = e.travelRange
    if (!(hi > lo)) return 0.0
    val vS = e.noise.varS; val vC = e.noise.varC
    // per bin of the position: sum r u / var and sum u^2 / var of both channels, in blocks on all cores
    val sums = Par.sums(e.n, 2 * Bins) { (a, z, m) =>
      var i = a
      while (i < z) {
        val b = math.min(Bins - 1, ((e.phase(i) - mean - lo) / (hi - lo) * Bins).toInt)
        m(b) += e.resS(i) * e.us(i) / vS + e.resC(i) * e.uc(i) / vC; m(Bins + b) += e.us(i) * e.us(i) / vS + e.uc(i) * e.uc(i) / vC; i += 1
      }
    }
    val ru = sums.slice(0, Bins); val uu = sums.slice(Bins, 2 * Bins)
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
  override def domainOf(t: Term): Domain = t match { case _: Term.ContrastSpline => Domain.Position; case _ => domain }
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    (() => c.linear(Term.Contrast).map(_._1).toSeq) +:
      (if (c.engine.spec.terms.exists(_.isInstanceOf[Term.ContrastSpline]) || amplitudeAlongTravel(c.engine) < Z) Nil
       else Seq(() => knots(c.engine).toSeq.flatMap(k => c.linear(Term.ContrastSpline(k)).map(_._1))))

  /** The span of positions the record covers (fringe periods). */
  def travelSpan(e: SignalEngine): Double = { val (lo, hi) = e.travelRange; hi - lo }

  /** The position along the travel as a fraction 0..1 of its range is (phase(i) - m - lo) / span at sample i (made
    * where it is read): m, lo and span, and the range (fringe periods).
    */
  private def unit(e: SignalEngine): (Double, Double, Double, Double) = {
    val m = e.travelMean; val (lo, hi) = e.travelRange
    (m, lo, math.max(1e-12, hi - lo), hi - lo)
  }

  /** The hat function of knot j of `k` at z (1 at its knot, 0 at its neighbours and beyond). */
  @inline def hat(k: Vector[Double], j: Int, z: Double): Double =
    if (j > 0 && z >= k(j - 1) && z <= k(j)) (z - k(j - 1)) / (k(j) - k(j - 1))
    else if (j + 1 < k.size && z >= k(j) && z <= k(j + 1)) (k(j + 1) - z) / (k(j + 1) - k(j))
    else 0.0

  /** The spline's columns made a block of samples at a time: per knot but the first, the sin channel's fitted
    * fundamental times the knot's hat function, then the cos channel's.
    */
  def splineGen(e: SignalEngine, k: Vector[Double]): ColGen = {
    val (m, lo, span, _) = unit(e); val kn = k.size; val ks = k.toArray
    new ColGen(Array.tabulate(2 * (kn - 1))(_ % 2 == 0), Array.tabulate(2 * (kn - 1))(_ % 2 == 1), (a, b, o, at) => {
      var j = 1
      while (j < kn) { java.util.Arrays.fill(o(4 * (j - 1)), at, at + b - a, 0.0); java.util.Arrays.fill(o(4 * (j - 1) + 3), at, at + b - a, 0.0); j += 1 }
      // the knots rise, so only the two of the interval [ks(t), ks(t + 1)] that holds z can have a hat above zero there
      var t = 0; var i = a
      while (i < b) {
        val q = at + i - a; val z = (e.phase(i) - m - lo) / span
        while (t > 0 && z < ks(t)) t -= 1
        while (t < kn - 2 && z > ks(t + 1)) t += 1
        j = math.max(1, t)
        while (j <= t + 1 && j < kn) {
          val w = hat(k, j, z)
          if (w != 0) { o(4 * (j - 1))(q) = e.us(i) * w; o(4 * (j - 1) + 3)(q) = e.uc(i) * w }
          j += 1
        }
        i += 1
      }
    })
  }

  /** The spline's columns, whole (made a block at a time: the block's columns stay in cache). */
  def splineCols(e: SignalEngine, k: Vector[Double]): IndexedSeq[Col] = {
    val g = splineGen(e, k); val o = g.buffers(e.n); var a = 0
    while (a < e.n) { val b = math.min(e.n, a + Gram.Block); g.fill(a, b, o, a); a = b }
    (0 until g.size).map(j => Col(o(2 * j), o(2 * j + 1)))
  }

  /** The knots of the smooth candidate, chosen by the criterion. The residual's amplitude is measured in bins of one
    * fringe period along the position (sum r u / sum u^2 per channel, weight sum u^2 / floor^2, the noise floor from
    * neighbouring samples); starting from a
    * straight line (knots at both ends), a knot goes where the weighted misfit of the piecewise-linear fit to those bins
    * (summed over three neighbouring bins) is largest, at least `MinKnotPeriods` from the others, up to `MaxKnots`. Of
    * that sequence the set with the lowest chi-square + parameters * ln N wins (each knot: two gains and its position).
    * None when no inner knot pays for itself.
    */
  def knots(e: SignalEngine): Option[Vector[Double]] = {
    // the position at each sample made where it is read (not an array of the record's length: 160 MB at 20 M)
    val (m, lo, zSpan, span) = unit(e)
    val nb = math.max(8, math.min(MaxSearchBins, (span / MinKnotPeriods).toInt))
    val num = Array.ofDim[Double](2, nb); val den = Array.ofDim[Double](2, nb)
    // the noise floor from neighbouring samples (the model's residual still holds the change being looked for)
    val vS = math.max(1e-30, math.pow(Adequacy.floor(e), 2)); val vC = vS; var i = 0
    while (i < e.n) {
      val b = math.min(nb - 1, ((e.phase(i) - m - lo) / zSpan * nb).toInt)
      num(0)(b) += e.resS(i) * e.us(i) / vS; den(0)(b) += e.us(i) * e.us(i) / vS
      num(1)(b) += e.resC(i) * e.uc(i) / vC; den(1)(b) += e.uc(i) * e.uc(i) / vC
      i += 1
    }
    val mid = Array.tabulate(nb)(b => (b + 0.5) / nb)
    // per bin: the weighted misfit of both channels' piecewise-linear fits with knots k
    def misfit(k: Vector[Double]): Array[Double] = {
      val out = new Array[Double](nb)
      for (ch <- 0 to 1) {
        val m = k.size; val g = Array.ofDim[Double](m, m); val r = new Array[Double](m)
        var seg = 0
        for (b <- 0 until nb if den(ch)(b) > 0) {
          while (seg + 2 < m && mid(b) > k(seg + 1)) seg += 1
          val t = (mid(b) - k(seg)) / (k(seg + 1) - k(seg)); val w = den(ch)(b); val a = num(ch)(b) / w
          val h = Array(1 - t, t)
          for (p <- 0 to 1; q <- 0 to 1) g(seg + p)(seg + q) += w * h(p) * h(q)
          r(seg) += w * h(0) * a; r(seg + 1) += w * h(1) * a
        }
        for (j <- 0 until m) g(j)(j) += 1e-9 * (g(j)(j) + 1)
        val f = LinearFit.normal(g, r).beta
        seg = 0
        for (b <- 0 until nb if den(ch)(b) > 0) {
          while (seg + 2 < m && mid(b) > k(seg + 1)) seg += 1
          val t = (mid(b) - k(seg)) / (k(seg + 1) - k(seg)); val d = num(ch)(b) / den(ch)(b) - ((1 - t) * f(seg) + t * f(seg + 1))
          out(b) += den(ch)(b) * d * d
        }
      }
      out
    }
    val minGap = MinKnotPeriods / math.max(span, 1e-12)
    var k = Vector(0.0, 1.0); var c = misfit(k)
    var best = (k, c.sum); val maxK = maxKnots(e)
    def cost(k: Vector[Double], chi2: Double) = chi2 + (2 * (k.size - 1) + (k.size - 2)) * e.lnN
    var open = true
    while (open && k.size < maxK) {
      val free = (0 until nb).filter(b => k.forall(x => math.abs(x - mid(b)) >= minGap * 0.999))
      if (free.isEmpty) open = false
      else {
        val b = free.maxBy(b => c(b) + (if (b > 0) c(b - 1) else 0.0) + (if (b + 1 < nb) c(b + 1) else 0.0))
        k = (k :+ mid(b)).sorted; c = misfit(k)
        if (cost(k, c.sum) < cost(best._1, best._2)) best = (k, c.sum)
      }
    }
    if (best._1.size > 2) Some(best._1) else None
  }

  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = t match {
    case Term.ContrastSpline(k) =>
      // knot j's relative gain changes (sin, cos) from the first knot's, which is the default part's
      def at(j: Int, ch: Int) = if (j == 0) 0.0 else b(2 * (j - 1) + ch)
      def sdAt(j: Int, ch: Int) = if (j == 0) 0.0 else sd(2 * (j - 1) + ch)
      val span = travelSpan(e)
      def range(ch: Int) = { val v = k.indices.map(at(_, ch)); v.max - v.min }
      // the mean of both channels' gain along the travel, on a fine grid: its typical level (median) and the band, the
      // largest departure from it: its depth, and its centre and width at half its depth
      val grid = 2048
      val g = Array.tabulate(grid + 1) { q =>
        val z = q.toDouble / grid; k.indices.map(j => hat(k, j, z) * 0.5 * (at(j, 0) + at(j, 1))).sum
      }
      val level = g.sorted.apply(grid / 2)
      val peak = g.indices.maxBy(q => math.abs(g(q) - level)); val depth = g(peak) - level
      def inBand(q: Int) = math.abs(g(q) - level) >= 0.5 * math.abs(depth)
      var a = peak; while (a > 0 && inBand(a - 1)) a -= 1
      var z = peak; while (z < grid && inBand(z + 1)) z += 1
      val near = k.indices.minBy(j => math.abs(k(j) - peak.toDouble / grid))
      (Map("knots" -> k.size.toDouble, "travel_periods" -> span, "gain_sin_range_rel" -> range(0), "gain_cos_range_rel" -> range(1),
        "band_at_periods" -> span * 0.5 * (a + z) / grid, "band_gain_rel" -> depth / (1 + level), "band_width_periods" -> span * (z - a) / grid),
        Map("knots" -> 0.0, "travel_periods" -> 0.0, "gain_sin_range_rel" -> sdAt(near, 0), "gain_cos_range_rel" -> sdAt(near, 1),
          "band_at_periods" -> span / grid, "band_gain_rel" -> 0.5 * math.hypot(sdAt(near, 0), sdAt(near, 1)),
          "band_width_periods" -> span / grid),
        s"against position: amplitude, ${k.size} knots", "both")
    case _ =>
      val names = params.map(_.name)
      val span = travelSpan(e)
      (names.zip(b).toMap + ("travel_periods" -> span), names.zip(sd).toMap + ("travel_periods" -> 0.0), "against position: offset and amplitude", "both")
  }
  /** The most knots the smooth candidate may have on engine `e` (its design is held in memory). */
  def maxKnots(e: SignalEngine): Int = math.min(MaxKnots.toLong, 1 + MaxCells / (2L * e.n)).toInt

  /** A smooth candidate whose knots reached their cap while its strongest band is narrower than two knot spacings: the
    * criterion still wanted more and no band is resolved, so the amplitudes change faster than the model follows, not
    * as a contrast change does (a band-limited intensity noise of 0.15 % at 2 kHz came out as a "band over 0.000
    * periods" with 64 knots; a contamination band of 1 mm, 40-64 knots, is some 50 periods wide).
    */
  override def unsupported(c: Cand, e: SignalEngine, fMin: Double, fMax: Double): Option[String] =
    c.spec.terms.diff(e.spec.terms).collectFirst { case Term.ContrastSpline(k) if k.size >= maxKnots(e) &&
        c.params.get("band_width_periods").exists(_ < 2 * MinKnotPeriods) =>
      s"its knots reached their cap (${k.size}) with the criterion still asking for more, and its strongest band is " +
        f"${c.params("band_width_periods")}%.2g fringe periods wide, narrower than its knots resolve: the amplitudes change faster " +
        "than a contrast along the travel does (a fast amplitude modulation or intensity noise in time, or a finer structure " +
        "of the scale); a scan back over the same travel tells a change in time from one along it"
    }

  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] =
    TimeOrTravel.lookAlikes(e, Warmup.name + " or " + Drift.name) ++ TimeOrTravel.speedLookAlike(e, alongTravel = true)

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private def d(k: String) = specs.map(_.p(k, 0.0)).sum
    private val sin = Slow(gainX = d("gain_sin_per_period"), offsetX = d("offset_sin_per_period"))
    private val cos = Slow(gainX = d("gain_cos_per_period"), offsetX = d("offset_cos_per_period"))
    override def slow(isSin: Boolean): Slow = if (isSin) sin else cos
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    val l = g("travel_periods")
    if (p.contains("knots"))
      f"contrast changes along the travel: ${100 * g("band_gain_rel")}%+.3g %% over ${g("band_width_periods")}%.4g periods (at half that depth) " +
        f"centred ${g("band_at_periods")}%.4g periods from the low end of the ${l}%.0f travelled (a band: contamination of the scale, or the beam " +
        f"walking); amplitudes vary by ${100 * g("gain_sin_range_rel")}%.3g / ${100 * g("gain_cos_range_rel")}%.3g %% (sin/cos), ${g("knots").toInt} knots"
    else
      f"contrast changes along the travel: amplitudes ${100 * g("gain_sin_per_period") * l}%.3g / ${100 * g("gain_cos_per_period") * l}%.3g %%, offsets ${g("offset_sin_per_period") * l}%.3g / ${g("offset_cos_per_period") * l}%.3g full scale over the ${l}%.0f periods travelled (sin/cos)"
  }
}
