package moire.explain

/** Adequacy first (issue 28): whether the model follows the signal, judged window by window against a noise floor that
  * does not depend on the motion model. The floor comes from k-th differences of neighbouring residual samples: white
  * noise of rms sigma gives mean square C(2k, k) sigma^2 to them, while a misfit that varies over more than a few samples
  * cancels in them (one at a fraction x of the sample rate passes with (2 sin(pi x))^k / sqrt(C(2k, k)) of its size).
  * The largest `Trim` of the squared differences are left out (a slip or a shock a few samples long is a misfit, not
  * noise) and the mean of the rest is scaled back to sigma^2 for Gaussian noise.
  *
  * The record is cut into `Windows` contiguous windows; where the residual's rms exceeds the window's floor by `Margin`,
  * the model does not follow the signal there. Effects are then fitted and judged only on the windows that follow
  * (the others are weighted out of the fit, `SignalEngine.exclude`); when those that follow hold less than
  * `MinFollowed` of the record, nothing is assessed.
  */
object Adequacy {
  /** Residual rms over the noise floor above which the model does not follow (3: white noise gives 1; noise whose band
    * ends at half the Nyquist frequency, as an oversampled analog bandwidth makes, gives 2.6).
    */
  val Margin = 3.0
  val Windows = 32
  /** The share of the record the windows that follow must hold for effects to be assessed on them: between short
    * islands the misfit's edges and the gaps leave slow effects (of time, position, low frequencies) undetermined.
    */
  val MinFollowed = 0.5
  /** The fraction of the largest squared differences left out of the floor. */
  val Trim = 0.1
  /** Differences of the floor that judges adequacy: 2nd (noise band-limited to half the Nyquist frequency still passes). */
  val JudgeOrder = 2
  /** Differences of the noise reported where the model does not follow: 4th (a misfit at a tenth of the sample rate
    * passes with 1 % of its size, against 12 % through 2nd differences).
    */
  val NoiseOrder = 4

  private val coef: Map[Int, Array[Double]] = Seq(JudgeOrder, NoiseOrder).map { k =>
    k -> Array.tabulate(k + 1)(j => (if (j % 2 == 0) 1.0 else -1.0) * (0 until j).foldLeft(1.0)((c, m) => c * (k - m) / (m + 1)))
  }.toMap

  /** Noise floor (full scale rms) of the residuals `rs` (and `rc`, when not null, pooled) over [a, b) from k-th
    * differences, skipping differences that touch a sample where `skip` is true (null: none); NaN from fewer than
    * `minCount` differences.
    */
  def floorOf(rs: Array[Double], rc: Array[Double], a: Int, b: Int, k: Int, skip: Array[Boolean], minCount: Int = 0): Double =
    Laps("adequacy: noise floor")(floorOf0(rs, rc, a, b, k, skip, minCount))
  private def floorOf0(rs: Array[Double], rc: Array[Double], a: Int, b: Int, k: Int, skip: Array[Boolean], minCount: Int): Double = {
    val c = coef(k); val norm = c.map(x => x * x).sum
    // the squared differences are made where they are read instead of kept (an array of twice the record's length
    // less: 320 MB at 20 M samples), the same numbers in the same order: with nothing skipped, the count from the
    // length, the sample's squares alone, then one pass for the sum; else a pass each (count, sample, sum)
    val m = squares(rs, rc, a, b, k, skip, c, Count, 1, 0.0, null)
    if (m < minCount) return Double.NaN
    if (m == 0) return 0.0
    // the mean of the smallest (1 - Trim) of the squares, scaled to the full mean of a Gaussian's squares; the
    // threshold from a strided sample of them, the correction from the fraction actually kept
    val stride = math.max(1, m / 40000)
    val smp = new Array[Double]((m + stride - 1) / stride)
    squares(rs, rc, a, b, k, skip, c, Sample, stride, 0.0, smp)
    // the sample's value at that rank, by selection (a sort of a window's 60,000 squares cost more than its passes)
    val thr = select.select(smp, null, math.min(smp.length - 1, ((1 - Trim) * smp.length).toInt))
    val acc = new Array[Double](2)
    squares(rs, rc, a, b, k, skip, c, Sum, 1, thr, acc)
    val s = acc(0); val kept = acc(1).toLong
    val p = kept.toDouble / m
    val ms = if (kept == 0) 0.0
      else if (p >= 1) s / kept
      else {
        // E[z^2 | |z| < q] = 1 - 2 q phi(q) / p, with P(|z| < q) = p
        val q = normal.inverseCumulativeProbability(0.5 + 0.5 * p)
        val cc = 1 - 2 * q * math.exp(-0.5 * q * q) / math.sqrt(2 * math.Pi) / p
        if (cc > 0) s / kept / cc else s / kept
      }
    math.sqrt(ms / norm)
  }

  private final val Count = 0; private final val Sample = 1; private final val Sum = 2
  /** One pass over the k-th differences' squares of rs (and rc, interleaved) over [a, b), skipping those that touch a
    * sample where `skip` is true, in their order q = 0, 1, ...: `Count` counts them; `Sample` puts square q into
    * out(q / stride) where q is a multiple of `stride`; `Sum` adds those at most `thr` into out(0) and counts them in
    * out(1). Returns the count.
    */
  private def squares(rs: Array[Double], rc: Array[Double], a: Int, b: Int, k: Int, skip: Array[Boolean], c: Array[Double],
                      mode: Int, stride: Int, thr: Double, out: Array[Double]): Int = {
    val per = if (rc != null) 2 else 1
    val i0 = math.max(0, a)
    // with nothing skipped the count is the differences' number (no pass)
    if (mode == Count && skip == null) return per * math.max(0, b - k - i0)
    // nor `Sample`: square q is channel q % per's difference at i0 + q / per, made only for the q it keeps
    if (mode == Sample && skip == null) {
      val m = per * math.max(0, b - k - i0); var q = 0; var slot = 0
      while (q < m) {
        val i = i0 + q / per; val r = if (q % per == 0) rs else rc
        var s = 0.0; var j = 0
        while (j <= k) { s += c(j) * r(i + j); j += 1 }
        out(slot) = s * s; slot += 1; q += stride
      }
      return m
    }
    // `Sum` of 2nd differences with nothing skipped (the judge's floor): the same products and additions, unrolled
    if (mode == Sum && skip == null && k == 2) {
      val c0 = c(0); val c1 = c(1); val c2 = c(2); var i = i0; var sum = 0.0; var kept = 0L
      while (i + 2 < b) {
        val s = 0.0 + c0 * rs(i) + c1 * rs(i + 1) + c2 * rs(i + 2); val v = s * s
        if (v <= thr) { sum += v; kept += 1 }
        if (rc != null) { val t = 0.0 + c0 * rc(i) + c1 * rc(i + 1) + c2 * rc(i + 2); val w = t * t; if (w <= thr) { sum += w; kept += 1 } }
        i += 1
      }
      out(0) = sum; out(1) = kept.toDouble
      return per * math.max(0, b - k - i0)
    }
    var m = 0; var i = i0; var sum = 0.0; var kept = 0L
    var next = 0; var slot = 0 // the next square `Sample` keeps (a multiple of stride) and its place: no division a square
    var bad = -1 // the last skipped sample at or before i + k
    while (i + k < b) {
      if (skip != null) { var j = math.max(i, bad + 1); while (j <= i + k) { if (skip(j)) bad = j; j += 1 } }
      if (bad < i) {
        // the difference of each channel: its coefficients' products added in order
        var s = 0.0; var j = 0
        while (j <= k) { s += c(j) * rs(i + j); j += 1 }
        var h = 0
        while (h < per) {
          val v = if (h == 0) s * s else { var t = 0.0; j = 0; while (j <= k) { t += c(j) * rc(i + j); j += 1 }; t * t }
          if (mode == Sample) { if (m == next) { out(slot) = v; slot += 1; next += stride } }
          else if (mode == Sum) { if (v <= thr) { sum += v; kept += 1 } }
          m += 1; h += 1
        }
      }
      i += 1
    }
    if (mode == Sum) { out(0) = sum; out(1) = kept.toDouble }
    m
  }
  private val select = new org.hipparchus.util.KthSelector(org.hipparchus.util.PivotingStrategy.MEDIAN_OF_3)
  private val normal = new org.hipparchus.distribution.continuous.NormalDistribution(0, 1)

  /** Noise floor (full scale rms) of the engine's residual on both channels over [a, b), from 2nd differences, on the
    * samples in the fit (not weighted out).
    */
  def floor(e: SignalEngine, a: Int = 0, b: Int = -1): Double =
    floorOf(e.resS, e.resC, a, if (b < 0) e.n else b, JudgeOrder, e.excluded)

  /** The noise (full scale rms) of one channel's residual where the model does not follow somewhere: from 4th
    * differences, over the windows that follow (all of them when none does).
    */
  def noiseOf(r: Array[Double], skip: Array[Boolean]): Double = {
    val f = if (skip == null) Double.NaN else floorOf(r, null, 0, r.length, NoiseOrder, skip, minCount = 64)
    if (f.isNaN) floorOf(r, null, 0, r.length, NoiseOrder, null) else f
  }

  private def rms(e: SignalEngine, a: Int, b: Int): Double = {
    var s = 0.0; var i = a
    while (i < b) { s += e.resS(i) * e.resS(i) + e.resC(i) * e.resC(i); i += 1 }
    if (b > a) math.sqrt(s / (2.0 * (b - a))) else 0.0
  }

  /** The model's rms over the floor for the whole record. */
  def ratio(e: SignalEngine): Double = { val f = floor(e); if (f > 0) rms(e, 0, e.n) / f else Double.PositiveInfinity }

  /** A window [a, b) of the record, its residual rms over its floor, and its residual rms (full scale). */
  final case class Window(a: Int, b: Int, ratio: Double, rms: Double)

  /** The windows of the record: n / Windows samples each (at least 16), the last takes the remainder. */
  def windows(e: SignalEngine): Seq[Window] = {
    val w = math.max(16, e.n / Windows); val k = math.max(1, e.n / w)
    (0 until k).map(j => (j * w, if (j == k - 1) e.n else (j + 1) * w)).map { case (a, b) =>
      val f = floor(e, a, b); val r = rms(e, a, b); Window(a, b, if (f > 0) r / f else 0.0, r)
    }
  }

  /** Where the model (the engine's current spec) does not follow, besides the windows `prior` already weighted out.
    * A misfit in part of the record also spoils the fit elsewhere (the default part and the trajectory take up some of
    * it), so the windows above `Margin` x their floor whose rms is also above `Margin` x the median rms of the windows
    * in the fit ("standing out") are weighted out and the spec is refitted without them, up to 4 times, until none
    * stands out. Returns those, and the windows still above the margin after that (each with its ratio when judged).
    * Leaves the standing-out windows weighted out of the engine's fit.
    */
  def judge(e: SignalEngine, prior: Seq[Window]): (Seq[Window], Seq[Window]) = {
    var out = Vector.empty[Window]; var k = 0; var more = true
    def inFit = windows(e).filter(w => !out.exists(_.a == w.a) && !prior.exists(_.a == w.a))
    while (more && k < 4) {
      val ws = inFit; val med = median(ws.map(_.rms))
      val stand = ws.filter(w => w.ratio > Margin && w.rms > Margin * med)
      if (stand.isEmpty) more = false
      else { out ++= stand; k += 1; e.exclude(maskOf(e, prior ++ out)) }
    }
    (out, inFit.filter(_.ratio > Margin))
  }

  private def median(xs: Seq[Double]): Double = if (xs.isEmpty) 0.0 else xs.sorted.apply(xs.size / 2)

  /** The samples in `ws` (null when empty). */
  def maskOf(e: SignalEngine, ws: Seq[Window]): Array[Boolean] =
    if (ws.isEmpty) null else { val m = new Array[Boolean](e.n); ws.foreach(w => java.util.Arrays.fill(m, w.a, w.b, true)); m }

  /** Whether effects are assessed with the windows `ws` weighted out: those that follow hold at least `MinFollowed`. */
  def assessable(e: SignalEngine, ws: Seq[Window]): Boolean = ws.map(w => w.b - w.a).sum <= (1 - MinFollowed) * e.n

  /** The windows `ws` where the model does not follow the signal, merged into runs, as located departures. */
  def misfit(e: SignalEngine, ws: Seq[Window]): Seq[Located] = {
    // runs of neighbouring windows
    val runs = ws.foldLeft(List.empty[(Int, Int, Double)]) {
      case ((a0, b0, r0) :: rest, w) if w.a == b0 => (a0, w.b, math.max(r0, w.ratio)) :: rest
      case (acc, w) => (w.a, w.b, w.ratio) :: acc
    }.reverse
    val p0 = e.phase(0)
    val share = ws.map(w => w.b - w.a).sum.toDouble / e.n
    runs.map { case (a, b, r) =>
      // where the data go there, from their own phase (the fitted trajectory does not follow them: a constant 20 kHz with
      // samples cut out read 0.56..37 kHz); the position from the start by the trajectory's phase at the window's start
      val (x0, x1, f0, f1) = Jumps.track(e, a, b).map { case (u0, u1, g0, g1) => val s = e.phase(a) - p0; (s + u0, s + u1, g0, g1) }
        .getOrElse((e.phase(a) - p0, e.phase(b - 1) - p0, math.abs(e.freq(a)), math.abs(e.freq(b - 1))))
      // a step of the phase there names the physics (samples lost, a slip)
      val jumps = Jumps.find(e, a, b)
      Located("the default model does not follow the signal here",
        f"residual rms up to ${r}%.1f x the noise floor (from neighbouring samples) at ${a / e.fs}%.4g..${b / e.fs}%.4g s, position ${x0}%.4g..${x1}%.4g " +
          f"fringe periods from the start, fringe frequency ${f0 / 1e3}%.4g..${f1 / 1e3}%.4g kHz; " + jumps.map(j => Jumps.describe(j, e.fs) + "; ").mkString +
          (if (!assessable(e, ws)) f"the model does not follow over ${share * 100}%.0f %% of the record: no effect is assessed"
           else f"effects are fitted and judged without these samples (${share * 100}%.0f %% of the record)"),
        Map("ratio" -> r, "t0_s" -> a / e.fs, "t1_s" -> b / e.fs, "position0_periods" -> x0, "position1_periods" -> x1, "f0_hz" -> f0, "f1_hz" -> f1,
          "share_not_followed" -> share) ++ jumps.headOption.map(j => Map("phase_step_periods" -> j.periods, "phase_step_s" -> j.at / e.fs)).getOrElse(Map()),
        significant = true)
    }
  }
}
