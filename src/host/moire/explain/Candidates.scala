package moire.explain

import moire.explain.effects._
import scala.jdk.CollectionConverters._


/** One fitted effect proposal: the model with it, its -2 ln L, extra parameters, and readable parameters. */
final case class Cand(effect: String, channel: String, spec: ModelSpec, m2ll: Double, extraK: Int,
                      params: Map[String, Double], unc: Map[String, Double], where: String)

/** Proposes and fits every catalogued effect against the engine's current state. */
final class Candidates(val engine: SignalEngine) {
  private val e = engine
  import e._

  /** The 2 % and 98 % points of the fringe frequency's magnitude. */
  val (fMin: Double, fMax: Double) = e.speedRange

  /** Linear term fitted with the default part on the current residual. */
  def linear(t: Term): Option[(Cand, LinSol)] = {
    if (spec.terms.contains(t)) return None
    val white = !spec.slopeNoise && cens.censS == null && cens.censC == null
    if (white && !FitPath.isReference) LinearFamily.of(t).foreach { case (f, ch) => return variant(t, f, ch) }
    // a long record's term made a block at a time where it is read (its columns would take as much heap as the fit)
    val gen = if (n > Candidates.SideBySide && !FitPath.isReference) termGen(t).orNull else null
    val design = new ColGroups(IndexedSeq(() => baseCols(s1, s2, c1, c2), () => termCols(t)), keep = gen == null, IndexedSeq(), IndexedSeq(null, gen))
    val s = design.solve(resS, resC)
    if (!s.ok) return None
    // without jitter or censoring only the sums of squares matter: no residual arrays
    val (nz, v) =
      if (white) {
        val (a, b) = design.rss(resS, resC, s.beta)
        (Noise.white(a, b, n, cens), (a + b) / (2.0 * n))
      } else {
        val rs = resS.clone(); val rc = resC.clone(); design.addToBoth(rs, rc, s.beta, -1.0)
        (Noise.fit(rs, rc, noiseSlopes(spec), cens), (sumSq(rs) + sumSq(rc)) / (2.0 * n))
      }
    val b = s.beta.drop(6); val sd = (6 until s.beta.length).map(i => math.sqrt(math.max(0, s.inv(i)(i)) * v)).toArray
    val (p, u, where, ch) = t.effect.describe(t, b, sd, e)
    Some((Cand(t.name, ch, spec.copy(terms = spec.terms :+ t), nz.m2ll, t.params, p, u, where), s))
  }

  /** Term t, the variant on channel `ch` of family f, from the family's sums (white noise, nothing censored). */
  private def variant(t: Term, f: Term, ch: String): Option[(Cand, LinSol)] = {
    // made outside the map's lock (its sums run on all cores; see `binned`); two searches may both make it
    val fam = Option(families.get(f)).getOrElse {
      val made = LinearFamily(baseCols(s1, s2, c1, c2) ++ termCols(f), resS, resC, yy._1, yy._2)
      Option(families.putIfAbsent(f, made)).getOrElse(made)
    }
    fromFamily(t, fam, ch)
  }

  /** A term that is linear once its nonlinear parameter is searched (a warm-up's time constant, a pickup's frequency)
    * fitted with the default part: on a long record from the screening subsample's sums (`LinearSweep`), to be fitted
    * again on all samples when it is significant there (`confirmed`); else on all samples.
    */
  def screenedLinear(t: Term): Option[Cand] = {
    val idx = screenIdx
    if (idx == null) linear(t).map(_._1)
    else LinearSweep.of(e, Seq(t), yy._1, yy._2, idx).get(t).flatMap(f => fromFamily(t, f, "both")).map(_._1)
  }

  /** Term t, the variant on channel `ch`, from its family's sums. */
  private def fromFamily(t: Term, fam: LinearFamily, ch: String): Option[(Cand, LinSol)] = {
    // the default part's columns as they are, the family's with the parts on the variant's channel
    def sin(j: Int) = j < 6 || ch != "cos"; def cos(j: Int) = j < 6 || ch != "sin"
    val use = fam.hasSin.indices.filter(j => (sin(j) && fam.hasSin(j)) || (cos(j) && fam.hasCos(j)))
    val (s, a, b) = fam.fit(use, j => sin(j) && fam.hasSin(j), j => cos(j) && fam.hasCos(j))
    if (!s.ok) return None
    val v = (a + b) / (2.0 * n)
    val bt = s.beta.drop(6); val sd = (6 until s.beta.length).map(i => math.sqrt(math.max(0, s.inv(i)(i)) * v)).toArray
    val (p, u, where, c) = t.effect.describe(t, bt, sd, e)
    Some((Cand(t.name, c, spec.copy(terms = spec.terms :+ t), Noise.white(a, b, n, cens).m2ll, t.params, p, u, where), s))
  }
  private val families = new java.util.concurrent.ConcurrentHashMap[Term, LinearFamily]()
  /** Each channel's residual sum of squares (every family's fit starts from it). */
  private lazy val yy = (sumSq(resS), sumSq(resC))

  /** a less the prediction of the channel whose repaired data and residual are (rp, rr). */
  private def sub(a: Array[Double], rp: Array[Double], rr: Array[Double]) = Doubles.tabulate(n)(i => a(i) - (rp(i) - rr(i)))
  /** The noise model of repaired data `r` against the engine's prediction (read where it is needed): with white noise
    * from the sums of squares alone (no residual arrays: a long record's candidate would hold two more).
    */
  private def repairedNoise(r: Repaired): Noise = {
    val slopes = noiseSlopes(spec)
    if (slopes != null) return Noise.fit(sub(r.s, repS, resS), sub(r.c, repC, resC), slopes, r)
    def ss(a: Array[Double], rp: Array[Double], rr: Array[Double]) =
      Par.sum(n) { (lo, hi) => var z = 0.0; var i = lo; while (i < hi) { val d = a(i) - (rp(i) - rr(i)); z += d * d; i += 1 }; z }
    Noise.fromSums(ss(r.s, repS, resS), ss(r.c, repC, resC), n, r)
  }

  def all(onStep: () => Unit): Seq[Cand] = {
    val timing = sys.props.contains("moire.timing")
    // the linear families whose columns are a function of the sample, from one pass (their searches read them off)
    // (a long record's on a spread subsample: see `confirmed`)
    val white = !spec.slopeNoise && cens.censS == null && cens.censC == null && !FitPath.isReference
    val screen = white && n > Candidates.ScreenAbove
    yy // made here, not in a search side by side (a lazy value's lock held across work on all cores: see `binned`)
    screenIdx = if (screen) Candidates.spread(n, n / Candidates.ScreenSamples) else null
    if (white) {
      val t0 = System.nanoTime()
      val idx = screenIdx
      LinearSweep.of(e, LinearSweep.terms(effects.Harmonic.Orders), yy._1, yy._2, idx).foreach { case (t, f) => families.put(t, f) }
      if (timing) System.err.println(f"candidate linear-sweep ${(System.nanoTime() - t0) / 1e6}%.0f ms")
    }
    val found = new Array[Seq[Cand]](searches.size)
    def run(k: Int): Unit = {
      val (name, search) = searches(k); val t0 = System.nanoTime()
      try found(k) = search() finally onStep.synchronized(onStep())
      if (timing) System.err.println(f"candidate $name ${(System.nanoTime() - t0) / 1e6}%.0f ms")
    }
    // the searches read the engine and write nothing of it: side by side on all cores, each into its own slot (the
    // same candidates in the same order as one after the other); a long record's one at a time (each holds columns)
    if (FitPath.isReference || n > Candidates.SideBySide) searches.indices.foreach(run)
    else {
      // a search's failure is kept and thrown after all ran (the first in the searches' order, as one after the other)
      val failed = new Array[Throwable](searches.size)
      java.util.stream.IntStream.range(0, searches.size).parallel().forEach(k => try run(k) catch { case x: Throwable => failed(k) = x })
      failed.find(_ != null).foreach(x => throw x)
    }
    if (screen) confirmed(found.toSeq.flatten, (n / Candidates.ScreenSamples).toDouble) else found.toSeq.flatten
  }

  /** The screening subsample of a long record's round (null: candidates are fitted on all samples). */
  @volatile private var screenIdx: Array[Int] = null

  /** The linear candidates screened on a subsample of every `st`-th sample's worth: those that lower BIC there (on the
    * subsample's own count) fitted again on all samples (their families in one more pass; a warm-up or a pickup line
    * at its searched time constant or frequency on its own), the rest dropped (kept with no gain: not significant on a
    * million samples, they are not material on more). Others as they are.
    */
  private def confirmed(cands: Seq[Cand], st: Double): Seq[Cand] = {
    val base = e.noise.m2ll
    def term(c: Cand) = c.spec.terms.lastOption.filter(t => c.spec.terms.size == spec.terms.size + 1 && Candidates.screened(t))
    // the candidate's gain on the subsample (its estimate is the subsample's scaled by st) against its own criterion there
    def significant(c: Cand) = (base - c.m2ll) / st - c.extraK * math.log(2.0 * n / st) > SignalExplain.Threshold
    val need = cands.filter(c => term(c).isDefined && significant(c)).flatMap(term)
    // the subsample's families go (a later `linear` makes its own on all samples); those needed, from all samples
    families.clear()
    if (need.nonEmpty) Laps("candidates: confirmed on all samples") {
      val fams = need.flatMap(t => LinearFamily.of(t).map(_._1)).distinct
      if (sys.props.contains("moire.timing")) System.err.println(s"candidate confirm ${need.distinct.mkString(", ")}")
      if (fams.nonEmpty) LinearSweep.of(e, fams, yy._1, yy._2).foreach { case (t, f) => families.put(t, f) }
    }
    cands.map { c =>
      term(c) match {
        // the fit on all samples; what only the search knows (a warm-up's time constant's uncertainty) is kept
        case Some(t) if need.contains(t) => Laps("candidates: confirmed on all samples")(linear(t)).map(x => if (LinearFamily.of(t).isDefined) x._1 else x._1.copy(unc = c.unc ++ x._1.unc.filter(!_._2.isNaN)))
          .getOrElse(c.copy(m2ll = base))
        case Some(_) => c.copy(m2ll = base)
        case None => c
      }
    }
  }
  /** The registry's searches for this record: one progress step each. */
  lazy val searches: Seq[(String, () => Seq[Cand])] = Effects.all.filter(_.searched).flatMap(f => f.searches(this).map(f.name -> _))
  def steps: Int = searches.size
  /** The reference names the mechanical angle and a turn holds enough fringe periods to tell its modulation from
    * harmonics of the fringe (with one period per turn they are the same thing).
    */
  def mechanical: Boolean = e.periodsPerTurn.exists(_ >= 3) && e.mechAngle.isDefined

  // ---- nonlinear: skew and bandwidth, by profile likelihood over one parameter ----

  /** -2 ln L (white noise per channel) of the default part refitted with modified fundamentals, on every stride-th sample
    * (of `idx` when given: a fold), scaled to n.
    */
  def profile(sp: ModelSpec, stride: Int, idx: Array[Int] = null): Double = Laps("profile: every sample") {
    val (ms, mc, cnt) = profileSums(sp, stride, idx)
    whiteM2ll(Candidates.rss(ms) / cnt, Candidates.rss(mc) / cnt)
  }

  /** The normal equations of each channel's default part (offset, the two fundamentals under `sp`) on every stride-th
    * sample (of `idx` when given), 10 sums per channel (see `Candidates.rss`), and the count of points.
    */
  private def profileSums(sp: ModelSpec, stride: Int, idx: Array[Int]): (Array[Double], Array[Double], Int) = {
    val resp = new ChannelResponse(sp)
    def acc(m: Array[Double], at: Int, x1: Double, x2: Double, y: Double): Unit = {
      m(at) += 1; m(at + 1) += x1; m(at + 2) += x2; m(at + 3) += x1 * x1; m(at + 4) += x1 * x2; m(at + 5) += x2 * x2
      m(at + 6) += y; m(at + 7) += y * x1; m(at + 8) += y * x2; m(at + 9) += y * y
    }
    val end = if (idx == null) n else idx.length
    val cnt = (end + stride - 1) / stride
    // the points in blocks on all cores: from the kept points, or (too many to keep) made where they are read
    // kept points serve the many calls of a search; one call on every sample (the fast path's) reads them where they are
    val keep = keeps(cnt) && (FitPath.isReference || stride > 1 || { val c = cached; c != null && c.version == e.version && c.stride == stride && (c.idx eq idx) })
    val sums = if (keep) {
      val pts = points(stride, idx)
      Par.sums(cnt, 20) { (lo, hi, m) =>
        val o = new Array[Double](4); var q = lo
        while (q < hi) {
          resp(pts.f(q), pts.sn(q), pts.cs(q), o)
          acc(m, 0, o(0), o(1), pts.ys(q))
          acc(m, 10, o(2), o(3), pts.yc(q))
          q += 1
        }
      }
    } else Par.sums(cnt, 20) { (lo, hi, m) =>
      val o = new Array[Double](4); val sc = new Array[Double](2); var q = lo
      val ref = FitPath.isReference // a thread-local lookup: once a block, not at every sample
      while (q < hi) {
        val k = q * stride; val i = if (idx == null) k else idx(k)
        if (ref) { val a = angle(i); sc(0) = math.sin(a); sc(1) = math.cos(a) } else Turns.sinCos(turn(i), sc, 0)
        resp(freq(i), sc(0), sc(1), o)
        acc(m, 0, o(0), o(1), repS(i) - termS(i))
        acc(m, 10, o(2), o(3), repC(i) - termC(i))
        q += 1
      }
    }
    (sums.slice(0, 10), sums.slice(10, 20), cnt)
  }

  /** The profile a search minimises: from the binned sums of all samples (of the fold `idx`); on the reference path,
    * `profile` on every stride-th sample.
    */
  def searched(sp: ModelSpec, stride: Int, idx: Array[Int] = null): Double =
    if (FitPath.isReference) profile(sp, stride, idx) else fromBins(sp, idx).getOrElse(profile(sp, stride, idx))
  /** The profile a curvature is taken from: the binned sums (the reference path: every sample). */
  def curved(sp: ModelSpec, idx: Array[Int] = null): Double =
    if (FitPath.isReference) profile(sp, 1, idx) else fromBins(sp, idx).getOrElse(profile(sp, 1, idx))
  /** The binned profile, or None where its bins are too coarse for the spec's response. */
  private def fromBins(sp: ModelSpec, idx: Array[Int]): Option[Double] = {
    val b = binned(idx)
    Some(Laps("profile: from the bins")(b.m2ll(sp))).filter(!_.isNaN)
  }

  /** The binned profile sums of the engine's state on all samples (or the fold `idx`), made once per state and fold. */
  def binned(idx: Array[Int] = null): ProfileSums = {
    val k = if (idx == null) Candidates.AllSamples else idx
    // the first search to ask makes them, outside the lock: they are made on all cores, and a search that waited on a
    // lock held across that work would hold the pool's only worker on a 2-core machine (a deadlock); a search that
    // asks meanwhile waits on the result, which lets the pool add a worker
    val (f, mine) = sums.synchronized {
      sums.get(k).filter(_._1 == e.version) match {
        case Some((_, f)) => (f, false)
        case None => val f = new java.util.concurrent.CompletableFuture[ProfileSums](); sums.put(k, (e.version, f)); (f, true)
      }
    }
    if (mine) try f.complete(Laps("profile: binned sums")(new ProfileSums(e, idx))) catch { case x: Throwable => f.completeExceptionally(x); throw x }
    try f.join() catch { case x: java.util.concurrent.CompletionException if x.getCause != null => throw x.getCause }
  }
  private val sums = new java.util.IdentityHashMap[Array[Int], (Long, java.util.concurrent.CompletableFuture[ProfileSums])]().asScala

  /** What `profile` reads at its points (every stride-th sample, of `idx` when given): the fringe frequency, the sin and
    * cos of the fringe phase, each channel less its terms. Made once for the engine's state (its `version`) while the
    * points fit in 2^21 samples: a search calls the profile some thirty times with the same points.
    */
  private final class Points(val version: Long, val stride: Int, val idx: Array[Int], val f: Array[Double], val sn: Array[Double],
                             val cs: Array[Double], val ys: Array[Double], val yc: Array[Double])
  private var cached: Points = null
  private def points(stride: Int, idx: Array[Int]): Points = {
    val c = cached
    if (c != null && c.version == e.version && c.stride == stride && (c.idx eq idx)) return c
    val end = if (idx == null) n else idx.length
    val cnt = (end + stride - 1) / stride
    def at(q: Int) = { val k = q * stride; if (idx == null) k else idx(k) }
    val f = new Array[Double](cnt); val sn = new Array[Double](cnt); val cs = new Array[Double](cnt)
    val ys = new Array[Double](cnt); val yc = new Array[Double](cnt)
    Par.blocks(cnt) { (lo, hi) =>
      var q = lo
      while (q < hi) {
        val i = at(q); val a = angle(i)
        f(q) = freq(i); sn(q) = math.sin(a); cs(q) = math.cos(a); ys(q) = repS(i) - termS(i); yc(q) = repC(i) - termC(i)
        q += 1
      }
    }
    val p = new Points(e.version, stride, idx, f, sn, cs, ys, yc)
    cached = p
    p
  }
  /** Points are made and kept when they fit in 2^21 samples; beyond, each profile makes them where it reads them. */
  private def keeps(cnt: Int): Boolean = cnt <= (1 << 21)

  /** Minimum of f on [lo, hi]: a grid, then Brent's method (golden sections and parabolas) around the best grid point,
    * to the bracket `golden` golden sections would leave there (0.618^golden of it). The profiles searched are smooth
    * there: the parabolas get to that bracket in fewer calls (see `minimizeAt`).
    */
  def minimize(f: Double => Double, lo: Double, hi: Double, grid: Int = 12, golden: Int = 14): Double = minimizeAt(f, lo, hi, grid, golden)._1

  /** `minimize` and f at the minimum. The joint search's lines at 1 M samples (30 golden sections before): 4,583
    * binned profiles a bench explain, 2,963 with the parabolas to the same bracket.
    */
  def minimizeAt(f: Double => Double, lo: Double, hi: Double, grid: Int = 12, golden: Int = 14): (Double, Double) = {
    import org.hipparchus.optim.{MaxEval, nonlinear}, org.hipparchus.optim.univariate._
    val xs = (0 to grid).map(k => lo + (hi - lo) * k / grid); val fs = xs.map(f)
    val best = fs.indices.minBy(fs)
    val a = xs(math.max(0, best - 1)); val b = xs(math.min(grid, best + 1))
    // Brent's method stops with its bracket within 4 x its absolute tolerance
    val tol = math.pow(Candidates.GoldenRatio, golden) * (b - a) / 4
    val r = if (!(tol > 0)) null else try new BrentOptimizer(1e-14, tol).optimize(new MaxEval(10 * golden + 20), new UnivariateObjectiveFunction(x => f(x)),
      nonlinear.scalar.GoalType.MINIMIZE, new SearchInterval(a, b, xs(best))) catch { case _: org.hipparchus.exception.MathRuntimeException => null }
    if (r != null && r.getValue < fs(best)) (r.getPoint, r.getValue) else (xs(best), fs(best))
  }

  /** The nonlinear parameters of `sp0` (skew, each channel's 1 / cut-off) minimised together on the profile (`searched`
    * on every `st`-th sample). A channel's low-pass delays it as a skew does, and two channels' low-passes share a
    * delay the phase trajectory takes up: the parameters lie along valleys of the profile. One at a time, the first
    * one found took the other's part of the delay, and a search of the other with it held there found little (a
    * 700 kHz low-pass on sin with cos 20 ns late: 638 kHz, 2 ns and a contrast along the travel for what was left).
    * Powell's method: each turn minimises along every direction of a set (at first each parameter's own) over the
    * whole range, then along the turn's move, which replaces the direction that gained most (the set comes to follow
    * the valleys); until a turn lowers the profile by less than 0.5 (at most `Candidates.MaxTurns`). Returns the spec
    * and how much it lowered the profile.
    */
  def joint(sp0: ModelSpec, st: Int, gains: Boolean = false): (ModelSpec, Double) = {
    val chs = sp0.bw.keys.toSeq.sorted; val sk = if (sp0.hasSkew) 1 else 0
    val nb = sk + chs.size; val dims = nb + (if (gains) 2 else 0)
    if (dims == 0) return (sp0, 0.0)
    def specOf(v: Array[Double]): ModelSpec = {
      val s = if (sp0.hasSkew) sp0.copy(skewS = v(0)) else sp0
      val g = if (gains) (v(nb), v(nb + 1)) else s.gainPerHz
      s.copy(bw = s.bw ++ chs.indices.map(k => chs(k) -> 1 / v(sk + k)), gainPerHz = g)
    }
    val limit = 0.5 / (2 * math.Pi * math.max(fMax, 1))
    val v = Array.tabulate(dims)(d => if (d < sk) sp0.skewS else if (d < nb) 1 / sp0.bw(chs(d - sk)) else if (d == nb) sp0.gainPerHz._1 else sp0.gainPerHz._2)
    // each parameter's range: the skew's as its search's, a cut-off from 50 x to 0.2 x the highest fringe frequency, a
    // gain per hertz up to 30 % at the highest
    val gMax = 0.3 / math.max(fMax, 1)
    val lo = Array.tabulate(dims)(d => math.min(v(d), if (d < sk) -limit else if (d < nb) 1 / (50 * math.max(fMax, 1)) else -gMax))
    val hi = Array.tabulate(dims)(d => math.max(v(d), if (d < sk) limit else if (d < nb) 5 / math.max(fMax, 1) else gMax))
    def f(x: Array[Double]): Double = searched(specOf(x), st)
    val f0 = f(v); var cur = f0
    // v moved along direction d to the profile's minimum within the ranges, where that lowers it; the gain
    def line(d: Array[Double]): Double = {
      var a = Double.NegativeInfinity; var b = Double.PositiveInfinity; var q = 0
      while (q < dims) {
        if (d(q) != 0) { val t1 = (lo(q) - v(q)) / d(q); val t2 = (hi(q) - v(q)) / d(q); a = math.max(a, math.min(t1, t2)); b = math.min(b, math.max(t1, t2)) }
        q += 1
      }
      if (!(b > a)) return 0.0
      val at = (t: Double) => Array.tabulate(dims)(r => math.min(hi(r), math.max(lo(r), v(r) + t * d(r))))
      val (best, fb) = minimizeAt(t => f(at(t)), a, b, golden = 30); val x = at(best)
      if (fb < cur) { val g = cur - fb; System.arraycopy(x, 0, v, 0, dims); cur = fb; g } else 0.0
    }
    val dirs = Array.tabulate(dims, dims)((p, q) => if (p == q) 1.0 else 0.0)
    var gain = Double.PositiveInfinity; var k = 0
    while (k < Candidates.MaxTurns && gain > 0.5) {
      val start = cur; val before = v.clone()
      var most = 0; var mostGain = -1.0
      for (p <- 0 until dims) { val g = line(dirs(p)); if (g > mostGain) { mostGain = g; most = p } }
      val d = Array.tabulate(dims)(q => v(q) - before(q))
      if (dims > 1 && d.exists(_ != 0)) {
        line(d)
        // the move replaces the direction that gained most (Powell's rule: the set stays spanning)
        dirs(most) = dirs(dims - 1); dirs(dims - 1) = d
      }
      gain = start - cur; k += 1
      if (SignalEngine.debug) System.err.println(f"joint: turn $k ${v.map(x => f"$x%.4g").mkString(" ")} gain $gain%.1f")
    }
    (specOf(v), f0 - cur)
  }

  /** Crosstalk with the skew and cut-offs searched with it. Its linear candidate holds them where they are, and a
    * low-pass found first has taken the amplitude's change with speed that crosstalk makes (sin += 5 ns x d(cos)/dt
    * with sin at 800 kHz: a cut-off of 742 kHz, then a skew of -12.6 ns rather than the crosstalk). On the profile
    * crosstalk is each channel's gain growing in proportion to the fringe frequency (its part is the other channel's
    * derivative, in phase with the channel's own fundamental): the two gains are searched together with the skew and
    * cut-offs, and the candidate is the crosstalk term at the skew and cut-offs found, ranked by that profile. Tried
    * only where the spec has a skew or cut-off and the held candidate `held` (-2 ln L) is significant.
    */
  def crosstalkJoint(held: Option[Cand]): Option[Cand] = {
    if ((!spec.hasSkew && spec.bw.isEmpty) || spec.terms.contains(Term.Crosstalk) || fMax <= 0) return None
    if (!held.exists(c => bic - (c.m2ll + (params + c.extraK) * lnN) > SignalExplain.Threshold)) return None
    val (sp, _) = joint(spec, stride, gains = true)
    val m2ll = fullM2ll(sp, profile(sp, 1))
    if (!(m2ll < held.get.m2ll)) return None
    val (kS, kC) = sp.gainPerHz
    // the gain per hertz back to each channel's tau: sin += tau_sc d(cos)/dt takes -2 pi tau_sc A_cos / A_sin per hertz
    val p = Map("sin_from_cos_tau_s" -> -kS * ampS / (2 * math.Pi * math.max(ampC, 1e-12)), "cos_from_sin_tau_s" -> kC * ampC / (2 * math.Pi * math.max(ampS, 1e-12)))
    Some(Cand(Crosstalk.name, "both", sp.copy(gainPerHz = (0.0, 0.0), terms = sp.terms :+ Term.Crosstalk), m2ll, 2, p,
      p.map { case (k, _) => k -> Double.NaN }, "against speed: amplitude of each channel, with the skew and cut-offs searched again"))
  }

  /** Standard deviation of a profile parameter from the curvature of -2 ln L (full data). */
  def curvatureSd(f: Double => Double, x: Double, h0: Double): Double = {
    var h = h0; var sd = Double.NaN
    for (_ <- 0 until 2) {
      val c = (f(x + h) - 2 * f(x) + f(x - h)) / (h * h)
      if (c > 0) { sd = math.sqrt(2 / c); h = sd } else return Double.NaN
    }
    sd
  }

  /** Full -2 ln L of a spec with modified fundamentals (current noise model), with the fitted default part. */
  def fullM2ll(sp: ModelSpec, white: => Double): Double = {
    // white noise, nothing censored: the streaming profile on every sample is the same fit, without arrays (`white`)
    if (!sp.slopeNoise && cens.censS == null && cens.censC == null) return white
    if (!FitPath.isReference) return Laps("profile: full -2 ln L")(streamedM2ll(sp))
    val a1 = new Array[Double](n); val a2 = new Array[Double](n); val b1 = new Array[Double](n); val b2 = new Array[Double](n)
    fundamentals(sp, a1, a2, b1, b2)
    val cols = baseCols(a1, a2, b1, b2)
    val ts = Doubles.tabulate(n)(i => repS(i) - termS(i)); val tcc = Doubles.tabulate(n)(i => repC(i) - termC(i))
    val s = LinearFit.solve(cols, ts, tcc)
    LinearFit.addTo(ts, cols, s.beta, sinCh = true, -1.0); LinearFit.addTo(tcc, cols, s.beta, sinCh = false, -1.0) // now the residual
    Noise.fit(ts, tcc, noiseSlopes(sp), cens).m2ll
  }

  /** `fullM2ll` from the profile's sums on every sample: the same least squares, its columns made where they are read.
    * White noise: -2 ln L from the residual's sums of squares (the censored samples' terms as the full fit's). Noise
    * growing with a slope: the residual made (two arrays of the record's length, not the six of the columns and data:
    * at 20 M samples those were 960 MB on top of the fit's own) and the noise model fitted to it.
    */
  private def streamedM2ll(sp: ModelSpec): Double = {
    val (ms, mc, _) = profileSums(sp, 1, null)
    if (!sp.slopeNoise) return Noise.fromSums(Candidates.rss(ms), Candidates.rss(mc), n, cens).m2ll
    val bs = Candidates.coefficients(ms); val bc = Candidates.coefficients(mc)
    val resp = new ChannelResponse(sp)
    val rs = new Array[Double](n); val rc = new Array[Double](n)
    Par.blocks(n) { (lo, hi) =>
      val o = new Array[Double](4); val sc = new Array[Double](2); var i = lo
      while (i < hi) {
        Turns.sinCos(turn(i), sc, 0); resp(freq(i), sc(0), sc(1), o)
        rs(i) = repS(i) - termS(i) - (bs(0) + bs(1) * o(0) + bs(2) * o(1))
        rc(i) = repC(i) - termC(i) - (bc(0) + bc(1) * o(2) + bc(2) * o(3))
        i += 1
      }
    }
    Noise.fit(rs, rc, noiseSlopes(sp), cens).m2ll
  }

  private def stride: Int = math.max(1, n / 50000)

  /** Skew between the channels: needs several speeds, else it is a phase error. */
  def skew(): Option[Cand] = {
    if (spec.hasSkew) return None
    // the fundamentals' derivative by the skew as one more column, made a block at a time where the fit reads it (not
    // two arrays of the record's length: 320 MB at 20 M samples); the same numbers as the fit on the whole column
    val dSkew = new ColGen(Array(true), Array(true), (lo, hi, o, at) => {
      var i = lo
      while (i < hi) { val q = at + i - lo; o(0)(q) = -math.Pi * freq(i) * vs(i); o(1)(q) = math.Pi * freq(i) * vc(i); i += 1 }
    })
    val base = baseCols(s1, s2, c1, c2)
    val s = new ColGroups(IndexedSeq(() => base, () => IndexedSeq(Col(null, null))), keep = false, IndexedSeq(false, false), IndexedSeq(null, dSkew))
      .solve(resS, resC)
    if (!s.ok) return None
    val sd0 = math.sqrt(s.inv(6)(6) * (sumSq(resS) + sumSq(resC)) / (2.0 * n))
    val t0 = s.beta(6); val span = 6 * sd0 + 0.3 * math.abs(t0)
    val limit = 0.5 / (2 * math.Pi * math.max(fMax, 1))
    val lo = math.max(-limit, t0 - span); val hi = math.min(limit, t0 + span)
    if (!(hi > lo)) return None
    val tau0 = minimize(x => searched(spec.copy(hasSkew = true, skewS = x), stride), lo, hi)
    // with a low-pass in the spec, the two share the delay (`joint`)
    val sp = if (spec.bw.isEmpty) spec.copy(hasSkew = true, skewS = tau0) else joint(spec.copy(hasSkew = true, skewS = tau0), stride)._1
    val tau = sp.skewS
    val full = Candidates.memo(x => profile(sp.copy(skewS = x), 1))
    val sd = curvatureSd(if (FitPath.isReference) full else x => curved(sp.copy(skewS = x)), tau, math.max(sd0, 1e-12))
    val (p, u, where) = (Map("skew_s" -> tau), Map("skew_s" -> sd), f"against speed: cos channel phase, ${fMin / 1e3}%.1f to ${fMax / 1e3}%.1f kHz")
    Some(Cand(ChannelSkew.name, "cos", sp, fullM2ll(sp, full(tau)), 1, p, u, where))
  }

  /** First-order low-pass on one channel or both, searched over 1 / cut-off. */
  def bandwidth(ch: String): Option[Cand] = {
    if (spec.bw.contains(ch) || fMax <= 0 || (fMax - fMin) < 0.05 * fMax) return None
    val fromBoth = bandwidthOf(ch)
    if (ch == "both") fromBoth.map(rankedAsEach) else (fromBoth.toSeq ++ splitBandwidth(ch)).sortBy(_.m2ll).headOption
  }

  /** The first low-pass of both channels ranked by the better of itself and one on each channel (searched together,
    * one parameter more): where the channels' cut-offs differ, the common one alone fits less than crosstalk or a
    * drift do (sin 750 kHz, cos 600 kHz: crosstalk 454,000 against 395,000 of BIC), and that was found instead. It
    * is still the common low-pass that is fitted and judged; the next round takes it apart (`splitBandwidth`).
    */
  private def rankedAsEach(c: Cand): Cand = if (spec.bw.nonEmpty || !apart(c.spec)) c else {
    val fb = c.spec.bw("both")
    val sp = joint(spec.copy(bw = Map("sin" -> fb, "cos" -> fb)), stride)._1
    val m2ll = fullM2ll(sp, profile(sp, 1))
    // the lower cut-off alone (a low-pass on one channel, its own candidate) must not fit as well: a 700 kHz low-pass
    // on sin alone with cos 20 ns late ranked the common one first, which was found at 12 MHz;
    // and the higher cut-off must lower the amplitude within the fringe frequencies (below 10 x the highest): one far
    // above shows as the delay of a skew (with cos 20 ns late, cos took a cut-off of 8 MHz there)
    val low = if (sp.bw("sin") <= sp.bw("cos")) "sin" else "cos"
    lazy val one = joint(spec.copy(bw = Map(low -> sp.bw(low))), stride)._1
    if (sp.bw.values.max < 10 * fMax && m2ll + lnN < c.m2ll && m2ll + lnN < fullM2ll(one, profile(one, 1))) c.copy(m2ll = m2ll, extraK = 2) else c
  }

  /** The low-pass of both channels found before taken apart into one on each, searched together (with the skew when
    * there is one): the channels' cut-offs differ. A low-pass added on one channel behind the common one is two in
    * series there, and a first-order low-pass of its own is not that: a sin at 650 kHz and cos at 600 kHz came out
    * as both at 650 kHz, cos at 1.65 MHz more (the same amplitudes, 5.6 degrees more lag at 200 kHz), a skew of 78 ns
    * to take the lag back and a warm-up. The candidate is the cos channel's (the common one becomes the sin channel's,
    * `Bandwidth.refresh`); it is tried beside the one in series, and the better fit is the channel's candidate.
    */
  private def splitBandwidth(ch: String): Option[Cand] = {
    if (ch != "cos" || spec.bw.keySet != Set("both") || !apart(spec)) return None
    val fb = spec.bw("both")
    val sp = joint(spec.copy(bw = Map("sin" -> fb, "cos" -> fb)), stride)._1
    val fc = sp.bw("cos"); val xs = 1 / fc
    val full = Candidates.memo(x => profile(sp.copy(bw = sp.bw + ("cos" -> 1 / x)), 1))
    val sdx = curvatureSd(if (FitPath.isReference) full else x => curved(sp.copy(bw = sp.bw + ("cos" -> 1 / x))), xs, xs * 0.05)
    Some(Cand(Bandwidth.name, "cos", sp, fullM2ll(sp, full(xs)), 1, Map("cutoff_hz" -> fc), Map("cutoff_hz" -> sdx / (xs * xs)),
      "against speed: cos channel amplitude and phase, its own cut-off beside the sin channel's"))
  }

  /** Whether the common low-pass of `sp` taken apart gains: the binned profile along the two cut-offs moving apart
    * (1 / cut-off up on one channel as much as down on the other) lowers -2 ln L by more than one parameter's BIC
    * and the threshold. A screen: the searches of the candidates above cost some 0.3 s a round at 1 M samples, and
    * a low-pass the same on both channels (the bench's) does not gain there.
    */
  private def apart(sp: ModelSpec): Boolean = {
    val x = 1 / sp.bw("both")
    def at(d: Double) = sp.copy(bw = sp.bw - "both" + ("sin" -> 1 / (x * (1 + d))) + ("cos" -> 1 / (x * (1 - d))))
    val f0 = searched(at(0), stride)
    val d = minimize(d => searched(at(d), stride), -0.9, 0.9, grid = 18, golden = 20)
    f0 - searched(at(d), stride) > lnN + SignalExplain.Threshold
  }

  private def bandwidthOf(ch: String): Option[Cand] = {
    val hiX = 5 / fMax
    val xs0 = minimize(x => searched(spec.copy(bw = spec.bw + (ch -> (if (x <= 0) Double.PositiveInfinity else 1 / x))), stride), 0, hiX, grid = 16)
    // a cut-off far above the fringe frequencies shows only as a delay, which is a skew, not a bandwidth
    if (xs0 <= 1 / (50 * fMax)) return None
    // with a skew or another low-pass in the spec, they share the delay (`joint`)
    val sp0 = spec.copy(bw = spec.bw + (ch -> 1 / xs0))
    val sp = if (!spec.hasSkew && spec.bw.isEmpty) sp0 else joint(sp0, stride)._1
    val fc = sp.bw(ch); val xs = 1 / fc
    val full = Candidates.memo(x => profile(sp.copy(bw = sp.bw + (ch -> 1 / x)), 1))
    val sdx = curvatureSd(if (FitPath.isReference) full else x => curved(sp.copy(bw = sp.bw + (ch -> 1 / x))), xs, xs * 0.05)
    val (p, u, where) = (Map("cutoff_hz" -> fc), Map("cutoff_hz" -> sdx / (xs * xs)),
      s"against speed: ${if (ch == "both") "amplitude of both channels" else s"$ch channel amplitude and phase"}")
    Some(Cand(Bandwidth.name, ch, sp, fullM2ll(sp, full(xs)), 1, p, u, where))
  }

  /** Noise variance growing with a slope (ds, dc): the fitted scale (rms of the slope's factor), its sd from the Fisher
    * information, the white noise left (full scale rms) and -2 ln L; None when the slope adds no variance.
    */
  private def slopeNoise(ds: Array[Double], dc: Array[Double]): Option[(Double, Double, Double, Double)] = {
    val nz = Noise.fit(resS, resC, (ds, dc), cens)
    if (nz.jitter2 <= 0) return None
    val info = Par.sum(n) { (lo, hi) =>
      var f = 0.0; var i = lo
      while (i < hi) {
        val a = ds(i) * ds(i) / (nz.varS + nz.jitter2 * ds(i) * ds(i)); val b = dc(i) * dc(i) / (nz.varC + nz.jitter2 * dc(i) * dc(i))
        f += 0.5 * (a * a + b * b); i += 1
      }
      f
    }
    val r = math.sqrt(nz.jitter2)
    Some((r, (1 / math.sqrt(info)) / (2 * r), math.sqrt(0.5 * (nz.varS + nz.varC)), nz.m2ll))
  }

  /** A long record's slope noise screened on the round's subsample (as its linear candidates): false when the slope's
    * variance does not lower BIC there on the subsample's own count, and the search on all samples is left out (not
    * significant on a million samples, it is not material on more).
    */
  private def passesScreen(ds: Int => Double, dc: Int => Double): Boolean = {
    val idx = screenIdx
    if (idx == null) return true
    val m = idx.length
    def pick(f: Int => Double) = Doubles.tabulate(m)(q => f(idx(q)))
    val rs = pick(resS(_)); val rc = pick(resC(_))
    val white = Noise.fit(rs, rc, null); val sloped = Noise.fit(rs, rc, (pick(ds), pick(dc)))
    sloped.jitter2 > 0 && white.m2ll - sloped.m2ll - math.log(2.0 * m) > SignalExplain.Threshold
  }

  def jitter(): Option[Cand] = {
    if (spec.slopeNoise || fMax <= 0) return None
    if (!passesScreen(timeSlopeS, timeSlopeC)) return None
    val (ds, dc) = slopes()
    slopeNoise(ds, dc).map { case (j, sdj, white, m2ll) =>
      Cand(Jitter.name, "both", spec.copy(jitter = true), m2ll, 1, Map("jitter_s" -> j, "white_noise_fs" -> white),
        Map("jitter_s" -> sdj, "white_noise_fs" -> 0.0), "noise against signal slope (speed and fringe phase)")
    }
  }

  /** Intensity noise of the light source: noise variance growing with the signal's value (relative rms). */
  def intensityNoise(): Option[Cand] = {
    // at a saturation the noise is the clamp's, not the source's: noise added after a clipping amplifier grows with the
    // prediction's value as this does (1 LSB after a clip at 0.7, 0.3 LSB before, was taken for it)
    if (spec.slopeNoise || spec.clips.nonEmpty) return None
    if (!passesScreen(us(_), uc(_))) return None
    val (ds, dc) = intensitySlopes()
    slopeNoise(ds, dc).map { case (r, sd, white, m2ll) =>
      Cand(IntensityNoise.name, "both", spec.copy(intensityNoise = true), m2ll, 1, Map("intensity_noise_rel" -> r, "white_noise_fs" -> white),
        Map("intensity_noise_rel" -> sd, "white_noise_fs" -> 0.0), "noise against the signal's value, largest at the fringe's peaks")
    }
  }

  /** Phase noise of the motion: noise variance growing with the slope against the fringe phase (radians rms). */
  def phaseNoise(): Option[Cand] = {
    if (spec.slopeNoise) return None
    if (!passesScreen(vs(_), vc(_))) return None
    val (ds, dc) = phaseSlopes()
    slopeNoise(ds, dc).map { case (r, sd, white, m2ll) =>
      Cand(PhaseNoise.name, "both", spec.copy(phaseNoise = true), m2ll, 1, Map("phase_noise_rad" -> r, "white_noise_fs" -> white),
        Map("phase_noise_rad" -> sd, "white_noise_fs" -> 0.0), "noise against the slope over the fringe phase, not growing with speed")
    }
  }

  /** Warm-up: the time constant by a log grid and golden section on every stride-th sample, then the full linear fit. */
  def warmup(): Option[Cand] = {
    if (spec.terms.exists(_.isInstanceOf[Term.Warmup])) return None
    val span = n / fs; val st = stride
    val idx = (0 until n by st).toArray
    def pick(a: Array[Double]) = if (a == null || (a eq Col.Ones)) a else Doubles.tabulate(idx.length)(q => a(idx(q)))
    val ys = pick(resS); val yc = pick(resC); val base = baseCols(s1, s2, c1, c2).map(c => Col(pick(c.s), pick(c.c)))
    val uS = Doubles.tabulate(idx.length)(q => us(idx(q))); val uC = Doubles.tabulate(idx.length)(q => uc(idx(q)))
    // -2 ln L (white noise) of the warm-up at log10(tau), from the subsample (its columns built there), scaled to all samples
    def f(lt: Double): Double = {
      val tau = math.pow(10, lt)
      val cols = base ++ warmupCols(Doubles.tabulate(idx.length)(q => math.exp(-idx(q) / fs / tau)), uS(_), uC(_))
      val sol = LinearFit.solve(cols, ys, yc)
      val rss = LinearFit.rss(cols, sol.beta, ys, sinCh = true) + LinearFit.rss(cols, sol.beta, yc, sinCh = false)
      2.0 * n * math.log(math.max(1e-300, rss / (2.0 * ys.length)))
    }
    // the fast path: the default part's sums once, then per time constant one pass for the warm-up's own (its columns
    // against the default part's, each other and the data), the rss from the sums (y'y - 2 b'X'y + b'X'X b)
    lazy val fixed = { val (g, r) = Gram.of(base, ys, yc); (g, r, sumSq(ys) + sumSq(yc)) }
    def fast(lt: Double): Double = {
      val tau = math.pow(10, lt); val (gB, rB, yy) = fixed
      val m = idx.length; val bs1 = base(1).s; val bs2 = base(2).s; val bc1 = base(4).c; val bc2 = base(5).c
      // per channel: w and u w against the channel's three default columns (1, sin, cos) and the data, and each other
      // exp(-t / tau) at the subsample's regular times: each block from its first point, then by its ratio
      val ratio = math.exp(-st / fs / tau)
      val q = Par.sums(m, 22, Gram.Block) { (a, b, o) =>
        // the sums in local variables (in the array, each sample's 22 additions waited on its stores)
        var z0 = 0.0; var z1 = 0.0; var z2 = 0.0; var z3 = 0.0; var z4 = 0.0; var z5 = 0.0; var z6 = 0.0; var z7 = 0.0
        var z8 = 0.0; var z9 = 0.0; var z10 = 0.0; var z11 = 0.0; var z12 = 0.0; var z13 = 0.0; var z14 = 0.0; var z15 = 0.0
        var z16 = 0.0; var z17 = 0.0; var z18 = 0.0; var z19 = 0.0; var z20 = 0.0; var z21 = 0.0
        var k = a; var w = math.exp(-idx(a) / fs / tau)
        while (k < b) {
          val ws = uS(k) * w; val wc = uC(k) * w
          val s1k = bs1(k); val s2k = bs2(k); val c1k = bc1(k); val c2k = bc2(k); val y1 = ys(k); val y2 = yc(k)
          z0 += w; z1 += w * s1k; z2 += w * s2k; z3 += w * y1
          z4 += ws; z5 += ws * s1k; z6 += ws * s2k; z7 += ws * y1
          z8 += w * w; z9 += w * ws; z10 += ws * ws
          z11 += w; z12 += w * c1k; z13 += w * c2k; z14 += w * y2
          z15 += wc; z16 += wc * c1k; z17 += wc * c2k; z18 += wc * y2
          z19 += w * w; z20 += w * wc; z21 += wc * wc
          w *= ratio; k += 1
        }
        o(0) += z0; o(1) += z1; o(2) += z2; o(3) += z3; o(4) += z4; o(5) += z5; o(6) += z6; o(7) += z7
        o(8) += z8; o(9) += z9; o(10) += z10; o(11) += z11; o(12) += z12; o(13) += z13; o(14) += z14; o(15) += z15
        o(16) += z16; o(17) += z17; o(18) += z18; o(19) += z19; o(20) += z20; o(21) += z21
      }
      // columns: the default part's 6 (sin: 0-2, cos: 3-5), then w on sin (6), w on cos (7), u w on sin (8), u w on cos (9)
      val g = Array.ofDim[Double](10, 10); val r = new Array[Double](10)
      for (i <- 0 until 6; j <- 0 until 6) g(i)(j) = gB(i)(j)
      for (i <- 0 until 6) r(i) = rB(i)
      def set(i: Int, j: Int, v: Double): Unit = { g(i)(j) = v; g(j)(i) = v }
      for ((col, at) <- Seq((6, 0), (8, 4))) { set(col, 0, q(at)); set(col, 1, q(at + 1)); set(col, 2, q(at + 2)); r(col) = q(at + 3) }
      for ((col, at) <- Seq((7, 11), (9, 15))) { set(col, 3, q(at)); set(col, 4, q(at + 1)); set(col, 5, q(at + 2)); r(col) = q(at + 3) }
      set(6, 6, q(8)); set(6, 8, q(9)); set(8, 8, q(10)); set(7, 7, q(19)); set(7, 9, q(20)); set(9, 9, q(21))
      val sol = LinearFit.normal(g, r)
      var rss = yy
      for (i <- 0 until 10) { rss -= 2 * sol.beta(i) * r(i); for (j <- 0 until 10) rss += sol.beta(i) * g(i)(j) * sol.beta(j) }
      2.0 * n * math.log(math.max(1e-300, rss / (2.0 * ys.length)))
    }
    val lo = math.log10(span / 100); val hi = math.log10(3 * span)
    val search: Double => Double = if (FitPath.isReference) f else fast
    val lt = minimize(search, lo, hi, grid = 12, golden = 12)
    val sdLog = curvatureSd(search, lt, 0.05)
    val tau = math.pow(10, lt)
    screenedLinear(Term.Warmup(tau)).map(c => c.copy(unc = c.unc + ("time_constant_s" -> tau * math.log(10) * sdLog)))
  }

  /** Fixed-frequency pickup: strongest line of the residual spectrum, refined by least squares. */
  def interference(): Option[Cand] = {
    val m = Integer.highestOneBit(math.min(n, 1 << 20))
    if (m < 64) return None
    val ps = new Array[Double](m / 2)
    // both channels' power by one complex FFT
    val both = Laps("interference: spectrum")(Fft.powerSum(resS, resC, m)); for (k <- 1 until m / 2) ps(k) = both(k)
    val k0 = Candidates.lineBin(ps, 4).getOrElse(return None)
    val bin = fs / m
    if (spec.terms.exists { case Term.Interference(h) => math.abs(h - k0 * bin) < 3 * bin; case _ => false }) return None
    val at = Candidates.spread(n, stride)
    // the residual at those samples gathered once: the search's 25 powers then read them in order (read in place, one
    // at a random place in each block of 20 missed the cache at every sample: 195 -> 93 ms a search at 1 M)
    val rs = Doubles.tabulate(at.length)(k => resS(at(k))); val rc = Doubles.tabulate(at.length)(k => resC(at(k)))
    val ref = FitPath.isReference; val sc = new Array[Double](2)
    def power(hz: Double): Double = {
      var a = 0.0; var b = 0.0; var c = 0.0; var d = 0.0; var k = 0
      while (k < at.length) {
        val i = at(k)
        // sin and cos of the line's phase from its turns (the reference path: the library's)
        if (ref) { val x = 2 * math.Pi * hz * i / fs; sc(0) = math.sin(x); sc(1) = math.cos(x) }
        else { val t = hz * i / fs; Turns.sinCos(t - Turns.floor(t), sc, 0) }
        val sx = sc(0); val cx = sc(1); val ys = rs(k); val yc = rc(k)
        a += ys * sx; b += ys * cx; c += yc * sx; d += yc * cx; k += 1
      }
      -(a * a + b * b + c * c + d * d)
    }
    val hz = Laps("interference: search")(minimize(power, (k0 - 1) * bin, (k0 + 1) * bin, grid = 8, golden = 16))
    Laps("interference: fit")(screenedLinear(Term.Interference(hz)))
  }

  def faults(): Seq[Cand] = {
    val adc = rec.adc
    val out = Seq.newBuilder[Cand]
    for ((codes, ch) <- Seq((rec.sin, 0), (rec.cos, 1))) {
      // the prediction (the repaired data less the residual) read where it is needed, not made as an array
      val (rp, rr) = if (ch == 0) (repS, resS) else (repC, resC)
      val need = math.max(20, n / 1000)
      val bits = adc.bits
      // per bit: samples with it set in the codes and in the prediction's codes, and with it unlike the next bit; from
      // the histograms of both codes (a count per code, in blocks of 2^18 samples), codes beyond them bit by bit
      val size = 1 << math.min(bits, 16)
      def addBits(m: Array[Double], at: Int, code: Int, w: Double): Unit = {
        var b = 0
        while (b < bits) {
          m(at + b) += w * ((code >> b) & 1)
          if (b + 1 < bits) m(at + 2 * bits + b) += w * (((code >> b) ^ (code >> (b + 1))) & 1)
          b += 1
        }
      }
      val h = new Array[Double](4 * bits)
      // (samples weighted out left out: ten glitches to random codes set the stuck bit 2 and hid it)
      val ex = excluded
      val hist = Par.sums(n, 2 * size + 4 * bits + 1, 1 << 18) { (a, z, m) =>
        var i = a
        while (i < z) {
          if (ex == null || !ex(i)) {
            val c = codes(i); val q = adc.pins(adc.signedCode(rp(i) - rr(i)).code)
            if (c >= 0 && c < size) m(c) += 1 else addBits(m, 2 * size, c, 1)
            if (q >= 0 && q < size) m(size + q) += 1 else addBits(m, 2 * size + bits, q, 1)
            m(2 * size + 4 * bits) += 1
          }
          i += 1
        }
      }
      val nIn = hist(2 * size + 4 * bits).toLong
      // the layout of h: set in codes, set in predictions, unlike the next (codes), unlike the next (predictions)
      var c = 0
      while (c < size) {
        if (hist(c) > 0) addBits(h, 0, c, hist(c))
        if (hist(size + c) > 0) addBits(h, bits, c, hist(size + c))
        c += 1
      }
      for (j <- 0 until 4 * bits) h(j) += hist(2 * size + j)
      def counts(at: Int) = Array.tabulate(bits)(b => h(at * bits + b).toLong)
      val m1 = counts(0); val p1 = counts(1); val diffM = counts(2); val diffP = counts(3)
      for (b <- coarseBits until bits) {
        if (m1(b) == 0 && p1(b) > need) out ++= faultCand(Fault(ch, b, 0, -1))
        else if (m1(b) == nIn && nIn - p1(b) > need) out ++= faultCand(Fault(ch, b, 1, -1))
        if (b + 1 < bits && diffM(b) == 0 && diffP(b) > need && m1(b) > 0 && m1(b) < nIn) out ++= faultCand(Fault(ch, b, -1, b + 1))
      }
    }
    out.result()
  }

  private def faultCand(f: Fault): Option[Cand] = {
    if (spec.faults.exists(g => g.ch == f.ch && g.bit == f.bit)) return None
    val sp = spec.copy(faults = spec.faults :+ f)
    val r = repair(sp)
    val nz = repairedNoise(r)
    val p = Map("bit" -> f.bit.toDouble) ++ (if (f.stuckAt >= 0) Map("stuck_at" -> f.stuckAt.toDouble) else Map("bridged_to" -> f.bridgedTo.toDouble))
    val (u, where) = (p.map { case (k, _) => k -> 0.0 }, s"code histogram: ${if (f.ch == 0) "sin" else "cos"} channel, bit ${f.bit}")
    Some(Cand(AdcBitFault.name, if (f.ch == 0) "sin" else "cos", sp, nz.m2ll, 1, p, u, where))
  }

  /** Saturation below the ADC rails: a pile-up of samples at one extreme code the model exceeds. */
  def clips(): Seq[Cand] = {
    val out = Seq.newBuilder[Cand]
    val raw = repair(spec, censor = false)
    // the noise floor from neighbouring samples, for both channels' flat tops (`flatClip`)
    lazy val floorSd = Adequacy.floor(e)
    for ((y, rp, rr, ch) <- Seq((raw.s, repS, resS, 0), (raw.c, repC, resC, 1)) if !spec.clips.exists(_.ch == ch)) {
      // (samples weighted out are held at the prediction: left out)
      val ex = excluded
      var hi = Double.NegativeInfinity; var lo = Double.PositiveInfinity; var i = 0
      while (i < n) { if (ex == null || !ex(i)) { if (y(i) > hi) hi = y(i); if (y(i) < lo) lo = y(i) }; i += 1 }
      // the samples at each extreme code, and those the model puts beyond it
      val k = Par.sums(n, 4) { (a, b, m) =>
        var i = a
        while (i < b) {
          if (y(i) >= hi - 0.5 * lsb) m(0) += 1; if (y(i) <= lo + 0.5 * lsb) m(1) += 1
          val p = rp(i) - rr(i)
          if (p > hi + lsb) m(2) += 1; if (p < lo - lsb) m(3) += 1
          i += 1
        }
      }
      val (atHi, atLo, overHi, underLo) = (k(0), k(1), k(2), k(3))
      val need = math.max(20, n / 2000)
      val useHi = hi < railHi && atHi > need && overHi > need
      val useLo = lo > railLo && atLo > need && underLo > need
      if (useHi || useLo) {
        val c = Clip(ch, if (useLo) lo else Double.NegativeInfinity, if (useHi) hi else Double.PositiveInfinity)
        val sp = spec.copy(clips = spec.clips :+ c)
        val r = repair(sp, soft = true)
        val nz = repairedNoise(r)
        // clip levels are read off the codes: uncertain by half an LSB
        val pp = Seq("low_fs" -> c.lo, "high_fs" -> c.hi).filter(!_._2.isInfinite).toMap
        val (u, where) = (pp.map { case (k, _) => k -> 0.5 * lsb }, s"code histogram: ${if (ch == 0) "sin" else "cos"} channel pile-up at the extremes")
        out += Cand(Clipping.name, if (ch == 0) "sin" else "cos", sp, nz.m2ll, c.params, pp, u, where)
      }
      flatClip(ch, y, lo, hi, floorSd).foreach(out += _)
    }
    out.result()
  }

  /** A saturation with the converter's noise after it: a flat top spread over a few codes, no pile-up at one. The
    * default fit's ellipse shrinks to the clipped shape, so the channel's ellipse is fitted again on the samples well
    * inside its range, then each level is the mean of the samples that ellipse puts beyond it, in turns; the channel's
    * -2 ln L is that of the clipped prediction. Only where the ellipse goes beyond a level by more than `FlatBeyond`
    * noise widths (a clean fringe's top is no flat one), and where the channel's noise term can be swapped (white
    * noise, nothing censored, repaired or weighted out). Another generator's 0.9 clipped at 0.8 with the ADC's 1 LSB
    * after it was harmonics 3, 5 and 7 with 38 % of the record misfit.
    */
  private def flatClip(ch: Int, y: Array[Double], yLo: Double, yHi: Double, sd: Double): Option[Cand] = {
    if (noise.jitter2 != 0 || spec.slopeNoise || spec.faults.exists(_.ch == ch) ||
      (if (ch == 0) cens.censS else cens.censC) != null) return None
    // samples weighted out (glitches, windows the model does not follow) take no part (three glitches hid a clipping)
    val ex = excluded
    @inline def in(i: Int) = ex == null || !ex(i)
    val (f1, f2, o) = if (ch == 0) (s1, s2, 0) else (c1, c2, 3)
    val (rp, rr) = if (ch == 0) (repS, resS) else (repC, resC)
    val b0 = base
    // the prediction less the channel's default part (the terms, held)
    @inline def rest(i: Int) = rp(i) - rr(i) - (b0(o) + b0(o + 1) * f1(i) + b0(o + 2) * f2(i))
    val need = math.max(20, n / 2000)
    def fit(use: Int => Boolean): Option[Array[Double]] = {
      val m = Par.sums(n, 10) { (a, b, m) =>
        var i = a
        while (i < b) {
          if (in(i) && use(i)) { val x1 = f1(i); val x2 = f2(i); val t = y(i) - rest(i)
            m(0) += 1; m(1) += x1; m(2) += x2; m(3) += x1 * x1; m(4) += x1 * x2; m(5) += x2 * x2; m(6) += t; m(7) += t * x1; m(8) += t * x2 }
          i += 1
        }
      }
      if (m(0) < 10) None else Some(Candidates.coefficients(m))
    }
    // a pile-up at an extreme code (more samples there than twice its neighbour's) is the noise before a saturation,
    // the censored kind's (`clips`): another generator's pile-ups at 0.7 of 1.0 were taken for flat tops, whose fit
    // holds the clipped samples and never left the clipped shape (harmonics 3, 5 and 7 of 0.1-0.9 %)
    val ends = Par.sums(n, 4) { (a, bb, m) =>
      var i = a
      while (i < bb) {
        val v = y(i)
        if (v >= yHi - 0.5 * step) m(0) += 1 else if (v >= yHi - 1.5 * step) m(1) += 1
        if (v <= yLo + 0.5 * step) m(2) += 1 else if (v <= yLo + 1.5 * step) m(3) += 1
        i += 1
      }
    }
    if ((ends(0) > need && ends(0) > 2 * ends(1)) || (ends(2) > need && ends(2) > 2 * ends(3))) return None
    val mid = 0.5 * (yHi + yLo); val half = 0.5 * (yHi - yLo)
    var b = fit(i => math.abs(y(i) - mid) < 0.7 * half).getOrElse(return None)
    // a clean fringe's ellipse fitted inside reaches the data's extremes, a clipped one's goes beyond them: the rest of
    // the search (a dozen passes) only then
    val amp0 = math.hypot(b(1), b(2))
    if (SignalEngine.debug) System.err.println(f"flat top? ch $ch: offset ${b(0) / lsb}%.1f amplitude ${amp0 / lsb}%.1f max ${yHi / lsb}%.1f min ${yLo / lsb}%.1f LSB; ellipse ${(b(0) + amp0 - yHi) / lsb}%.1f LSB beyond the top, ${(yLo - (b(0) - amp0)) / lsb}%.1f beyond the bottom; noise ${sd / lsb}%.2f LSB")
    if (!(b(0) + amp0 - yHi > Candidates.FlatBeyond * sd || yLo - (b(0) - amp0) > Candidates.FlatBeyond * sd)) return None
    @inline def pred(i: Int) = rest(i) + b(0) + b(1) * f1(i) + b(2) * f2(i)
    var hiL = yHi - 3 * sd; var loL = yLo + 3 * sd; var k = 0; var nHi = 0.0; var nLo = 0.0
    while (k < 6) {
      // each level the mean of the samples predicted beyond it, then the ellipse on the samples predicted inside both
      val (h, l) = (hiL, loL)
      val m = Par.sums(n, 4) { (a, bb, m) =>
        var i = a
        while (i < bb) { if (in(i)) { val p = pred(i); if (p >= h) { m(0) += 1; m(1) += y(i) } else if (p <= l) { m(2) += 1; m(3) += y(i) } }; i += 1 }
      }
      nHi = m(0); nLo = m(2)
      hiL = if (m(0) > need) m(1) / m(0) else Double.PositiveInfinity
      loL = if (m(2) > need) m(3) / m(2) else Double.NegativeInfinity
      if (hiL.isInfinite && loL.isInfinite) return None
      val (h2, l2) = (hiL, loL)
      b = fit(i => { val p = pred(i); p < h2 && p > l2 }).getOrElse(return None)
      k += 1
    }
    // the residual about the levels and about the ellipse inside them (that one's scatter is the noise)
    def sums(h: Double, l: Double) = Par.sums(n, 3) { (a, bb, m) =>
      var i = a
      while (i < bb) {
        if (in(i)) {
          val p = pred(i)
          if (p >= h || p <= l) { val d = y(i) - (if (p >= h) h else l); m(0) += d * d; m(1) += 1 } else { val d = y(i) - p; m(2) += d * d }
        }
        i += 1
      }
    }
    val q0 = sums(hiL, loL); val noiseVar = q0(2) / math.max(1.0, n - (if (ex == null) 0 else excludedCount) - q0(1))
    // the samples at a level must scatter by more than a code's rounding: a pile-up at one code has the noise before
    // the saturation (censored, above), and there a flat top's zero residual would be taken for a quieter noise. Less
    // noise after the saturation than before is fine (the flat top's variance is its own): 1 LSB before and 0.5 after
    // was refused when the scatter had to be half the noise's
    if (!(q0(0) / math.max(1.0, q0(1)) >= Candidates.FlatNoise * step * step)) return None
    val amp = math.hypot(b(1), b(2)); val sdIn = math.sqrt(noiseVar)
    val useHi = !hiL.isInfinite && b(0) + amp - hiL > Candidates.FlatBeyond * sdIn && hiL < railHi
    val useLo = !loL.isInfinite && loL - (b(0) - amp) > Candidates.FlatBeyond * sdIn && loL > railLo
    if (!useHi && !useLo) return None
    val h = if (useHi) hiL else Double.PositiveInfinity; val l = if (useLo) loL else Double.NegativeInfinity
    val q = if (useHi == !hiL.isInfinite && useLo == !loL.isInfinite) q0 else sums(h, l)
    val rss = q(0) + q(2)
    val v0 = if (ch == 0) noise.varS else noise.varC
    val m2ll = noise.m2ll - n * (math.log(2 * math.Pi * v0) + 1) + n * (math.log(2 * math.Pi * math.max(1e-30, rss / n)) + 1)
    val c = Clip(ch, l, h, after = true)
    val pp = Seq("low_fs" -> l, "high_fs" -> h).filter(!_._2.isInfinite).toMap
    val name = if (ch == 0) "sin" else "cos"
    // each level's uncertainty: the noise's over the samples it is the mean of
    val unc = pp.map { case (k2, _) => k2 -> sdIn / math.sqrt(math.max(1.0, if (k2 == "high_fs") nHi else nLo)) }
    Some(Cand(Clipping.name, name, spec.copy(clips = spec.clips :+ c), m2ll, c.params, pp, unc,
      s"code histogram: $name channel flat at the extremes, with the converter's noise on it"))
  }
}

object Candidates {
  /** The key of the binned sums of all samples. */
  private val AllSamples = new Array[Int](0)

  /** A pickup is a line: its bin's power stands this many times above the median of its neighbours'. White noise's
    * bins (both channels' power, a gamma of shape 2) pass it with p = 2e-6 each, and a line BIC accepts stands above
    * 12 x even at 1,000 samples; a band of coloured noise (1/f, a slow wander) rises with its neighbours and does not.
    */
  val LineOverNeighbours = 8.0
  /** Bins a line's own spread may reach on either side (left out of its neighbours), and the strongest bins tried. */
  private val LineSpread = 2; private val LineTries = 64

  /** The strongest bin from `from` on (of the `LineTries` strongest) whose power `ps` stands `LineOverNeighbours` times
    * above its neighbours' median (within k / 2 bins on either side, 8 to 32, the line's own spread left out); None
    * when none does. Before, the strongest bin: under 1/f noise or a coupler's slow wander the lowest bins, whose "lines"
    * did not replicate and were listed as unexplained structure (and a 50 Hz hum beside them was not tried).
    */
  def lineBin(ps: Array[Double], from: Int): Option[Int] = {
    val end = ps.length
    if (end <= from) return None
    // the strongest bins: the threshold by selection (a sort of a million bins a round cost 0.1 s)
    val thr = if (end - from <= LineTries) Double.NegativeInfinity else {
      val c = java.util.Arrays.copyOfRange(ps, from, end)
      new org.hipparchus.util.KthSelector(org.hipparchus.util.PivotingStrategy.MEDIAN_OF_3).select(c, null, c.length - LineTries)
    }
    val ks = (from until end).filter(k => ps(k) >= thr).sortBy(k => -ps(k)).take(LineTries)
    def level(k: Int): Double = {
      val w = math.min(32, math.max(8, k / 2))
      val xs = ((k - w) to (k + w)).filter(j => j >= 1 && j < end && math.abs(j - k) > LineSpread).map(ps).sorted
      if (xs.isEmpty) 0.0 else xs(xs.size / 2)
    }
    // the strongest of those that stand out (ks is in order of power)
    ks.find(k => ps(k) >= LineOverNeighbours * level(k))
  }

  /** The residual sum of squares of one channel's fit of y on (1, x1, x2) from the sums n, x1, x2, x1 x1, x1 x2, x2 x2,
    * y, y x1, y x2, y y.
    */
  def rss(m: Array[Double]): Double = {
    val x = coefficients(m)
    math.max(1e-300, m(9) - x(0) * m(6) - x(1) * m(7) - x(2) * m(8))
  }
  /** The least-squares coefficients (offset, the two fundamentals) of one channel's sums `m` (see `profile`). */
  def coefficients(m: Array[Double]): Array[Double] = {
    val a = Array(Array(m(0), m(1), m(2), 0, m(6)), Array(m(1), m(3), m(4), 0, m(7)), Array(m(2), m(4), m(5), 0, m(8)), Array(0.0, 0, 0, 1, 0))
    Trajectory.solve4(a)
  }

  /** f with its values kept (a profile on every sample is evaluated at the same point more than once). */
  def memo(f: Double => Double): Double => Double = {
    val seen = scala.collection.mutable.Map.empty[Double, Double]
    x => seen.getOrElseUpdate(x, f(x))
  }

  /** Samples above which the linear candidates are screened on a spread subsample of `ScreenSamples`, and those that
    * are significant there fitted on all samples.
    */
  /** Turns of `joint` at most (each a line search along every direction of its set and one along the turn's move). */
  val MaxTurns = 12

  def ScreenAbove: Int = screen.value._1
  def ScreenSamples: Int = screen.value._2
  private val screen = new scala.util.DynamicVariable((1 << 22, 1 << 20))
  /** Runs `body` with screening above `above` samples on `samples` (a test's short records). */
  def screening[A](above: Int, samples: Int)(body: => A): A = screen.withValue((above, samples))(body)

  /** Terms a long record's round fits on the screening subsample first: the linear families' and those linear once
    * searched (a warm-up, a pickup line).
    */
  def screened(t: Term): Boolean = LinearFamily.of(t).isDefined || (t match { case _: Term.Warmup | _: Term.Interference => true; case _ => false })

  /** Samples up to which the searches run side by side (beyond, their columns would hold too much of the heap at once). */
  val SideBySide: Int = 1 << 22

  /** Noise widths by which the ellipse fitted inside must go beyond a flat top's level (`flatClip`). */
  val FlatBeyond = 6.0
  /** Squared quantization steps the samples at a flat top's level must scatter by at least (`flatClip`): a code's
    * rounding alone is 1/12, a pile-up at one code none (0.3 LSB of noise after a saturation gives 0.17; at 0.16 that
    * record was neither kind of clipping).
    */
  val FlatNoise = 0.1

  /** (sqrt(5) - 1) / 2: a golden section's bracket shrinks by this. */
  val GoldenRatio: Double = (math.sqrt(5) - 1) / 2

  /** About n / st sample indices, one at a random place in each block of st; all of them when st is 1. A regular
    * stride would alias a line at a multiple of fs / st to DC (50 kHz at 10 MS/s with a stride of 400: 20,000,000 rows).
    */
  def spread(n: Int, st: Int): Array[Int] =
    if (st <= 1) Array.range(0, n)
    else { val r = new scala.util.Random(n.toLong * 31 + st); Array.tabulate(n / st)(q => q * st + r.nextInt(st)) }
}
