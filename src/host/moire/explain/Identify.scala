package moire.explain

/** A change of offsets or amplitudes is a drift only when the record can tell time from the alternatives (issue 12,
  * "no stories" (c)): a change along the travel (beam walk, contamination) and a change with speed. In a scan that
  * only moves one way at an even speed, position, speed and time go together and no fit can say which it was.
  * The test: the candidate must still lower BIC by more than the threshold when the alternative is already fitted
  * (and a contrast change along the travel must do so beyond a drift in time). An alternative the record refuted
  * (`refuted`: its joint refit did not replicate on the splits of its domain) is left out: where position goes with
  * time as the square of it (a ramp), a change linear in one does not replicate on the halves of the other.
  */
object Identify {
  /** The alternatives of a change in time and of one along the travel: each other (a scan at one speed, one way). */
  val Travel = "a contrast change along the travel"
  val Time = "a drift in time"
  /** A warm-up's alternative: the linear change its slow settling is like. */
  val Linear = "a linear drift (a warm-up slower than the record, or none)"

  /** The alternative the record cannot tell the candidate from, and why (None: it can). */
  def confound(e: SignalEngine, c: Cand, refuted: Set[String] = Set.empty): Option[(String, String)] = c.spec.terms.diff(e.spec.terms).headOption match {
    case Some(t @ (Term.Drift | Term.Warmup(_))) =>
      val travel = e.spec.terms.contains(Term.Contrast) || refuted(effects.ContrastAlongTravel.name)
      // a warm-up must settle: what a linear drift predicts as well is no warm-up (a 2 % gain drift on a slow ramp, its
      // change along the travel fitted unnamed, left a curvature that came out as a warm-up of 0.08 % with 38 ms)
      val linear = t != Term.Drift && !e.spec.terms.contains(Term.Drift) && !refuted(effects.Drift.name)
      val alts = (if (travel) Nil else Seq(Travel -> (() => e.termCols(Term.Contrast)))) ++
        (if (linear) Seq(Linear -> (() => e.termCols(Term.Drift))) else Nil) :+
        ("an amplitude change with speed" -> (() => speedCols(e)))
      beyond(e, t, alts ++ fringeHarmonics(e))
    case Some(t @ (Term.Contrast | Term.ContrastSpline(_))) =>
      val inTime = e.spec.terms.exists(t => t == Term.Drift || t.isInstanceOf[Term.Warmup]) || refuted(effects.Drift.name)
      val time = if (inTime) Nil else Seq(Time -> (() => e.termCols(Term.Drift)))
      beyond(e, t, time ++ fringeHarmonics(e))
    case _ => None
  }

  /** The harmonics of the fringe (the catalogue's orders) as the alternative of a change in time or along the travel in a
    * record of a few fringe periods. Over one period (a magnetic encoder's turn) time and position are the fringe phase:
    * offsets and gains changing linearly over it are a mix of all its harmonics (t = 1/2 - sum sin(k theta) / (k pi) over
    * the period), so only what a change predicts beyond them tells it from harmonics of the fringe; over the periods
    * that split a periodic effect into contiguous halves (`Replicate.MinCycles` each) they differ.
    */
  private def fringeHarmonics(e: SignalEngine): Seq[(String, () => IndexedSeq[Col])] = {
    val orders = effects.Harmonic.Orders
    if (e.travelPeriods >= 2 * Replicate.MinCycles) Nil
    else Seq(f"harmonics ${orders.head}..${orders.last} of the fringe (the record spans ${e.travelPeriods}%.2g fringe periods)" ->
      (() => orders.flatMap(k => e.termCols(Term.Harm(k, "both"))).toIndexedSeq))
  }

  /** Amplitudes in proportion to the squared fringe frequency (the first order of any low-pass). */
  private def speedCols(e: SignalEngine): IndexedSeq[Col] = {
    var m = 0.0; var i = 0
    while (i < e.n) { m = math.max(m, math.abs(e.freq(i))); i += 1 }
    def u(i: Int) = if (m > 0) (e.freq(i) / m) * (e.freq(i) / m) else 0.0
    IndexedSeq(Col(Doubles.tabulate(e.n)(i => e.us(i) * u(i)), null), Col(null, Doubles.tabulate(e.n)(i => e.uc(i) * u(i))))
  }

  private def m2ll(e: SignalEngine, cols: IndexedSeq[Col]): Option[Double] = {
    val s = LinearFit.solve(cols, e.resS, e.resC)
    if (!s.ok) None
    else {
      if (e.cens.censS == null && e.cens.censC == null)
        Some(Noise.white(LinearFit.rss(cols, s.beta, e.resS, sinCh = true), LinearFit.rss(cols, s.beta, e.resC, sinCh = false), e.n, e.cens).m2ll)
      else {
        val rs = LinearFit.minus(e.resS, cols, s.beta, sinCh = true); val rc = LinearFit.minus(e.resC, cols, s.beta, sinCh = false)
        Some(Noise.fit(rs, rc, null, e.cens).m2ll)
      }
    }
  }

  /** The alternatives' columns are made one at a time (a long record's columns are large). */
  private def beyond(e: SignalEngine, t: Term, alts: Seq[(String, () => IndexedSeq[Col])]): Option[(String, String)] = {
    val base = e.baseCols(e.s1, e.s2, e.c1, e.c2); val own = e.termCols(t)
    alts.iterator.flatMap { case (name, make) =>
      val alt = make()
      // an alternative the record cannot fit at all (collinear with the default part) confounds nothing
      (m2ll(e, base ++ alt), m2ll(e, base ++ alt ++ own)) match {
        case (Some(a), Some(b)) =>
          val gain = a - b - t.params * e.lnN
          if (gain > SignalExplain.Threshold) None
          else Some(name -> (f"the record cannot tell it from $name: beyond that it lowers BIC by only $gain%.1f" +
            (if (name.contains("(")) "" else f" (position and time correlate, r = ${correlation(e)}%.3f)")))
        case (Some(_), None) => Some(name -> s"the record cannot tell it from $name: the two are collinear")
        case _ => None
      }
    }.nextOption()
  }

  /** Correlation of the position along the travel with time. */
  def correlation(e: SignalEngine): Double = {
    // the travel and the time from the record's middle (`e.travel`, `e.tc`) read where they are needed
    val m = e.travelMean; val mid = 0.5 * (e.n - 1)
    var sxy = 0.0; var sxx = 0.0; var syy = 0.0; var i = 0
    while (i < e.n) { val x = e.phase(i) - m; val t = (i - mid) / e.fs; sxy += x * t; sxx += x * x; syy += t * t; i += 1 }
    if (sxx > 0 && syy > 0) sxy / math.sqrt(sxx * syy) else 0.0
  }
}
