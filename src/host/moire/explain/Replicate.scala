package moire.explain

import org.hipparchus.distribution.continuous.{ChiSquaredDistribution, NormalDistribution}
import org.hipparchus.linear.{Array2DRowRealMatrix, LUDecomposition}

/** Replication (issue 12, "no stories" (b)): after the joint refit that accepts a candidate, its own parameters (and
  * the default part) are refitted separately on each half of the recording with the trajectory and all other effects
  * fixed (a few linear fits or one-parameter profiles), and the halves' estimates must agree within their
  * uncertainties. Jitter must also agree across speed bands; an interference line must keep its frequency.
  *
  * Agreement: the fold estimates' chi-square about their weighted mean, (k-1) p degrees of freedom, must stay below
  * its 99.73 % point, the two-sided 3 sd of one parameter. A real effect fails this once in 370; structure that
  * follows the motion, the contrast or the quantization rather than the catalogued physics differs between halves
  * by many sd in a long recording and fails it.
  *
  * The fit model is an approximation (a piecewise trajectory or a smoothed reference, first-order filters), so an
  * effect hundreds of sd strong agrees between the halves only as well as the model fits: each fold's uncertainty
  * has a floor, `ModelRel` of the effect's size in the signal expressed in each parameter's units (an interference
  * line's frequency has none). It matters only above 50 sd per fold; a story near the threshold (a few sd) is
  * judged by its noise alone, and one whose halves differ by tens of percent still fails.
  */
object Replicate {
  val PValue = 0.0027
  val ModelRel = 0.02
  val SpeedBands = 3

  /** None when the effect that `e.spec` has beyond `prev` replicates (or cannot be refitted on folds: faults,
    * clipping), else where and how large.
    */
  def why(e: SignalEngine, prev: ModelSpec): Option[String] = {
    val sp = e.spec
    lazy val cands = new Candidates(e)
    def parts(x: effects.Effect, d: Option[effects.Domain] = None) = splits(e, x, d)
    sp.terms.diff(prev.terms).headOption match {
      case Some(t: Term.Interference) => val (f, w) = parts(t.effect); interferenceWhy(e, t, f, w)
      case Some(t) =>
        val (f, w) = parts(t.effect, Some(t.effect.domainOf(t)))
        // contiguous halves: their levels may differ where the whole's effect says a change (interleaved parts are mixed)
        val whole = if (w == Halves) Some(e.sol.beta.slice(e.termIndex(t), e.termIndex(t) + e.termCols(t).size)) else None
        agree(linearFolds(e, t, f), w, t.name, whole)
      case None =>
        if (sp.jitter && !prev.jitter) { val (f, w) = parts(effects.Jitter); jitterWhy(e, f, w, e.slopes(), "jitter variance") }
        else if (sp.intensityNoise && !prev.intensityNoise) {
          val (f, w) = parts(effects.IntensityNoise); jitterWhy(e, f, w, e.intensitySlopes(), "intensity noise variance", radial = true)
        }
        else if (sp.phaseNoise && !prev.phaseNoise) {
          val (f, w) = parts(effects.PhaseNoise); jitterWhy(e, f, w, e.phaseSlopes(), "phase noise variance")
        }
        else if (sp.hasSkew && !prev.hasSkew) {
          val (f, w) = parts(effects.ChannelSkew)
          agree(profileFolds(e, cands, f, sp.skewS, x => sp.copy(skewS = x), math.max(math.abs(sp.skewS), 1e-10)), w, "skew")
        } else {
          // each new cut-off (both channels' when one of both was taken apart)
          val (f, w) = parts(effects.Bandwidth)
          sp.bw.filter { case (ch, _) => !prev.bw.contains(ch) }.toSeq.sortBy(_._1).iterator.map { case (ch, fc) =>
            agree(profileFolds(e, cands, f, 1 / fc, x => sp.copy(bw = sp.bw + (ch -> 1 / x)), 1 / fc), w, s"1 / cut-off ($ch)")
          }.collectFirst { case Some(why) => why }
        }
    }
  }

  /** The bins either side of a line (from, to) whose power gives the noise beside it. */
  val NearFrom = 3; val NearTo = 10

  /** Interleaved blocks per part: each part takes every other block of n / `Blocks` samples. */
  val Blocks = 64
  /** A periodic effect is split into contiguous halves when each half covers at least this many of its cycles. */
  val MinCycles = 2.0

  /** The replication parts of an effect, covering its domain, and their name: contiguous halves for effects of time (and
    * periodic effects whose cycle each half covers `MinCycles` times); interleaved blocks, so that each part covers the
    * whole cycle, for periodic effects of a record of a few cycles (one turn of a magnet), for effects of speed (each
    * part spans the speed range) and for a settling (each part covers its start); alternate fringe periods for local structure along the position (a band), so that
    * each part covers the whole travel. `d`: the domain of the term being tested, when not the effect's own.
    */
  def splits(e: SignalEngine, x: effects.Effect, d: Option[effects.Domain] = None): (Seq[Array[Int]], String) = d.getOrElse(x.domain) match {
    case effects.Domain.Periodic if x.cycles(e) >= 2 * MinCycles => (folds(e.n), Halves)
    case effects.Domain.Position => (alternatePeriods(e), "alternate fringe periods")
    case effects.Domain.Periodic | effects.Domain.Speed | effects.Domain.Settling => (interleaved(e.n), "interleaved halves")
    case _ => (folds(e.n), Halves)
  }

  /** Two parts of the samples in even and odd fringe periods of the position: each covers the whole travel. */
  def alternatePeriods(e: SignalEngine): Seq[Array[Int]] = parts(e.n)(i => math.floorMod(math.floor(e.phase(i)).toLong, 2L).toInt)

  /** Two parts of alternating blocks of n / `Blocks` samples. */
  def interleaved(n: Int): Seq[Array[Int]] = {
    val b = math.max(1, n / Blocks)
    parts(n)(i => (i / b) % 2)
  }

  /** The samples of part 0 and of part 1, in order (`part(i)` is 0 or 1), without boxing a long record's indices. */
  private def parts(n: Int)(part: Int => Int): Seq[Array[Int]] = {
    val out = Array(new Array[Int](n), new Array[Int](n)); val k = Array(0, 0); var i = 0
    while (i < n) { val p = part(i); out(p)(k(p)) = i; k(p) += 1; i += 1 }
    Seq(java.util.Arrays.copyOf(out(0), k(0)), java.util.Arrays.copyOf(out(1), k(1)))
  }

  /** An interference line: on each half its frequency (searched near the full-record value) and its amplitude on each
    * channel. A line whose frequency or amplitude differs between the halves is not a fixed-frequency pickup.
    */
  def interferenceWhy(e: SignalEngine, t: Term.Interference, halves: Seq[Array[Int]], what: String): Option[String] = {
    val cands = new Candidates(e)
    val at = e.termIndex(t); val b = e.sol.beta
    val floorA = ModelRel * 0.5 * (math.hypot(b(at), b(at + 1)) + math.hypot(b(at + 2), b(at + 3)))
    val ests = halves.map { idx =>
      val m = idx.length; val pts = Candidates.spread(m, math.max(1, m / 50000))
      // the target (the residual with the line's fitted part added back) at the search's points
      val (ys, yc) = { val w = 2 * math.Pi * t.hz / e.fs; val k = pts.length; val a = new Array[Double](k); val c = new Array[Double](k); var q = 0
        while (q < k) { val i = idx(pts(q)); val sx = math.sin(w * i); val cx = math.cos(w * i); a(q) = e.resS(i) + b(at) * sx + b(at + 1) * cx; c(q) = e.resC(i) + b(at + 2) * sx + b(at + 3) * cx; q += 1 }
        (a, c) }
      def powerOf(ys: Array[Double], yc: Array[Double], hz: Double): Double = {
        var a = 0.0; var b = 0.0; var c = 0.0; var d = 0.0; var k = 0
        while (k < pts.length) {
          val i = idx(pts(k)); val x = 2 * math.Pi * hz * i / e.fs; val sx = math.sin(x); val cx = math.cos(x)
          a += ys(k) * sx; b += ys(k) * cx; c += yc(k) * sx; d += yc(k) * cx; k += 1
        }
        -(a * a + b * b + c * c + d * d)
      }
      def power(hz: Double): Double = powerOf(ys, yc, hz)
      val half = e.fs / m
      val hz = cands.minimize(power, t.hz - half, t.hz + half, grid = 8, golden = 16)
      val (sol, rss) = lineFit(e, t, hz, idx)
      if (!sol.ok) None
      else {
        // the noise beside the line: the residual's power 3 to 10 bins either side, over white noise's (2 v per point);
        // 1/f noise or a wander under a 50 Hz line is stronger there than its mean over all frequencies, and a half's
        // line moves with it (hum on a scanned stage with 1/f noise: 50.1 against 50.0 Hz, "6.9 sd" by white noise)
        val v0 = rss / (2.0 * m)
        val near = {
          val rs = pts.map(q => e.resS(idx(q))); val rc = pts.map(q => e.resC(idx(q)))
          val fsAt = (Replicate.NearFrom to Replicate.NearTo).flatMap(k => Seq(hz - k * half, hz + k * half)).filter(f => f > 0 && f < e.fs / 2)
          if (fsAt.isEmpty || !(v0 > 0)) 1.0 else fsAt.map(f => -powerOf(rs, rc, f)).sum / fsAt.size / (2 * v0 * pts.length)
        }
        val v = v0 * math.max(1.0, near)
        val as = math.hypot(sol.beta(6), sol.beta(7)); val ac = math.hypot(sol.beta(8), sol.beta(9))
        // Cramer-Rao bound of a sinusoid's frequency at the noise beside the line, both channels' power together, for the
        // samples the search used (its subsample spans the half, so the bound grows as the root of m over their number)
        val sdF = e.fs / (2 * math.Pi) * math.sqrt(24 * v / ((as * as + ac * ac) * m.toDouble * m * m)) * math.sqrt(m.toDouble / pts.length)
        val sdA = math.sqrt(v * sol.inv(6)(6))
        Some(Est(Array(hz, as, ac), Array(Array(sdF * sdF, 0, 0), Array(0, sdA * sdA, 0), Array(0, 0, sdA * sdA)), Array(0.0, floorA, floorA)))
      }
    }
    agree(ests, what, "frequency (Hz) and amplitudes (full scale)")
  }

  /** The default part and a line at hz fitted on the samples idx to the residual with the pickup t's fitted part added
    * back, and the fit's residual sum of squares: the columns and the target made a block of samples at a time where
    * they are read (whole, they took four arrays of the record's length: at 20 M samples the run's peak heap).
    */
  private def lineFit(e: SignalEngine, t: Term.Interference, hz: Double, idx: Array[Int]): (LinSol, Double) = {
    val at = e.termIndex(t); val b = e.sol.beta; val k = 10; val gs = k * (k + 1) / 2 + k
    val w0 = 2 * math.Pi * t.hz / e.fs; val w = 2 * math.Pi * hz / e.fs
    val sums = Par.sums(idx.length, gs + 1, Gram.Block) { (lo, hi, out) =>
      val len = hi - lo
      val one = Array.fill(len)(1.0); val a1 = new Array[Double](len); val a2 = new Array[Double](len); val b1 = new Array[Double](len)
      val b2 = new Array[Double](len); val ls = new Array[Double](len); val lc = new Array[Double](len)
      val y1 = new Array[Double](len); val y2 = new Array[Double](len)
      // both lines by rotation along a run of consecutive samples, from sin and cos at its first
      val r0 = (math.sin(w0), math.cos(w0)); val r = (math.sin(w), math.cos(w))
      var s0 = 0.0; var c0 = 0.0; var s1 = 0.0; var c1 = 0.0; var q = 0
      while (q < len) {
        val i = idx(lo + q)
        if (q == 0 || i != idx(lo + q - 1) + 1) { s0 = math.sin(w0 * i); c0 = math.cos(w0 * i); s1 = math.sin(w * i); c1 = math.cos(w * i) }
        else {
          val t0 = s0 * r0._2 + c0 * r0._1; c0 = c0 * r0._2 - s0 * r0._1; s0 = t0
          val t1 = s1 * r._2 + c1 * r._1; c1 = c1 * r._2 - s1 * r._1; s1 = t1
        }
        a1(q) = e.s1(i); a2(q) = e.s2(i); b1(q) = e.c1(i); b2(q) = e.c2(i); ls(q) = s1; lc(q) = c1
        y1(q) = e.resS(i) + b(at) * s0 + b(at + 1) * c0; y2(q) = e.resC(i) + b(at + 2) * s0 + b(at + 3) * c0
        q += 1
      }
      // the columns as `baseCols` and the pickup's `termCols` order them
      Gram.block(Array(one, a1, a2, null, null, null, ls, lc, null, null), Array(null, null, null, one, b1, b2, null, null, ls, lc),
        y1, y2, null, 0, len, out)
      var yy = 0.0; q = 0
      while (q < len) { yy += y1(q) * y1(q) + y2(q) * y2(q); q += 1 }
      out(gs) = yy
    }
    val (g, r) = Gram.unpack(sums.take(gs), k)
    val sol = LinearFit.normal(g, r)
    // y'y - 2 b'X'y + b'X'X b
    var rss = sums(gs)
    for (i <- 0 until k) { rss -= 2 * sol.beta(i) * r(i); for (j <- 0 until k) rss += sol.beta(i) * g(i)(j) * sol.beta(j) }
    (sol, math.max(0.0, rss))
  }

  /** The name of contiguous halves as a split (`splits`). */
  val Halves = "halves"

  /** Contiguous halves of the record. */
  def folds(n: Int): Seq[Array[Int]] = Seq(Array.range(0, n / 2), Array.range(n / 2, n))

  /** A fold's estimate of a parameter vector, its covariance and the model-error floor of each parameter's sd. */
  final case class Est(theta: Array[Double], cov: Array[Array[Double]], floor: Array[Double])

  private def pick(a: Array[Double], idx: Array[Int]): Array[Double] = if (a == null) null else idx.map(a(_))
  private def pick(a: Array[Float], idx: Array[Int]): Array[Float] = if (a == null) null else idx.map(a(_))

  /** The term's coefficients refitted with the default part on each fold of what the term explains. A warm-up's
    * time constant stays free on each fold (one column: its fitted shape's derivative by the time constant), since
    * the later half sees only the tail, whose size depends on it.
    */
  def linearFolds(e: SignalEngine, t: Term, fs: Seq[Array[Int]]): Seq[Option[Est]] = {
    val tcols = e.termCols(t); val at = e.termIndex(t)
    val nuisance = t match {
      case Term.Warmup(tau) =>
        val b = e.sol.beta.slice(at, at + tcols.size); val h = 0.05
        val up = tau * (1 + h); val dn = tau * (1 - h)
        // the warm-up's fitted shape at tau (1 + h) less at tau (1 - h), sample by sample (its columns w, w, u w, u w)
        def d(sinCh: Boolean) = Doubles.tabulate(e.n) { i =>
          val wu = math.exp(-i / e.fs / up); val wd = math.exp(-i / e.fs / dn)
          val p = if (sinCh) b(0) * wu + b(2) * (e.us(i) * wu) else b(1) * wu + b(3) * (e.uc(i) * wu)
          val q = if (sinCh) b(0) * wd + b(2) * (e.us(i) * wd) else b(1) * wd + b(3) * (e.uc(i) * wd)
          (p - q) / (2 * h)
        }
        IndexedSeq(Col(d(true), d(false)))
      case _ => IndexedSeq.empty
    }
    val cols = e.baseCols(e.s1, e.s2, e.c1, e.c2) ++ tcols ++ nuisance
    // fitted on the residual, the term's coefficients are its change: the target (residual plus the term) needs no arrays
    val own = e.sol.beta.slice(at, at + tcols.size)
    // the term's size in the signal (rms over the record), in the units of each of its parameters
    val rms = tcols.map(c => math.sqrt(((if (c.s == null) 0.0 else e.sumSq(c.s)) + (if (c.c == null) 0.0 else e.sumSq(c.c))) / e.n))
    val size = math.sqrt(tcols.indices.map(j => math.pow(e.sol.beta(at + j) * rms(j), 2)).sum)
    val floor = rms.map(r => if (r > 0) ModelRel * size / r else 0.0).toArray
    fs.map { idx =>
      val sol = LinearFit.solve(cols, e.resS, e.resC, idx)
      if (!sol.ok) None
      else {
        val m = idx.length
        val v = LinearFit.rss(cols, sol.beta, e.resS, e.resC, idx) / math.max(1, 2 * m - cols.size)
        val k = 6 + tcols.size
        Some(Est(Array.tabulate(tcols.size)(j => sol.beta(6 + j) + own(j)), Array.tabulate(k - 6, k - 6)((a, b) => sol.inv(a + 6)(b + 6) * v), floor))
      }
    }
  }

  /** A one-parameter profile (skew, 1 / cut-off) minimised on each fold near the full-record value x0. */
  def profileFolds(e: SignalEngine, cands: Candidates, fs: Seq[Array[Int]], x0: Double, spec: Double => ModelSpec, span: Double): Seq[Option[Est]] =
    fs.map { idx =>
      val st = math.max(1, idx.length / 50000)
      val x = cands.minimize(v => cands.searched(spec(v), st, idx), x0 - span, x0 + span, grid = 8, golden = 10)
      val sd = cands.curvatureSd(v => cands.curved(spec(v), idx) * idx.length / e.n, x, math.max(span * 0.05, 1e-15))
      if (sd.isNaN || sd <= 0) None else Some(Est(Array(x), Array(Array(sd * sd)), Array(ModelRel * math.abs(x0))))
    }

  /** Jitter: the same jitter on both halves and in every speed band (noise growing with slope wherever it can show). */
  def jitterWhy(e: SignalEngine, halves: Seq[Array[Int]], what: String, sl: (Array[Double], Array[Double]), name: String,
                radial: Boolean = false): Option[String] = {
    val (ds, dc) = sl
    def est(idx: Array[Int]): Option[Est] = {
      val a = pick(ds, idx); val b = pick(dc, idx)
      val cens = if (e.cens == null) null else {
        val (ps, pc) = (pick(e.cens.pvS, idx), pick(e.cens.pvC, idx))
        Repaired(null, null, pick(e.cens.censS, idx), pick(e.cens.censC, idx), ps, pc, Option(ps).fold(0.0)(_.map(_.toDouble).sum), Option(pc).fold(0.0)(_.map(_.toDouble).sum))
      }
      val nz = Noise.fit(pick(e.resS, idx), pick(e.resC, idx), (a, b), cens)
      var info = 0.0; var i = 0
      while (i < a.length) {
        val p = a(i) * a(i) / (nz.varS + nz.jitter2 * a(i) * a(i)); val q = b(i) * b(i) / (nz.varC + nz.jitter2 * b(i) * b(i))
        info += 0.5 * (p * p + q * q); i += 1
      }
      if (info <= 0) None else Some(Est(Array(nz.jitter2), Array(Array(1 / info)), Array(ModelRel * e.noise.jitter2)))
    }
    val f = e.freq.map(math.abs); val q = OrderStats.of(e.n, f(_), (0 until SpeedBands).map(_ * e.n / SpeedBands))
    val edges = (0 to SpeedBands).map(b => if (b == SpeedBands) Double.PositiveInfinity else q(b))
    val bands = (0 until SpeedBands).map { b =>
      val out = Array.newBuilder[Int]; var i = 0
      while (i < e.n) { if (f(i) >= edges(b) && f(i) < edges(b + 1)) out += i; i += 1 }
      out.result()
    }
    agree(halves.map(est), what, name).orElse(agree(bands.map(est), "speed bands", name))
      .orElse(quantizationJitter(e, ds, dc)).orElse(PhaseWhiteness.why(e, radial))
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

  /** None when the fold estimates agree, with each other and (`whole`) their mean with the whole record's estimate;
    * else the values, the chi-square and its equivalent in sd. The parts' mean against the whole: halves that agree
    * with each other may still not say what the whole does (an offset step of 10 LSB between two flat halves is a drift
    * of 15 LSB over the record, while each half, its offset free, shows none); the mean's covariance from the parts
    * alone (the whole's own is smaller, and correlated with it) makes the test conservative.
    */
  def agree(ests: Seq[Option[Est]], what: String, name: String, whole: Option[Array[Double]] = None): Option[String] = {
    val ok0 = ests.flatten
    if (ok0.size < 2) return None
    val p = ok0.head.theta.length
    val ok = ok0.map(x => x.copy(cov = Array.tabulate(p, p)((a, b) => x.cov(a)(b) + (if (a == b) x.floor(a) * x.floor(a) else 0.0))))
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
    if (pv >= PValue) whole.filter(_.length == p).flatMap { w =>
      val d = Array.tabulate(p)(a => mean(a) - w(a))
      val chiW = (0 until p).map(a => (0 until p).map(b => d(a) * wSum(a)(b) * d(b)).sum).sum
      val pw = 1 - new ChiSquaredDistribution(p).cumulativeProbability(chiW)
      if (pw >= PValue) None
      else {
        val z = if (pw > 0) -new NormalDistribution().inverseCumulativeProbability(pw / 2) else wilsonHilferty(chiW, p)
        val sdM = inv(wSum).map(c => Array.tabulate(p)(a => math.sqrt(c(a)(a)))).getOrElse(Array.fill(p)(Double.NaN))
        val shown = if (p <= MaxShown) 0 until p else Seq((0 until p).maxBy(a => math.abs(d(a)) / sdM(a)))
        val partsV = shown.map(a => f"${mean(a)}%.3g +- ${sdM(a)}%.2g").mkString("(", ", ", ")")
        val wholeV = shown.map(a => f"${w(a)}%.3g").mkString("(", ", ", ")")
        Some(f"it does not replicate on the $what: they agree with each other, but their mean $name $partsV is not the whole record's $wholeV (chi-square $chiW%.1f for $p, $z%.1f sd)")
      }
    }
    else {
      val z = if (pv > 0) -new NormalDistribution().inverseCumulativeProbability(pv / 2) else wilsonHilferty(chi2, dof)
      // a long parameter vector (a spline's knots) is shown by the parameter whose folds disagree most
      val shown = if (p <= MaxShown) 0 until p else {
        val worst = (0 until p).maxBy(a => ok.map(x => (x.theta(a) - mean(a)) / math.sqrt(x.cov(a)(a))).map(math.abs).max)
        Seq(worst)
      }
      val vals = ok.map(x => shown.map(a => f"${x.theta(a)}%.3g +- ${math.sqrt(x.cov(a)(a))}%.2g").mkString("(", ", ", ")")).mkString(" vs ")
      val which = if (p <= MaxShown) "" else s" (parameter ${shown.head + 1} of $p, the one whose parts disagree most)"
      Some(f"it does not replicate on the $what: $name$which $vals (chi-square $chi2%.1f for $dof, $z%.1f sd)")
    }
  }

  /** Parameters shown one by one in a disagreement; a longer vector shows its worst. */
  val MaxShown = 6

  /** The sd equivalent of a chi-square far in its tail, where the p-value underflows (Wilson-Hilferty's cube root). */
  def wilsonHilferty(chi2: Double, dof: Int): Double = {
    val k = 2.0 / (9 * dof)
    (math.cbrt(chi2 / dof) - (1 - k)) / math.sqrt(k)
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
