package moire.explain

import org.hipparchus.distribution.continuous.{ChiSquaredDistribution, NormalDistribution}
import org.hipparchus.linear.{Array2DRowRealMatrix, LUDecomposition}

/** Replication (issue 12, "no stories" (b)): a candidate is refitted on each half of the recording (only its own
  * parameters and the default part; the trajectory and all other effects stay fixed, so this costs a few linear fits),
  * and its fold estimates must agree within their uncertainties. Jitter must also agree across speed bands.
  *
  * Agreement: the fold estimates' chi-square about their weighted mean, (k-1) p degrees of freedom, must stay below
  * its 99.73 % point, the two-sided 3 sd of one parameter. A real effect fails this once in 370; structure that
  * follows the motion, the contrast or the quantization rather than the catalogued physics differs between halves
  * by many sd in a long recording and fails it.
  */
object Replicate {
  val PValue = 0.0027
  val SpeedBands = 3

  /** None when the candidate replicates (or cannot be refitted on folds: faults, clipping), else where and how large. */
  def why(e: SignalEngine, c: Cand, cands: Candidates): Option[String] = {
    val halves = folds(e.n)
    val newTerm = c.spec.terms.diff(e.spec.terms).headOption
    newTerm match {
      case Some(t) => agree(linearFolds(e, t, halves), "halves", t.name)
      case None =>
        if (c.spec.jitter && !e.spec.jitter) jitterWhy(e, halves)
        else if (c.spec.hasSkew && !e.spec.hasSkew)
          agree(profileFolds(e, cands, halves, c.spec.skewS, x => c.spec.copy(skewS = x), math.max(math.abs(c.spec.skewS), 1e-10)), "halves", "skew")
        else c.spec.bw.find { case (ch, _) => !e.spec.bw.contains(ch) } match {
          case Some((ch, fc)) => agree(profileFolds(e, cands, halves, 1 / fc, x => c.spec.copy(bw = c.spec.bw + (ch -> 1 / x)), 1 / fc), "halves", "1 / cut-off")
          case None => None
        }
    }
  }

  /** Contiguous halves of the record. */
  def folds(n: Int): Seq[Array[Int]] = Seq(Array.range(0, n / 2), Array.range(n / 2, n))

  /** A fold's estimate of a parameter vector and its covariance (None when the fold cannot determine it). */
  final case class Est(theta: Array[Double], cov: Array[Array[Double]])

  private def pick(a: Array[Double], idx: Array[Int]): Array[Double] = if (a == null) null else idx.map(a(_))

  /** The term's coefficients refitted with the default part on each fold of the current residual. */
  def linearFolds(e: SignalEngine, t: Term, fs: Seq[Array[Int]]): Seq[Option[Est]] = {
    val cols = e.baseCols(e.s1, e.s2, e.c1, e.c2) ++ e.termCols(t)
    fs.map { idx =>
      val cf = cols.map(c => Col(pick(c.s, idx), pick(c.c, idx)))
      val ys = pick(e.resS, idx); val yc = pick(e.resC, idx)
      val sol = LinearFit.solve(cf, ys, yc)
      if (!sol.ok) None
      else {
        val m = idx.length
        val ps = LinearFit.combine(cf, sol.beta, sinCh = true, m); val pc = LinearFit.combine(cf, sol.beta, sinCh = false, m)
        var rss = 0.0; var i = 0
        while (i < m) { val a = ys(i) - ps(i); val b = yc(i) - pc(i); rss += a * a + b * b; i += 1 }
        val v = rss / math.max(1, 2 * m - cols.size)
        val k = cols.size
        Some(Est(sol.beta.slice(6, k), Array.tabulate(k - 6, k - 6)((a, b) => sol.inv(a + 6)(b + 6) * v)))
      }
    }
  }

  /** A one-parameter profile (skew, 1 / cut-off) minimised on each fold near the full-record value x0. */
  def profileFolds(e: SignalEngine, cands: Candidates, fs: Seq[Array[Int]], x0: Double, spec: Double => ModelSpec, span: Double): Seq[Option[Est]] =
    fs.map { idx =>
      val st = math.max(1, idx.length / 50000)
      val x = cands.minimize(v => cands.profile(spec(v), st, idx), x0 - span, x0 + span, grid = 8, golden = 10)
      val sd = cands.curvatureSd(v => cands.profile(spec(v), 1, idx) * idx.length / e.n, x, math.max(span * 0.05, 1e-15))
      if (sd.isNaN || sd <= 0) None else Some(Est(Array(x), Array(Array(sd * sd))))
    }

  /** Jitter: the same jitter on both halves and in every speed band (noise growing with slope wherever it can show). */
  def jitterWhy(e: SignalEngine, halves: Seq[Array[Int]]): Option[String] = {
    val (ds, dc) = e.slopes()
    def est(idx: Array[Int]): Option[Est] = {
      val a = pick(ds, idx); val b = pick(dc, idx)
      val cens = if (e.cens == null) null else Repaired(null, null, pick(e.cens.censS, idx), pick(e.cens.censC, idx))
      val nz = Noise.fit(pick(e.resS, idx), pick(e.resC, idx), (a, b), cens)
      var info = 0.0; var i = 0
      while (i < a.length) {
        val p = a(i) * a(i) / (nz.varS + nz.jitter2 * a(i) * a(i)); val q = b(i) * b(i) / (nz.varC + nz.jitter2 * b(i) * b(i))
        info += 0.5 * (p * p + q * q); i += 1
      }
      if (info <= 0) None else Some(Est(Array(nz.jitter2), Array(Array(1 / info))))
    }
    val f = e.freq.map(math.abs); val q = f.clone(); java.util.Arrays.sort(q)
    val edges = (0 to SpeedBands).map(b => if (b == SpeedBands) Double.PositiveInfinity else q(b * e.n / SpeedBands))
    val bands = (0 until SpeedBands).map(b => (0 until e.n).filter(i => f(i) >= edges(b) && f(i) < edges(b + 1)).toArray)
    agree(halves.map(est), "halves", "jitter variance").orElse(agree(bands.map(est), "speed bands", "jitter variance"))
      .orElse(quantizationJitter(e, ds, dc))
  }

  /** Slope-dependent noise that quantization alone could make (its error variance depends on the signal value when the
    * analog noise is below about half a step) is not jitter.
    */
  private def quantizationJitter(e: SignalEngine, ds: Array[Double], dc: Array[Double]): Option[String] = {
    val nz = Noise.fit(e.resS, e.resC, (ds, dc), e.cens)
    var m = 0.0; var i = 0
    while (i < e.n) { m += ds(i) * ds(i) + dc(i) * dc(i); i += 1 }
    val jitterVar = nz.jitter2 * m / (2.0 * e.n); val q = Quantization.varianceModulation(e)
    if (jitterVar > q) None
    else Some(f"its extra variance ${jitterVar / (e.step * e.step)}%.3g step^2 at the mean slope is within what quantization makes (${q / (e.step * e.step)}%.3g step^2)")
  }

  /** None when the fold estimates agree; else the fold values, the chi-square and its equivalent in sd. */
  def agree(ests: Seq[Option[Est]], what: String, name: String): Option[String] = {
    val ok = ests.flatten
    if (ok.size < 2) return None
    val p = ok.head.theta.length
    val ws = ok.map(x => inv(x.cov))
    if (ws.exists(_.isEmpty)) return None
    val wSum = Array.tabulate(p, p)((a, b) => ws.map(_.get(a)(b)).sum)
    val rhs = Array.tabulate(p)(a => ok.indices.map(f => (0 until p).map(b => ws(f).get(a)(b) * ok(f).theta(b)).sum).sum)
    val mean = inv(wSum).map(w => Array.tabulate(p)(a => (0 until p).map(b => w(a)(b) * rhs(b)).sum)).getOrElse(return None)
    val chi2 = ok.indices.map { f =>
      val d = Array.tabulate(p)(a => ok(f).theta(a) - mean(a))
      (0 until p).map(a => (0 until p).map(b => d(a) * ws(f).get(a)(b) * d(b)).sum).sum
    }.sum
    val dof = (ok.size - 1) * p
    val pv = 1 - new ChiSquaredDistribution(dof).cumulativeProbability(chi2)
    if (pv >= PValue) None
    else {
      val z = if (pv <= 0) Double.PositiveInfinity else -new NormalDistribution().inverseCumulativeProbability(pv / 2)
      val vals = ok.map(x => x.theta.indices.map(a => f"${x.theta(a)}%.3g +- ${math.sqrt(x.cov(a)(a))}%.2g").mkString("(", ", ", ")")).mkString(" vs ")
      Some(f"it does not replicate on the $what: $name $vals (chi-square $chi2%.1f for $dof, $z%.1f sd)")
    }
  }

  private def inv(m: Array[Array[Double]]): Option[Array[Array[Double]]] = {
    val p = m.length
    val sc = Array.tabulate(p)(i => if (m(i)(i) > 0) 1 / math.sqrt(m(i)(i)) else 0.0)
    if (sc.contains(0.0)) return None
    val lu = new LUDecomposition(new Array2DRowRealMatrix(Array.tabulate(p, p)((a, b) => m(a)(b) * sc(a) * sc(b))), 1e-12)
    if (!lu.getSolver.isNonSingular) None
    else { val x = lu.getSolver.getInverse; Some(Array.tabulate(p, p)((a, b) => x.getEntry(a, b) * sc(a) * sc(b))) }
  }
}
