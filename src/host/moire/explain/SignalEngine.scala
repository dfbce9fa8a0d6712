package moire.explain

import moire.recording.{Recording, Reference}

/** Fits the backward model to a recording: phase trajectory, default part, accepted effects.
  * All per-sample work is on primitive arrays; the state after `refit` is consistent
  * (prediction, residual, noise model and -2 ln L of the current `spec`).
  */
final class SignalEngine(val rec: Recording, val refColumn: Option[Reference] = None,
                         holdBytes: Long = SignalEngine.HoldBytes) {
  val n: Int = rec.length
  val fs: Double = rec.sampleRateHz
  val lsb: Double = rec.adc.lsb
  val ys: Array[Double] = rec.values(rec.sin)
  val yc: Array[Double] = rec.values(rec.cos)
  /** Low bits that no sample of either channel uses (a narrower converter in a wider code format, a scope's 8 bits
    * in 16): the quantization step is 2^coarseBits LSB and its error is not white noise.
    */
  val coarseBits: Int = {
    val m = (1 << rec.adc.bits) - 1
    // the codes' bits OR-ed per block on all cores, then the blocks'
    val k = (n + Par.Block - 1) / Par.Block; val ors = new Array[Int](k)
    Par.blocks(n) { (lo, hi) =>
      var or = 0; var i = lo
      while (i < hi) { or |= (rec.adc.fromPins(rec.sin(i)) & m) | (rec.adc.fromPins(rec.cos(i)) & m); i += 1 }
      ors(lo / Par.Block) = or
    }
    val or = ors.foldLeft(0)(_ | _)
    if (or == 0) 0 else math.min(rec.adc.bits - 4, Integer.numberOfTrailingZeros(or))
  }
  /** The quantization step in full-scale units. */
  val step: Double = lsb * (1 << coarseBits)
  val railLo: Double = -1.0
  val railHi: Double = (rec.adc.half - (1 << coarseBits)) * lsb
  /** A value at an ADC end code (the repair censors it; clipping levels inside the range aside). */
  @inline final def atRail(v: Double): Boolean = v >= railHi - 0.5 * lsb || v <= railLo + 0.5 * lsb
  /** Time from the record's middle (s), made when a term needs it. */
  def tc: Array[Double] = Doubles.tabulate(n)(i => (i - 0.5 * (n - 1)) / fs)
  /** The offsets' column: ones, not stored (`Col.Ones`). */
  def ones: Array[Double] = Col.Ones
  val lnN: Double = math.log(2.0 * n)

  val phase = new Array[Double](n); val freq = new Array[Double](n)
  // the plain fundamentals (sin and cos of the fringe phase); a spec with skew or bandwidth keeps its cos channel's here
  private val plainSin = new Array[Double](n); private val plainCos = new Array[Double](n)
  /** The fundamentals' columns (sin, cos channel): the plain sin and cos of the phase unless the spec skews or filters
    * a channel, then arrays of their own (allocated on first need).
    */
  private var _s1: Array[Double] = plainSin; private var _s2: Array[Double] = plainCos
  private var _c1: Array[Double] = plainSin; private var _c2: Array[Double] = plainCos
  def s1: Array[Double] = _s1; def s2: Array[Double] = _s2; def c1: Array[Double] = _c1; def c2: Array[Double] = _c2
  /** The fitted fundamental (u) and its derivative by the fringe phase (v) per channel at sample i, from the default
    * part and the fundamentals' columns (not stored: four fewer arrays of the record's length).
    */
  @inline final def us(i: Int): Double = base(1) * s1(i) + base(2) * s2(i)
  @inline final def vs(i: Int): Double = base(1) * s2(i) - base(2) * s1(i)
  @inline final def uc(i: Int): Double = base(4) * c1(i) + base(5) * c2(i)
  @inline final def vc(i: Int): Double = base(4) * c2(i) - base(5) * c1(i)
  // The fit's state: private, read through the methods below (the caller sets `spec` and refits)
  private var _repS: Array[Double] = ys; private var _repC: Array[Double] = yc
  private var _cens: Repaired = Repaired(ys, yc, null, null)
  /** The measured values with faults undone and censored samples at the prediction (the data the model is fitted to). */
  def repS: Array[Double] = _repS; def repC: Array[Double] = _repC
  def cens: Repaired = _cens
  // the repaired data's arrays are also held elsewhere (a saved state, a trajectory length kept in `init`): the next
  // refit's repair makes new ones instead of writing over them (at 20 M samples a repaired channel is 240 MB)
  private var shared = false
  val resS = new Array[Double](n); val resC = new Array[Double](n)

  var spec: ModelSpec = ModelSpec()
  private var _base: Array[Double] = new Array[Double](6)
  private var _sol: LinSol = _
  private var _termIndex: Map[Term, Int] = Map.empty
  private var _noise: Noise = Noise(1, 1, 0, 0)
  private var _traj: PhaseTrack = _
  /** The default part's coefficients (offset, sin, cos of each channel), the joint fit, where each term's coefficients
    * start in it, the noise model and the phase trajectory.
    */
  def base: Array[Double] = _base; def sol: LinSol = _sol; def termIndex: Map[Term, Int] = _termIndex
  def noise: Noise = _noise; def traj: PhaseTrack = _traj
  /** The reference the phase follows (None: the trajectory is fitted from the signals), and why one was not used. */
  private var _reference: Option[RefTrajectory] = None
  private var _referenceRefused: Option[String] = None
  private var _typicalHz = 0.0
  def reference: Option[RefTrajectory] = _reference; def referenceRefused: Option[String] = _referenceRefused
  def typicalHz: Double = _typicalHz

  def ampS: Double = math.hypot(base(1), base(2))
  def ampC: Double = math.hypot(base(4), base(5))
  /** Quadrature phase error in degrees: cos channel phase minus sin channel phase minus 90. */
  def phaseErrorDeg: Double = {
    val d = math.toDegrees(math.atan2(base(5), base(4)) - math.atan2(base(2), base(1))) - 90
    ((d + 540) % 360) - 180
  }
  /** The terms' part of the prediction at sample i (the prediction less the default part). */
  def termS(i: Int): Double = repS(i) - resS(i) - base(0) - us(i)
  def termC(i: Int): Double = repC(i) - resC(i) - base(3) - uc(i)
  /** The model's prediction (not stored: the repaired data less the residual), as new arrays. */
  def predS: Array[Double] = Doubles.tabulate(n)(i => repS(i) - resS(i))
  def predC: Array[Double] = Doubles.tabulate(n)(i => repC(i) - resC(i))
  /** The prediction at sample i, read where it is needed (no array of the record's length). */
  @inline final def predSAt(i: Int): Double = _repS(i) - resS(i)
  @inline final def predCAt(i: Int): Double = _repC(i) - resC(i)
  def params: Int = 6 + traj.params + 2 + spec.extraParams
  /** The fraction of its samples' information a column keeps where a soft repair's weights are spread (1: none): the
    * variances of the linear terms fitted to the weights' means are the complete data's, larger by its inverse (Louis'
    * missing information, spread evenly over each channel's samples).
    */
  def informationLeft(col: Col): Double = {
    def left(lost: Double) = math.max(1e-3, 1 - lost / math.max(1, n - excludedCount))
    if (!_cens.soft) 1.0
    else if (col.c == null) left(_cens.lostS) else if (col.s == null) left(_cens.lostC)
    else { val (a, b) = (sumSq(col.s), sumSq(col.c)); if (a + b <= 0) 1.0 else (a * left(_cens.lostS) + b * left(_cens.lostC)) / (a + b) }
  }
  /** -2 ln L of white noise of mean squares (varS, varC) on all samples, with the soft repair's spread and entropy. */
  def whiteM2ll(varS: Double, varC: Double): Double = Noise.white(varS * n, varC * n, n, _cens).m2ll
  def bic: Double = noise.m2ll + params * lnN
  /** The rms of the residual over the samples in the fit. */
  def rms: Double = math.sqrt(meanSquare * n / math.max(1, n - excludedCount))
  /** The residual's mean square over both channels, with a soft repair's spread (the data's own, not its mean's). */
  def meanSquare: Double = (sumSq(resS) + sumSq(resC) + _cens.pvSumS + _cens.pvSumC) / (2.0 * n)
  def rmsOf(a: Array[Double]): Double = math.sqrt(sumSq(a) / a.length)

  // Samples weighted out of the fit (where the model does not follow the signal, `Adequacy`): their data are held at
  // the prediction, so they carry no residual; null when every sample is in the fit.
  private var _excluded: Array[Boolean] = null
  private var _excludedCount = 0
  /** Runs of samples the data lost (`Dropouts`), weighted out of the phase's steps as well (null: none). */
  var lost: Array[Boolean] = null
  def excluded: Array[Boolean] = _excluded
  def excludedCount: Int = _excludedCount
  /** Samples of bad data (glitches, runs lost) that every exclusion keeps out (null: none). Before, the windows the
    * model did not follow replaced them: another generator's 19 glitches came back into the fit and made 8 misfit windows.
    */
  var badData: Array[Boolean] = null
  /** Weights the samples where `mask` (or `badData`) is true out of the fit (null: none) and refits. */
  def exclude(mask0: Array[Boolean]): Unit = {
    val mask = Glitches.union(mask0, badData)
    _excluded = mask; _excludedCount = if (mask == null) 0 else mask.count(identity)
    if (mask != null) { _repS = repS.clone(); _repC = repC.clone(); _cens = _cens.copy(s = _repS, c = _repC); holdExcluded() }
    converge()
  }
  /** The data of the excluded samples at the current prediction: no residual there. */
  private def holdExcluded(): Unit = if (_excluded != null) {
    var i = 0
    while (i < n) { if (_excluded(i)) { _repS(i) -= resS(i); _repC(i) -= resC(i); resS(i) = 0; resC(i) = 0 }; i += 1 }
  }

  /** Initial ellipse from the extremes, raw phase by atan2, first trajectory, then the full default fit. */
  def init(): Unit = {
    val (os, as) = mid(ys); val (oc, ac) = mid(yc)
    // the angle of each sample on all cores, then unwrapped in order
    val raw = Doubles.tabulate(n)(i => math.atan2((ys(i) - os) / as, (yc(i) - oc) / ac) / (2 * math.Pi))
    var prev = 0.0; var turns = 0.0; var i = 0
    while (i < n) {
      val p = raw(i)
      if (i > 0) { val d = p - prev; if (d > 0.5) turns -= 1 else if (d < -0.5) turns += 1 }
      raw(i) = p + turns; prev = p; i += 1
    }
    val blk = math.max(16, math.min(4096, n / 64))
    // a block's speed from its path, summed over 16 strides: a block over a reversal moves little but travels far
    val stride = math.max(1, blk / 16)
    def path(a: Int, b: Int): Double = { var s = 0.0; var j = a; while (j < b) { val k = math.min(b, j + stride); s += math.abs(raw(k) - raw(j)); j = k }; s }
    val speeds = (0 until n / blk).map(b => path(b * blk, (b + 1) * blk - 1) * fs / (blk - 1)).sorted
    _typicalHz = if (speeds.isEmpty) 0.0 else speeds(speeds.size / 2)
    def prepare(t: PhaseTrack, first: Array[Double]): Unit = {
      _traj = t; traj.addFit(first, null); evalTraj()
      _base = Array(os, as, 0, oc, 0, ac); spec = ModelSpec(); _cens = Repaired(ys, yc, null, null); _repS = ys; _repC = yc
    }
    // a plain solve and three refining steps; the fast path leaves out the third when the second gained < 0.5
    def finish(): Unit = if (FitPath.isReference || !plainData || lastGain > 0.5) refit(4, refineTraj = true, from = 3)
    def start(t: PhaseTrack, first: Array[Double]): Unit = { prepare(t, first); refit(3, refineTraj = true); finish() }
    /** The trajectory from the signals: of segments spanning 16, 6 or 2.5 fringe periods (shorter
      * ones while they lower it), the one with the lowest BIC. */
    def freeFit(): Unit = {
      def free(len: Int): Unit = start(new Trajectory(n, len, fs), raw)
      val lens = Seq(16.0, 6.0, 2.5).map(p => Trajectory.segmentLength(n, fs, typicalHz, p)).distinct
      segmentLens = lens
      val shortest = Identifiable.shortestSegment(n, fs, typicalHz)
      if (lens.size == 1 && lens.head <= shortest) { free(lens.head); return }
      // each length's fitted trajectory and repaired data are kept: the best is restored and solved once, not fitted again
      final case class Fitted(len: Int, bic: Double, traj: PhaseTrack, repS: Array[Double], repC: Array[Double], cens: Repaired, gain: Double,
                              motionMisfit: Boolean, far: Boolean, ratio: Double) {
        def follows: Boolean = !motionMisfit && !far
      }
      def kept(l: Int) = {
        // the motion not followed: a residual mostly along the signals' path, or, where the phase is off by so much that
        // the residual points anywhere, one of a tenth of the fringe's amplitude
        // (beyond the part that turns with the fringe: a harmonic of it on both channels is no motion)
        val r = alongOverAcross; val far = math.sqrt(meanSquare) > 0.1 * math.min(as, ac)
        val rb = if (far || r <= SignalEngine.MotionMisfit) r else alongOverAcrossBeyondFringe
        if (SignalEngine.debug) System.err.println(f"trajectory segments of $l samples: BIC $bic%.1f, residual along / across the fringe $r%.3f" +
          f"${if (rb != r) f" ($rb%.3f beyond the fringe's own shape)" else ""}${if (far) ", far off" else ""}")
        shared = true; Fitted(l, bic, _traj, _repS, _repC, _cens, lastGain, far || rb > SignalEngine.MotionMisfit, far, rb)
      }
      def restore(f: Fitted): Unit = {
        _traj = f.traj; evalTraj(); _repS = f.repS; _repC = f.repC; _cens = f.cens
        refit(1, refineTraj = false); _lastGain = f.gain
      }
      // motion that turns faster than the shortest segments follow (oscillation, reversals): shorter ones while BIC
      // falls, down to `Identifiable.shortestSegment`
      // Only for the motion: motion the trajectory does not follow leaves a residual along the signals' path (a phase
      // error), pickup, a harmonic or clipping as much across it (off the ellipse) as along. Shorter segments take up
      // part of those too, and lowered BIC by it: a 5 LSB pickup at 1 kHz on 3 kHz fringes went into 1-period segments,
      // and every effect was then not identifiable.
      // Where every length tried is far off (a vibration reversing within the shortest, whose speed the blocks' path
      // undercounts: 2 kHz at 1 MS/s left 743 LSB rms), shorter ones down to the trajectory's least length.
      def shorter(fits: Seq[Fitted], fit: Int => Fitted): Seq[Fitted] = {
        var f = fits
        def lost = f.forall(_.far)
        // (and the longest segments already leave motion: where they follow it, what shorter ones gain by BIC is the
        // fringe's own shape that they half follow, a harmonic of it on both channels)
        // Where the shortest still leave the motion, shorter ones still, down to `Trajectory.LeastLength`, while they
        // lower BIC or, none following it yet, take up more of it (a 2 kHz shake of 5 periods at 1 MS/s: 64-sample
        // cubics left 2.4 x the noise floor; of 2 periods, 56-sample ones a misfit that five pickup lines took up)
        def best = f.minBy(_.bic).len == f.last.len && f.last.motionMisfit && f.head.motionMisfit
        def closing = f.size > 1 && !f.last.far && f.last.motionMisfit && f.head.motionMisfit && !f.exists(_.follows) &&
          f.last.ratio < 0.7 * f(f.size - 2).ratio
        // (only where the motion changes within a few such segments: the speed's own time, rms speed over rms change of
        // it, under 4 of them; else what they leave is the fringe's shape, not motion: a 0.5 % 3rd harmonic on a
        // 400 Hz back-and-forth at 10 MS/s went into 23-sample segments and came out at 0.016 %)
        def turns = f.last.len / fs > motionTimeS / 4
        // (each length shorter than the last: where all are far off, none below `Trajectory.MinLength`; a head
        // creeping over 1 % of a period tried 64 samples again and again)
        def next: Int =
          if (f.last.len <= shortest && !lost) math.max(Trajectory.LeastLength, (f.last.len * 0.6).toInt)
          else math.max(if (lost) Trajectory.MinLength else shortest, (f.last.len * 0.4).toInt)
        while (((lost && f.last.len > Trajectory.MinLength) || (best && f.last.len > shortest) ||
          (!lost && (best || closing) && f.last.len > Trajectory.LeastLength && f.last.len <= shortest && turns)) && next < f.last.len)
          f = f :+ fit(next)
        f
      }
      // the lowest BIC; but where that length leaves the motion and a shorter one follows it, the shorter one (what a
      // trajectory leaves of the motion, the effects' searches take up: pickup lines at the shake's harmonics)
      def chosen(fits: Seq[Fitted]): Fitted = {
        val b = fits.minBy(_.bic)
        if (b.follows || b.far) b else fits.filter(x => x.follows && x.len < b.len).sortBy(_.bic).headOption.getOrElse(b)
      }
      if (FitPath.isReference) { free(chosen(shorter(lens.map { l => free(l); kept(l) }, l => { free(l); kept(l) })).len); return }
      // the fast path: each length's plain solve and first refining step, then the further steps only for the lengths
      // within reach of the best (their BIC within twice their last step's gain and the threshold of it)
      def tried(l: Int) = { prepare(new Trajectory(n, l, fs), raw); refit(2, refineTraj = true); kept(l) }
      val first = shorter(lens.map(tried), tried)
      val lead = chosen(first)
      val reach = first.filter(f => (f eq lead) || (f.follows || !lead.follows) && f.bic - lead.bic < 2 * math.max(f.gain, 0) + 10)
      var now = first.last
      val done = reach.map { f =>
        if (f ne now) restore(f)
        refit(3, refineTraj = true, from = 2); finish()
        val k = kept(f.len); now = k; k
      }
      val best = chosen(done)
      if (best ne now) restore(best)
    }
    // a reference with a corrupted row is not used (its reason said in the report)
    refColumn.filter { r => _referenceRefused = RefTrajectory.jump(r); _referenceRefused.isEmpty }.foreach { r =>
      // the smoothing of the reference: the window with the lowest BIC (a noisy reference wants a wide one)
      def fit(h: Int): RefTrajectory = { val rt = new RefTrajectory(r, fs, r.periodsPerUnit, h); rt.start(raw); start(rt, new Array[Double](n)); rt }
      val hs = RefTrajectory.HalfWidths.filter(h => h == RefTrajectory.HalfWidths.head || 8 * h <= n)
      var last: RefTrajectory = null
      val best = if (hs.size == 1) hs.head else hs.minBy { h => last = fit(h); if (SignalEngine.debug) System.err.println(f"reference smoothing $h: BIC $bic%.1f"); bic }
      val rt = if (hs.size > 1 && best == hs.last && !FitPath.isReference) last else fit(best) // the last one tried is the engine's state already
      val rms = phaseRms
      val stepPeriods = math.abs(rt.k) * RefTrajectory.step(r.values)
      if (r.values.min == r.values.max)
        _referenceRefused = Some(s"it does not move (${effects.Effect.show(r.values.min)} ${r.unit} on every row): not used, the motion is fitted from the signals")
      // (a scale that makes the phase no number, counts_per_period 2^63, too: it was told as "within NaN degree")
      else if (bic.isNaN || bic.isInfinite || rms.isNaN || rms.isInfinite)
        _referenceRefused = Some(f"its values (from ${r.values.min}%.4g to ${r.values.max}%.4g ${r.unit}) take the fit out of range: not used, the motion is fitted from the signals")
      else if (!(rms <= RefTrajectory.MaxPhaseRms))
        _referenceRefused = Some(f"the signals follow ${r.column} only within ${rms * 360}%.1f degree of fringe phase rms " +
          f"(at most ${RefTrajectory.MaxPhaseRms * 360}%.0f): not used, the motion is fitted from the signals")
      else if (stepPeriods > RefTrajectory.MaxStepPeriods) {
        // A coarse reference (an A/B count) knows the phase only to its step, the signals far better: where their
        // own trajectory is identifiable (segments over several periods) it is used; else the reference is.
        freeFit()
        if (Identifiable.periodsPerSegment(this) >= Identifiable.MinPeriodsPerSegment)
          _referenceRefused = Some(f"${r.column} moves in steps of ${stepPeriods}%.4g fringe period (coarser than " +
            f"${RefTrajectory.MaxStepPeriods}%.4g) and the record spans enough periods to fit the motion from the signals: not used")
        else _reference = Some(fit(best))
      } else _reference = Some(rt)
    }
    if (reference.isEmpty && !traj.isInstanceOf[Trajectory]) freeFit()
    // then settle until BIC does: samples held at a rail and the fit converge in turns, slowly when many sit at a rail (a
    // third of the samples at the rails take some 30 steps; left after four, the clipping passed for INL and odd harmonics)
    // (the fast path not when the last refining step gained < 0.5 already and no sample sits at a rail)
    var last = if (FitPath.isReference || !plainData) Double.PositiveInfinity else bic + lastGain; var k = 0
    while (k < 40 && last - bic > 0.5) { last = bic; refit(2, refineTraj = true, from = 1); k += 1 }
  }

  /** Fringe periods per turn, when the reference names turns (from its k and its turns per unit). */
  def periodsPerTurn: Option[Double] = reference.flatMap(r => r.ref.turnsPerUnit.map(t => math.abs(r.k) / t))
  /** Mechanical angle (radians) per sample from a reference that names turns. */
  lazy val mechAngle: Option[Array[Double]] = reference.flatMap(r => r.ref.turnsPerUnit.map(t => r.x.map(v => 2 * math.Pi * t * (v + r.xMid))))

  /** The residual's mean square along the signals' path (the fringe phase's direction) over its mean square across it
    * (off the ellipse). Noise, pickup, harmonics and clipping give about 1 (or less: the trajectory takes up part of
    * the first); motion the trajectory does not follow, more.
    */
  def alongOverAcross: Double = {
    var a = 0.0; var c = 0.0; var i = 0
    while (i < n) {
      val gs = gS(i); val gc = gC(i); val ww = gs * gs + gc * gc
      if (ww > 0) { val t = resS(i) * gs + resC(i) * gc; val r = resS(i) * gc - resC(i) * gs; a += t * t / ww; c += r * r / ww }
      i += 1
    }
    if (c > 0) a / c else Double.PositiveInfinity
  }

  /** The time (s) in which the fitted motion changes: its fringe frequency's rms over the rms of its rate of change
    * (1 / (2 pi f) for a back-and-forth at f), from differences over `Trajectory.MinLength` samples.
    */
  def motionTimeS: Double = {
    val k = math.min(n - 1, Trajectory.MinLength); if (k < 1) return Double.PositiveInfinity
    var ff = 0.0; var dd = 0.0; var i = 0
    while (i + k < n) { val d = (freq(i + k) - freq(i)) * fs / k; ff += freq(i) * freq(i); dd += d * d; i += 1 }
    if (dd > 0) math.sqrt(ff / dd) else Double.PositiveInfinity
  }

  /** `alongOverAcross` of the residual less its part that is a function of the fringe phase (a mean and harmonics 1 to
    * `FringeOrders` of it, along and across apart): what is left along the path beyond the across is motion. A harmonic
    * of the fringe on both channels turns with the fringe (its along part a wobble of the phase once or more per period,
    * its across part alike): segments shorter than a period follow its along part, and lowered BIC by that. A 0.3 %
    * 2nd harmonic on both channels at a constant 5 kHz went into 0.4-period segments, each effect then not identifiable.
    */
  def alongOverAcrossBeyondFringe: Double = {
    val k = 2 * SignalEngine.FringeOrders + 1; val g = k * (k + 1) / 2
    // per sample: the basis (1, sin and cos of 2 pi j phase), the along and across parts; their sums
    val m = Par.sums(n, g + 2 * k + 2) { (lo, hi, o) =>
      val b = new Array[Double](k); val sc = new Array[Double](2); var i = lo
      while (i < hi) {
        val gs = gS(i); val gc = gC(i); val ww = gs * gs + gc * gc
        if (ww > 0) {
          val w = 1 / math.sqrt(ww); val a = (resS(i) * gs + resC(i) * gc) * w; val c = (resS(i) * gc - resC(i) * gs) * w
          val t = phase(i); Turns.sinCos(t - Turns.floor(t), sc, 0)
          b(0) = 1.0; b(1) = sc(0); b(2) = sc(1); var j = 3
          while (j < k) { b(j) = b(j - 2) * sc(1) + b(j - 1) * sc(0); b(j + 1) = b(j - 1) * sc(1) - b(j - 2) * sc(0); j += 2 }
          var p = 0; var q = 0
          while (p < k) { var r = 0; while (r <= p) { o(q) += b(p) * b(r); q += 1; r += 1 }; o(g + p) += b(p) * a; o(g + k + p) += b(p) * c; p += 1 }
          o(g + 2 * k) += a * a; o(g + 2 * k + 1) += c * c
        }
        i += 1
      }
    }
    val gram = Array.ofDim[Double](k, k); var q = 0
    for (p <- 0 until k; r <- 0 to p) { gram(p)(r) = m(q); gram(r)(p) = m(q); q += 1 }
    def left(at: Int, total: Double): Double = {
      val rhs = Array.tabulate(k)(p => m(at + p)); val sol = LinearFit.normal(gram, rhs)
      if (!sol.ok) total else math.max(0.0, total - (0 until k).map(p => sol.beta(p) * rhs(p)).sum)
    }
    val c = left(g + k, m(g + 2 * k + 1))
    if (c > 0) left(g, m(g + 2 * k)) / c else Double.PositiveInfinity
  }

  /** Rms of the fringe phase residual (periods): how well the signals follow the phase model. */
  def phaseRms: Double = {
    var s = 0.0; var k = 0; var i = 0
    while (i < n) {
      val ww = gS(i) * gS(i) + gC(i) * gC(i)
      if (ww > 0) { val d = (resS(i) * gS(i) + resC(i) * gC(i)) / ww / (2 * math.Pi); s += d * d; k += 1 }
      i += 1
    }
    // a phase the slopes do not give at most samples (not finite: a reference far out of range) is no fit
    if (k < n / 2) Double.NaN else math.sqrt(s / k)
  }

  private def mid(a: Array[Double]): (Double, Double) = {
    var lo = Double.MaxValue; var hi = -Double.MaxValue; var i = 0
    while (i < a.length) { val v = a(i); if (v < lo) lo = v; if (v > hi) hi = v; i += 1 }
    (0.5 * (lo + hi), math.max(0.5 * (hi - lo), lsb))
  }

  /** Counts the changes of the fit's state (phase, fundamentals, default part, residual): a cache made at one count
    * holds while the count stays.
    */
  def version: Long = _version
  private var _version = 0L

  def evalTraj(): Unit = {
    _version += 1; phaseCount += 1
    Laps("traj: eval")(traj.eval(phase, freq))
    range = null
    Laps("traj: setFundamentals")(setFundamentals())
  }

  private var range: (Double, Double) = null
  /** The 2 % and 98 % points of the fringe frequency's magnitude (Hz): the speed range the record spans. */
  def speedRange: (Double, Double) = {
    if (range == null) {
      def rank(q: Double) = math.min(n - 1, (q * n).toInt)
      val a = OrderStats.of(n, i => math.abs(freq(i)), Seq(rank(0.02), rank(0.98)))
      range = (a(0), a(1))
    }
    range
  }
  /** Fringe periods travelled over the record (both directions counted). */
  def travelPeriods: Double = {
    if (travelAt != phaseCount) { var s = 0.0; var i = 0; while (i < n) { s += math.abs(freq(i)); i += 1 }; travel0 = s / fs; travelAt = phaseCount }
    travel0
  }
  // made once per phase (a round's candidates each ask)
  private var travel0 = 0.0; private var travelAt = -1L
  def fMin: Double = speedRange._1
  def fMax: Double = speedRange._2

  /** 2 pi times the fractional fringe phase of sample i. */
  @inline final def angle(i: Int): Double = 2 * math.Pi * (phase(i) - Turns.floor(phase(i)))
  /** The fractional fringe phase of sample i (turns, in [0, 1]). */
  @inline final def turn(i: Int): Double = phase(i) - Turns.floor(phase(i))

  // the phase's changes, and the phase and spec the fundamentals were made for (made again only when either changed)
  private var phaseCount = 0L
  private var madeFor: (Long, Boolean, Double, Map[String, Double]) = null
  /** s1, s2, c1, c2 for the current phase and spec. */
  private def setFundamentals(): Unit = {
    val key = (phaseCount, spec.hasSkew, spec.skewS, spec.bw)
    if (key == madeFor && !FitPath.isReference) return
    madeFor = key
    if (!spec.hasSkew && spec.bw.isEmpty) {
      _s1 = plainSin; _s2 = plainCos; _c1 = plainSin; _c2 = plainCos
      val ref = FitPath.isReference
      Par.blocks(n) { (lo, hi) =>
        val sc = new Array[Double](2); var i = lo
        while (i < hi) {
          if (ref) { val a = angle(i); plainSin(i) = math.sin(a); plainCos(i) = math.cos(a) }
          else { Turns.sinCos(turn(i), sc, 0); plainSin(i) = sc(0); plainCos(i) = sc(1) }
          i += 1
        }
      }
    } else {
      if (s1 eq plainSin) { _s1 = new Array[Double](n); _s2 = new Array[Double](n); _c1 = plainSin; _c2 = plainCos }
      fundamentals(spec, s1, s2, c1, c2)
    }
  }

  /** Fundamental columns of both channels under the skew and bandwidth of `sp`. */
  def fundamentals(sp: ModelSpec, a1: Array[Double], a2: Array[Double], b1: Array[Double], b2: Array[Double]): Unit = {
    val plain = !sp.hasSkew && sp.bw.isEmpty
    val resp = new ChannelResponse(sp)
    // the response from a table over the fringe frequencies when it holds to 1e-10 (fast path)
    val table = if (plain || FitPath.isReference) null else {
      val (lo, hi) = freqRange
      val t = new ResponseTable(resp, lo, hi, SignalEngine.ResponseBins, 1e-10)
      if (t.ok) t else null
    }
    val ref = FitPath.isReference
    Par.blocks(n) { (lo, hi) =>
      val o = new Array[Double](4); val sc = new Array[Double](2); var i = lo
      while (i < hi) {
        if (ref) { val a = angle(i); sc(0) = math.sin(a); sc(1) = math.cos(a) } else Turns.sinCos(turn(i), sc, 0)
        val sn = sc(0); val cs = sc(1)
        if (plain) { a1(i) = sn; a2(i) = cs; b1(i) = sn; b2(i) = cs }
        else {
          if (table != null) table(freq(i), sn, cs, o) else resp(freq(i), sn, cs, o)
          a1(i) = o(0); a2(i) = o(1); b1(i) = o(2); b2(i) = o(3)
        }
        i += 1
      }
    }
  }

  /** The lowest and highest fringe frequency (Hz, signed) of the current phase. */
  def freqRange: (Double, Double) = {
    if (fRange == null || fRangeAt != phaseCount) { fRange = Doubles.range(n)(freq(_)); fRangeAt = phaseCount }
    fRange
  }
  private var fRange: (Double, Double) = null
  private var fRangeAt = -1L

  def baseCols(a1: Array[Double], a2: Array[Double], b1: Array[Double], b2: Array[Double]): IndexedSeq[Col] =
    IndexedSeq(Col(ones, null), Col(a1, null), Col(a2, null), Col(null, ones), Col(null, b1), Col(null, b2))

  /** Columns of a linear term at the current state. */
  def termCols(t: Term): IndexedSeq[Col] = t match {
    case Term.Inl(ch) =>
      def t2(p: Array[Double]) = Doubles.tabulate(n)(i => (2 * p(i) * p(i) - 1) * lsb)
      def t3(p: Array[Double]) = Doubles.tabulate(n)(i => (4 * p(i) * p(i) * p(i) - 3 * p(i)) * lsb)
      val ps = if (ch != "cos") predS else null; val pc = if (ch != "sin") predC else null
      def on(p: Array[Double], f: Array[Double] => Array[Double]) = if (p == null) null else f(p)
      IndexedSeq(Col(on(ps, t2), on(pc, t2)), Col(on(ps, t3), on(pc, t3)))
    case t: Term.ContrastSpline => effects.ContrastAlongTravel.splineCols(this, t.knots)
    case Term.Interference(hz) =>
      val (a, b) = line(hz)
      IndexedSeq(Col(a, null), Col(b, null), Col(null, a), Col(null, b))
    case _ => termGen(t).get.whole(n)
  }

  /** A term's columns a block of samples at a time (`ColGen`), for the terms whose columns are a function of the
    * sample; None for INL (from the prediction, which the fit overwrites) and the contrast spline.
    */
  def termGen(t: Term): Option[ColGen] = {
    val T = true; val F = false
    def gen(sin: Array[Boolean], cos: Array[Boolean])(f: (Int, Int, Array[Array[Double]], Int) => Unit) = Some(new ColGen(sin, cos, f))
    t match {
      case Term.Harm(k, ch) =>
        val onS = ch != "cos"; val onC = ch != "sin"
        // the k-th harmonic of the fitted fundamental (u, v): its amplitude times sin and cos of k times its angle
        @inline def harm(ui: Double, vi: Double, o1: Array[Double], o2: Array[Double], q: Int): Unit = {
          val a = math.sqrt(ui * ui + vi * vi)
          if (a > 0) {
            val ia = 1 / a; val s = ui * ia; val c = vi * ia; var re = 1.0; var im = 0.0; var j = 0
            while (j < k) { val r2 = re * c - im * s; im = re * s + im * c; re = r2; j += 1 }
            o1(q) = a * im; o2(q) = a * re
          } else { o1(q) = 0; o2(q) = 0 }
        }
        val sin = (if (onS) Array(T, T) else Array[Boolean]()) ++ (if (onC) Array(F, F) else Array[Boolean]())
        val cos = (if (onS) Array(F, F) else Array[Boolean]()) ++ (if (onC) Array(T, T) else Array[Boolean]())
        // the low-passes' gain and lag at k f (none: the fundamental's, k times)
        val hr = harmonicResponse(k)
        gen(sin, cos) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) {
            val q = at + i - lo
            if (onS) { harm(us(i), vs(i), o(0), o(2), q); if (hr != null) hr(freq(i), 0, o(0), o(2), q) }
            if (onC) { val p = if (onS) 4 else 0; harm(uc(i), vc(i), o(p + 1), o(p + 3), q); if (hr != null) hr(freq(i), 1, o(p + 1), o(p + 3), q) }
            i += 1
          }
        }
      case Term.Drift =>
        gen(Array(T, F, T, F), Array(F, T, F, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) { val q = at + i - lo; val x = (i - 0.5 * (n - 1)) / fs; o(0)(q) = x; o(3)(q) = x; o(4)(q) = us(i) * x; o(7)(q) = uc(i) * x; i += 1 }
        }
      case Term.Contrast =>
        val m = Par.sum(n) { (lo, hi) => var s = 0.0; var i = lo; while (i < hi) { s += phase(i); i += 1 }; s } / n
        gen(Array(T, F, T, F), Array(F, T, F, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) { val q = at + i - lo; val x = phase(i) - m; o(0)(q) = x; o(3)(q) = x; o(4)(q) = us(i) * x; o(7)(q) = uc(i) * x; i += 1 }
        }
      case Term.Warmup(tau) =>
        gen(Array(T, F, T, F), Array(F, T, F, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) { val q = at + i - lo; val w = math.exp(-i / fs / tau); o(0)(q) = w; o(3)(q) = w; o(4)(q) = us(i) * w; o(7)(q) = uc(i) * w; i += 1 }
        }
      case Term.Crosstalk =>
        gen(Array(T, F), Array(F, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) { val q = at + i - lo; val w = 2 * math.Pi * freq(i); o(0)(q) = vc(i) * w; o(3)(q) = vs(i) * w; i += 1 }
        }
      case Term.Am =>
        val l = rec.linesPerRev.getOrElse(1.0)
        val m = mechAngle.orNull
        gen(Array(T, T), Array(T, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) {
            val q = at + i - lo; val th = if (m != null) m(i) else 2 * math.Pi * phase(i) / l; val c = math.cos(th); val s = math.sin(th)
            o(0)(q) = us(i) * c; o(1)(q) = uc(i) * c; o(2)(q) = us(i) * s; o(3)(q) = uc(i) * s; i += 1
          }
        }
      case Term.AngleHarm(m) =>
        val th = mechAngle.get
        gen(Array(T, T), Array(T, T)) { (lo, hi, o, at) =>
          var i = lo
          while (i < hi) {
            val q = at + i - lo; val c = 2 * math.Pi * math.cos(m * th(i)); val s = 2 * math.Pi * math.sin(m * th(i))
            o(0)(q) = gS(i) * c; o(1)(q) = gC(i) * c; o(2)(q) = gS(i) * s; o(3)(q) = gC(i) * s; i += 1
          }
        }
      case Term.Interference(hz) =>
        gen(Array(T, T, F, F), Array(F, F, T, T)) { (lo, hi, o, at) => lineBlock(hz, lo, hi, o(0), o(2), o(5), o(7), at) }
      case Term.ContrastSpline(k) => Some(effects.ContrastAlongTravel.splineGen(this, k))
      case _ => None
    }
  }

  /** How the spec's low-passes pass harmonic k beside the fundamental (`HarmonicResponse`), null without any. */
  def harmonicResponse(k: Int): HarmonicResponse =
    if (spec.bw.isEmpty || k < 2) null else { val (lo, hi) = freqRange; new HarmonicResponse(spec, k, lo, hi) }

  /** sin and cos of a fixed-frequency line at every sample: the last one made is kept while two arrays of the record's
    * length fit in a sixteenth of the heap (a refit makes the columns of an accepted pickup at every iteration; they do not
    * change with the fit).
    */
  private def line(hz: Double): (Array[Double], Array[Double]) = {
    val k = lastLine
    if (k != null && k._1 == hz) return (k._2, k._3)
    val a = new Array[Double](n); val b = new Array[Double](n)
    if (FitPath.isReference) { var i = 0; while (i < n) { a(i) = math.sin(2 * math.Pi * hz * i / fs); b(i) = math.cos(2 * math.Pi * hz * i / fs); i += 1 } }
    else Par.blocks(n, Gram.Block)((lo, hi) => lineBlock(hz, lo, hi, a, b, null, null, lo))
    if (16L * n <= holdBytes / 2) lastLine = (hz, a, b) // a long record's are made again (memory before time)
    (a, b)
  }
  @volatile private var lastLine: (Double, Array[Double], Array[Double]) = null
  /** The line's sin (into a, and a2 unless null) and cos (b, b2) over samples [lo, hi), sample i at at + i - lo: by
    * rotation from the sin and cos at lo (the error stays near 1e-12 over a block of `Gram.Block`).
    */
  private def lineBlock(hz: Double, lo: Int, hi: Int, a: Array[Double], b: Array[Double], a2: Array[Double], b2: Array[Double], at: Int): Unit = {
    val w = 2 * math.Pi * hz / fs; val sw = math.sin(w); val cw = math.cos(w)
    var s = math.sin(w * lo); var c = math.cos(w * lo); var i = lo
    while (i < hi) {
      val q = at + i - lo; a(q) = s; b(q) = c; if (a2 != null) { a2(q) = s; b2(q) = c }
      val s1 = s * cw + c * sw; c = c * cw - s * sw; s = s1; i += 1
    }
  }

  /** Position along the travel in fringe periods, centred on the record's mean position. */
  def travel: Array[Double] = { val m = travelMean; Doubles.tabulate(n)(i => phase(i) - m) }
  /** The record's mean position (fringe periods): `travel` is the phase less it. */
  def travelMean: Double = Par.sum(n) { (lo, hi) => var s = 0.0; var i = lo; while (i < hi) { s += phase(i); i += 1 }; s } / n
  /** The lowest and highest value of `travel`, read where it is needed (no array of the record's length). */
  def travelRange: (Double, Double) = { val m = travelMean; Doubles.range(n)(i => phase(i) - m) }

  /** exp(-t / tau) from the first sample: the part of a warm-up still to come. */
  def warmupBasis(tau: Double): Array[Double] = Doubles.tabulate(n)(i => math.exp(-i / fs / tau))
  /** A warm-up's columns from its basis w and the fundamentals u, v (all samples, or a subsample's). */
  def warmupCols(w: Array[Double], u: Int => Double, v: Int => Double): IndexedSeq[Col] =
    IndexedSeq(Col(w, null), Col(null, w), Col(Doubles.tabulate(w.length)(i => u(i) * w(i)), null), Col(null, Doubles.tabulate(w.length)(i => v(i) * w(i))))

  private def mul(a: Int => Double, b: Array[Double]): Array[Double] = {
    val o = new Array[Double](n); var i = 0
    while (i < n) { o(i) = a(i) * b(i); i += 1 }
    o
  }

  /** Each code's preimages under the faults `fl` (codes as the ADC's pins), a table over the converter's codes made
    * once per set of faults.
    */
  private def preimages(fl: Seq[Fault]): Array[Array[Int]] = synchronized {
    preTables.getOrElseUpdate(fl, Array.tabulate(if (rec.adc.bits <= 16) 1 << rec.adc.bits else 0)(c => preimagesOf(fl, c)))
  }
  private val preTables = scala.collection.mutable.Map.empty[Seq[Fault], Array[Array[Int]]]
  /** Each code's value (full scale), for the codes the preimage tables cover. */
  private lazy val codeValues: Array[Double] = Array.tabulate(if (rec.adc.bits <= 16) 1 << rec.adc.bits else 0)(c => rec.adc.fromPins(c) * lsb)
  private def preimagesOf(fl: Seq[Fault], code: Int): Array[Int] = fl.foldLeft(Seq(code))((cs, f) => cs.flatMap(f.preimages)).distinct.toArray

  /** Measured values with faults undone; samples at a saturation level (ADC rails or a clipping effect) are censored:
    * their value is replaced by the prediction and `cens` holds the distance from the prediction up to the level (NaN
    * where not censored), for the Tobit likelihood.
    * A fault's code has several preimages. Hard (`soft` false, or a fault new to the spec): the one closest to the
    * prediction. Soft (once the current spec's noise is fitted): their mean weighted by each one's likelihood under that
    * noise (an EM step of the mixture likelihood); `Repaired` then holds the weights' variance and entropy, which
    * -2 ln L adds.
    * The closest preimage pulls the data toward the prediction where the preimages are a few sd apart: a 0.6 LSB
    * pickup fitted with bit 2 stuck came out 1 % (6 sd) low at 5 M samples.
    */
  def repair(sp: ModelSpec, censor: Boolean = true, soft: Boolean = false, inPlace: Boolean = false): Repaired = {
    val adc = rec.adc
    val nz = _noise; val useSoft = soft && nz.m2ll != 0 && sp.faults == spec.faults
    // the prediction (the repaired data less the residual) read where it is needed, not made as an array
    def one(ch: Int, y: Array[Double], codes: Array[Int], rp: Array[Double], rr: Array[Double], pv0: Array[Float]): (Array[Double], Array[Double], Array[Float], Double, Double, Double, Array[Boolean]) = {
      val fl = sp.faults.filter(_.ch == ch); val cl = sp.clips.filter(c => c.ch == ch && !c.after)
      // a saturation with the noise after it: a sample there is its level plus noise, whatever the signal beyond (held at
      // the prediction plus that noise: it tells the fit nothing, and its residual is the noise about the level)
      val ca = sp.clips.filter(c => c.ch == ch && c.after)
      val loA = (Double.NegativeInfinity +: ca.map(_.lo)).max; val hiA = (Double.PositiveInfinity +: ca.map(_.hi)).min
      val flat = ca.nonEmpty
      // the noise variance at sample i (the soft repair's weights)
      val white = if (ch == 0) nz.varS else nz.varC; val j2 = nz.jitter2
      @inline def noiseVar(i: Int): Double = {
        val d = if (j2 == 0) 0.0 else if (spec.jitter) (if (ch == 0) timeSlopeS(i) else timeSlopeC(i)) else if (spec.phaseNoise) (if (ch == 0) vs(i) else vc(i)) else if (spec.intensityNoise) (if (ch == 0) us(i) else uc(i)) else 0.0
        math.max(1e-30, white + j2 * d * d)
      }
      val lo = (railLo +: cl.map(_.lo)).max; val hi = (railHi +: cl.map(_.hi)).min
      val ex = _excluded
      val pre = if (fl.isEmpty) null else preimages(fl)
      val vals = if (pre == null) null else codeValues
      // the sample's value with the faults undone (the preimage of its code closest to the prediction p)
      @inline def value(i: Int, p: Double): Double = {
        var v = y(i)
        if (pre != null) {
          val c0 = codes(i)
          val table = c0 >= 0 && c0 < pre.length
          val cands = if (table) pre(c0) else preimagesOf(fl, c0)
          @inline def of(c: Int) = if (table) vals(c) else adc.fromPins(c) * lsb
          var best = c0; var bestV = 0.0; var bestD = Double.MaxValue; var q = 0
          while (q < cands.length) { val c = cands(q); val cv = of(c); val d = math.abs(cv - p); if (d < bestD) { bestD = d; best = c; bestV = cv }; q += 1 }
          if (best != c0) v = bestV
        }
        v
      }
      @inline def censored(v: Double) = censor && (v >= hi - 0.5 * lsb || v <= lo + 0.5 * lsb)
      // without faults most records change nothing: a scan first, so that an unchanged channel is `y` itself
      if (pre == null && ex == null && !censor && !flat) return (y, null, null, 0.0, 0.0, 0.0, null)
      if (pre == null && ex == null && !flat && Par.sum(n) { (a, b) => var k = 0.0; var i = a; while (i < b) { if (censored(y(i))) k += 1; i += 1 }; k } == 0)
        return (y, null, null, 0.0, 0.0, 0.0, null)
      // `inPlace`: over the fit's own arrays (each sample's prediction is read before its value is written), never the data
      val out = if (inPlace && (rp ne y) && rp.length == n) rp else new Array[Double](n)
      // soft: each sample's weights' variance (full scale squared; 0 where one preimage), in single precision (a long
      // record's array; the sums are of the values kept); every sample's written
      val pv = if (!(useSoft && pre != null)) null else if (inPlace && pv0 != null && pv0.length == n) pv0 else new Array[Float](n)
      // the soft value at sample i (the hard one's code when the weights are all on it): m(2) += variance, m(3) += entropy
      @inline def softValue(i: Int, p: Double, m: Array[Double]): Double = {
        val c0 = codes(i)
        val table = c0 >= 0 && c0 < pre.length
        val cands = if (table) pre(c0) else preimagesOf(fl, c0)
        if (cands.length < 2) { pv(i) = 0; return y(i) }
        val nv = noiseVar(i); val h = -0.5 / nv
        if (cands.length == 2) {
          // a stuck bit's two preimages: the far one's weight relative to the near one's, w = exp(a)
          val v0 = if (table) vals(cands(0)) else adc.fromPins(cands(0)) * lsb; val v1 = if (table) vals(cands(1)) else adc.fromPins(cands(1)) * lsb
          val d0 = v0 - p; val d1 = v1 - p; val near0 = d0 * d0 <= d1 * d1
          val vn = if (near0) v0 else v1; val u = if (near0) v1 - v0 else v0 - v1
          val a = h * (if (near0) d1 * d1 - d0 * d0 else d0 * d0 - d1 * d1)
          if (!(a > -60)) { pv(i) = 0; return vn } // (and a NaN prediction: the closest preimage, as the hard repair)
          val w = math.exp(a); val z = 1 + w; val t = w / z; val vr = (t * (1 - t) * u * u).toFloat
          pv(i) = vr; m(2) += vr; m(3) += math.log(z) - a * t; m(4) += vr / nv
          return vn + t * u
        }
        // weights relative to the closest preimage's (no underflow): w_k = exp(h ((v_k - p)^2 - d_min^2)), 1 for it
        var dmin = Double.MaxValue; var k = 0; var q = 0
        while (q < cands.length) { val c = cands(q); val d = (if (table) vals(c) else adc.fromPins(c) * lsb) - p; if (d * d < dmin) { dmin = d * d; k = q }; q += 1 }
        val vk = if (table) vals(cands(k)) else adc.fromPins(cands(k)) * lsb
        // the others' sums about the closest one's value (its own terms are 1, 0, 0): no cancellation in the variance
        var z = 1.0; var s1 = 0.0; var s2 = 0.0; var sl = 0.0; q = 0
        while (q < cands.length) {
          if (q != k) {
            val c = cands(q); val v = if (table) vals(c) else adc.fromPins(c) * lsb; val d = v - p
            val a = h * (d * d - dmin)
            if (a > -60) { val w = math.exp(a); val u = v - vk; z += w; s1 += w * u; s2 += w * u * u; sl += w * a }
          }
          q += 1
        }
        val du = s1 / z; pv(i) = math.max(0.0, s2 / z - du * du).toFloat; val vr = pv(i).toDouble
        if (z > 1) { m(2) += vr; m(3) += math.log(z) - sl / z; m(4) += vr / nv } // entropy: -sum (w/z) ln(w/z)
        vk + du
      }
      // a flat top's samples scatter by the noise after the saturation alone (the read head's, before it, is cut off
      // there): their deviations from the level scaled to the channel's noise, by g = sqrt(its variance / theirs), and
      // -2 ln L given back 2 ln g each (the entropy's term): the two variances' likelihood. Without it another
      // generator's 0.3 LSB before and 1 LSB after a saturation made the flat tops' lower noise a phase noise.
      val g = if (!flat || nz.m2ll == 0) 1.0 else {
        val q = Par.sums(n, 2) { (a, b, m) =>
          var i = a
          while (i < b) {
            val p = rp(i) - rr(i); val v = y(i)
            if (!(ex != null && ex(i)) && !censored(v)) {
              if (v >= hiA || p >= hiA) { m(0) += (v - hiA) * (v - hiA); m(1) += 1 }
              else if (v <= loA || p <= loA) { m(0) += (v - loA) * (v - loA); m(1) += 1 }
            }
            i += 1
          }
        }
        if (q(1) < 2 || !(q(0) > 0)) 1.0 else math.max(0.1, math.min(10.0, math.sqrt(white * q(1) / q(0))))
      }
      val lnG = math.log(g)
      // the flat top's samples (held at the prediction plus their scatter: the fit leaves them out, `deepCensored`)
      val held = if (flat) new Array[Boolean](n) else null
      // the censored samples' distances, NaN elsewhere: made when the first one is met (most repairs censor none)
      var cen: Array[Double] = null
      val lock = new Object
      def cenArray(): Array[Double] = lock.synchronized {
        if (cen == null) { val a = new Array[Double](n); java.util.Arrays.fill(a, Double.NaN); cen = a }
        cen
      }
      val counts = Par.sums(n, 5) { (a, b, m) =>
        var mine: Array[Double] = null
        var i = a
        while (i < b) {
          val p = rp(i) - rr(i)
          if (ex != null && ex(i)) { out(i) = p; m(0) += 1; if (pv != null) pv(i) = 0 }
          else {
            val v = if (pv != null) softValue(i, p, m) else value(i, p)
            if (censored(v)) {
              if (mine == null) mine = cenArray()
              val top = v >= hi - 0.5 * lsb; val d = if (top) v - 0.5 * lsb - p else p - (v + 0.5 * lsb)
              mine(i) = d; m(1) += 1
              // EM's value of a censored sample: the mean of the noise's tail beyond the level (once the noise is fitted).
              // Held at the prediction, the fit was that of the samples inside the level alone, whose noise the level
              // cuts: another generator's 1.0 FS clipped at 0.7 came out 0.075 % low, 1 LSB near the level, and was
              // told as harmonics 3, 5 and 7
              // A sample at the level with the prediction more than `Deep` noise widths inside it is no tail of that noise
              // (a glitch to the rail, a misfit): held at the prediction, as before the tail means (two glitches in a row
              // to code 0 pulled the fit by 20 LSB toward the rail and were no glitches any more)
              val sd = if (nz.m2ll == 0) 0.0 else math.sqrt(noiseVar(i))
              out(i) = if (sd > 0 && d < SignalEngine.Deep * sd) p + (if (top) sd else -sd) * Noise.tailMean(d / sd) else p
              if (pv != null && pv(i) != 0) { m(2) -= pv(i); m(4) -= pv(i) / noiseVar(i); pv(i) = 0 } // held at the prediction
            }
            else if (flat && (v >= hiA || p >= hiA)) { out(i) = p + (v - hiA) * g; m(0) += 1; m(3) += lnG; held(i) = true }
            else if (flat && (v <= loA || p <= loA)) { out(i) = p + (v - loA) * g; m(0) += 1; m(3) += lnG; held(i) = true }
            else { out(i) = v; if (v != y(i)) m(0) += 1 }
          }
          i += 1
        }
      }
      if (pv == null && counts(0) == 0 && counts(1) == 0) (y, null, null, 0.0, 0.0, 0.0, null)
      else (out, if (counts(1) == 0) null else lock.synchronized(cen), pv, counts(2), counts(3), counts(4), held)
    }
    val (a, ca, pa, sa, ea, la, ha) = one(0, ys, rec.sin, _repS, resS, _cens.pvS); val (b, cb, pb, sb, eb, lb, hb) = one(1, yc, rec.cos, _repC, resC, _cens.pvC)
    Repaired(a, b, ca, cb, pa, pb, sa, sb, ea + eb, la, lb, step, ha, hb)
  }

  /** The samples the linear fit and the phase leave out (`Gram.Skip`), null where none: a channel held at a saturation
    * level with the prediction `SignalEngine.Deep` noise widths beyond it. Its value there is the noise's tail mean
    * beyond the level (`repair`), next to the prediction: held in the fit it anchored the fit where it was, each step
    * going a fifth of the way (the expectation-maximization's rate, the information the level hides). Another
    * generator's 1.0 FS clipped at 0.7 on both channels, half the samples, stopped after 12 refits with an rms of 10
    * LSB and was told as harmonics 3, 5 and 7. Left out, the step is the likelihood's Newton step.
    */
  private def deepCensored: Gram.Skip = {
    val c = _cens
    if ((c.censS == null && c.censC == null && c.heldS == null && c.heldC == null) || _noise.m2ll == 0) null
    // a saturation level new to the fit: the prediction is still the clipped shape the fit before it followed, at the
    // level; every sample held there is left out of the first solve (from the samples inside the level alone)
    else if (censClips != clipsFitted) Gram.Skip(c.censS, Double.PositiveInfinity, c.censC, Double.PositiveInfinity, c.heldS, c.heldC)
    else Gram.Skip(c.censS, -SignalEngine.Deep * math.sqrt(_noise.varS), c.censC, -SignalEngine.Deep * math.sqrt(_noise.varC), c.heldS, c.heldC)
  }
  // the saturation levels of the repair as it stands, and of the one the last solve had
  private var censClips: Vector[Clip] = Vector.empty; private var clipsFitted: Vector[Clip] = Vector.empty

  /** No fault repaired and no sample held at a rail: the fit's data do not change from one step to the next. */
  private def plainData: Boolean = spec.faults.isEmpty && !spec.clips.exists(_.after) && cens.censS == null && cens.censC == null

  /** How much the last refining step of `refit` lowered BIC (infinite before the first). */
  def lastGain: Double = _lastGain
  private var _lastGain = Double.PositiveInfinity

  /** Refits the default part and all linear terms (and the trajectory) for the current spec. */
  def refit(iters: Int, refineTraj: Boolean, from: Int = 0): Unit = {
    var it = from
    while (it < iters) {
      val before = if (_noise.m2ll == 0 || _traj == null) Double.PositiveInfinity else bic; val refines = it > 0 && refineTraj
      if (it > 0 && refineTraj && traj.isInstanceOf[RefTrajectory]) jointStep(traj.asInstanceOf[RefTrajectory])
      else if (it > 0 && refineTraj) Laps("refit: trajectory and fundamentals") {
        // the phase residual of each sample (periods) weighted by its slope's square, read where the fit sums it
        val sk = deepCensored; val ex = lost
        def w(i: Int): Double = { val ww = gS(i) * gS(i) + gC(i) * gC(i); if (ww > 0) ww else 0.0 }
        def d(i: Int): Double = (resS(i) * gS(i) + resC(i) * gC(i)) / w(i) / (2 * math.Pi)
        Laps("traj: addFit")(traj match {
          case t: Trajectory => t.addFitBy { (i, o) =>
            // a channel held at a saturation level far below the prediction tells nothing of the phase there: its
            // slope left out (held at the prediction, it anchored the phase where it was)
            // (a run of samples lost, held at the prediction, anchored the phase where it was too: a hold of 40 samples
            // left the default fit's stopped phase and a misfit window of 32 x the noise floor)
            val out = ex != null && ex(i)
            val gs = if (out || (sk != null && sk.s(i))) 0.0 else gS(i); val gc = if (out || (sk != null && sk.c(i))) 0.0 else gC(i)
            val ww = gs * gs + gc * gc
            if (ww > 0) { o(0) = (resS(i) * gs + resC(i) * gc) / ww / (2 * math.Pi); o(1) = ww } else { o(0) = 0.0; o(1) = 0.0 }
          }
          case t => t.addFit(Doubles.tabulate(n)(i => if (w(i) > 0) d(i) else 0.0), Doubles.tabulate(n)(w))
        })
        Laps("traj: evalTraj")(evalTraj())
      }
      if (it > 0) Laps("refit: repair") { val r = repair(spec, soft = true, inPlace = !shared); _repS = r.s; _repC = r.c; _cens = r; shared = false; censClips = spec.clips }
      Laps("refit: fundamentals")(setFundamentals())
      val cols = groups()
      _sol = Laps("refit: solve")(cols.solve(repS, repC, deepCensored))
      _termIndex = spec.terms.zip(cols.offsets.tail).toMap; clipsFitted = censClips
      // the terms' columns may be made again below: from the state they were fitted in (the old default part)
      Laps("refit: residual") { residual(cols); holdExcluded(); predictionSlope(cols, sol.beta.take(6)) }
      _colBase = _base; _base = sol.beta.take(6)
      it += 1
      _noise = Laps("refit: noise")(Noise.fit(resS, resC, noiseSlopes(spec), cens))
      _version += 1
      if (refines) _lastGain = before - bic
      if (SignalEngine.debug) System.err.println(f"refit $it: rms $rms%.4g bic $bic%.8g")
    }
  }

  /** The free trajectory's segments halved where cubics on the halves lower BIC by more than their 4 parameters and
    * the threshold: the phase residual's weighted sum of squares they take up over the residual's variance, beyond
    * what the same cubics take up of the residual across the path (motion is along it alone), each
    * sample's standardised phase residual held within `SplitZ` (one glitch splits nothing). For motion that changes
    * within a segment (a move ending in a standstill, a jerk) and not over the record: the uniform segments the default
    * fit chose left a move-and-dwell's transitions as a material departure against fringe phase. Halves of a fringe
    * period at the typical speed and `Trajectory.MinLength` at least; refitted after each pass, kept while BIC falls.
    * After the bad data are out (a glitch in a short segment threw its cubic off). True when a segment was halved.
    */
  def splitSegments(): Boolean = {
    val least = math.max(Trajectory.MinLength, Identifiable.shortestSegment(n, fs, typicalHz))
    var pass = 0
    while (pass < SignalEngine.SplitPasses) traj match {
      case t: Trajectory if t.len >= 2 * least =>
        val k = 4 * math.Pi * math.Pi / meanSquare
        if (!(k > 0 && !k.isInfinite)) return pass > 0
        val sk = deepCensored; val ex = lost; val zMax = SignalEngine.SplitZ
        // the residual along the path (a phase error) and across it, alike: motion the cubics miss is along it alone;
        // a pickup, a glitch or an offset's change is as much across, and halves would take up its along part
        def part(along: Boolean): Array[Double] = t.splitGains({ (i, o) =>
          val out = ex != null && ex(i)
          val gs = if (out || (sk != null && sk.s(i))) 0.0 else gS(i); val gc = if (out || (sk != null && sk.c(i))) 0.0 else gC(i)
          val ww = gs * gs + gc * gc
          if (ww > 0) {
            val d = (if (along) resS(i) * gs + resC(i) * gc else resS(i) * gc - resC(i) * gs) / ww / (2 * math.Pi)
            val lim = zMax / math.sqrt(k * ww)
            o(0) = math.max(-lim, math.min(lim, d)); o(1) = ww
          } else { o(0) = 0.0; o(1) = 0.0 }
        }, least)
        val (ga, gc) = (part(along = true), part(along = false))
        val which = ga.indices.map(j => (ga(j) - gc(j)) * k > 4 * lnN + SignalExplain.Threshold).toArray
        // a departure at a few places is the motion's (a move's end); one in many segments is the signal's or the
        // segment length's, which the lengths' BIC chose (a 5 LSB pickup at 1 kHz on 3 kHz fringes: 89 of 366)
        if (!which.exists(identity) || which.count(identity) > SignalEngine.SplitShare * t.nseg) return pass > 0
        val back = save().getOrElse(return pass > 0)
        val before = bic; val ph = phase.clone()
        val nt = t.split(which); _traj = nt; nt.addFit(ph, null); evalTraj(); refit(3, refineTraj = true, from = 1)
        if (SignalEngine.debug) System.err.println(f"segments split: ${which.count(identity)} of ${t.nseg}, BIC $bic%.1f against $before%.1f")
        if (!(bic < before)) { back(); return pass > 0 }
        pass += 1
      case _ => return pass > 0
    }
    pass > 0
  }

  // the segment lengths the default fit tried for a free trajectory, longest first
  private var segmentLens: Seq[Int] = Nil

  /** A free trajectory of segments shorter than the longest the default fit tried (its motion misfit asked for them)
    * is fitted again with each longer length from the phase as it stands, once an effect is in the spec, and the one
    * with the lowest BIC kept. What looked like motion to the default fit may be that effect: an offsets' warm-up on a
    * back-and-forth made it take segments of 244 samples instead of 1564, which took up part of the warm-up (its
    * time constant came out 20 ms for `simulate`'s 25). True when a longer length is kept.
    */
  def relengthen(): Boolean = traj match {
    case t: Trajectory if !FitPath.isReference && segmentLens.exists(_ > t.len) =>
      val back = save()
      if (back.isEmpty) return false
      val start = bic; val ph = phase.clone()
      var best = (start, t.len); var bestBack = back
      for (l <- segmentLens.filter(_ > t.len)) {
        bestBack.get(); val nt = new Trajectory(n, l, fs); _traj = nt; nt.addFit(ph, null); evalTraj(); converge()
        // (and the longer segments must follow the motion: a residual along the signals' path is motion they miss, which
        // the next effects' fits would take up; a clipped slow back-and-forth kept longer ones by BIC and ended misfit)
        val follows = alongOverAcross <= SignalEngine.MotionMisfit
        if (SignalEngine.debug) System.err.println(f"segments of $l samples again: BIC $bic%.1f against $start%.1f, residual along / across the fringe $alongOverAcross%.3f")
        if (bic < best._1 && follows) { best = (bic, l); bestBack = save() }
      }
      if (best._2 == t.len || bestBack.isEmpty) { back.get(); false } else { bestBack.get(); true }
    case _ => false
  }

  /** Gauss-Newton step of a reference map jointly with the default part and the terms (fitted in turn they converge
    * slowly: a harmonic of the fringe and the lag share part of their shape). The offset stays where `start` put it.
    */
  private def jointStep(r: RefTrajectory): Unit = {
    // the offset is left out: the fundamental's own phases (default part) already are one
    val jc = r.basis.tail.map { b =>
      val a = new Array[Double](n); val c = new Array[Double](n); var i = 0
      while (i < n) { val v = 2 * math.Pi * (if (b == null) 1.0 else b(i)); a(i) = gS(i) * v; c(i) = gC(i) * v; i += 1 }
      Col(a, c)
    }
    val s = groups(IndexedSeq(jc.toIndexedSeq)).solve(repS, repC)
    if (s.ok && jc.nonEmpty) { r.addDelta(0.0 +: s.beta.takeRight(jc.size)); evalTraj() }
  }

  /** The fit as it stands (spec, trajectory, data, solution, residual), to go back to when a trial refit is not kept:
    * `restore` gives the same state to the bit, where fitting the old spec again would end near it after some refits.
    * `light` (the default when the residual's copy would take more than a 32nd of the heap): the residual is not copied
    * but made again from the solution, the data and the columns it was made from (a pass over the record; at 20 M
    * samples in 4 GB the copy held through every trial ran the heap out, and fitting the old spec again took some
    * refits). None where that cannot give the same residual: samples weighted out (their data are held in place) or
    * an INL term (its columns come from the prediction).
    */
  def save(light: Boolean = 16L * n > Runtime.getRuntime.maxMemory / 32): Option[() => Unit] =
    if (light && (_excluded != null || spec.terms.exists(_.isInstanceOf[Term.Inl]))) None else {
    val sp = spec; val tr = _traj; val trBack = tr.keep()
    val held = _excluded != null // the data of excluded samples are held at the prediction in place: copies then
    val (rS, rC, cn) = if (held) { val a = _repS.clone(); val b = _repC.clone(); (a, b, _cens.copy(s = a, c = b)) } else (_repS, _repC, _cens)
    val (b, cb, so, ti, no, gs, gc, lg) = (_base, _colBase, _sol, _termIndex, _noise, slopeS, slopeC, _lastGain); val (cf, cc) = (clipsFitted, censClips)
    val resS0 = if (light) null else resS.clone(); val resC0 = if (light) null else resC.clone()
    shared = true
    Some { () =>
      spec = sp; _traj = tr; trBack(); evalTraj() // the phase, frequency and fundamentals from the trajectory
      _repS = rS; _repC = rC; _cens = cn; shared = true
      _sol = so; _termIndex = ti; _noise = no; slopeS = gs; slopeC = gc; _lastGain = lg; clipsFitted = cf; censClips = cc
      if (light) {
        // the residual as the last refit made it: its columns from the default part they were made with
        _base = cb; groups().addToBoth(resS, resC, so.beta, -1.0, repS, repC)
      } else { System.arraycopy(resS0, 0, resS, 0, n); System.arraycopy(resC0, 0, resC, 0, n) }
      _base = b; _colBase = cb
      _version += 1
    }
  }
  /** The default part the last residual's columns were made with (a refit makes them before it updates `base`). */
  private var _colBase: Array[Double] = _base

  /** Refits until BIC stops falling (fault repairs and the trajectory settle over a few iterations). `moved`: only
    * nonlinear parameters of the spec moved a little (a polish), no effect is new: one refining step before the first
    * check, and the loop stops on a small gain even with repairs (the reference path fits as for a new effect).
    * `tune` (null: none) may move a nonlinear parameter of the spec before each of the loop's refits, and says by how
    * many of its sd (0: not moved).
    */
  def converge(maxIters: Int = 12, moved: Boolean = false, tune: () => Double = null): Unit = {
    val quick = moved && !FitPath.isReference
    // three steps before the first check: a new fault's repair may gain little at its first step and much later
    refit(if (quick) 2 else 3, refineTraj = true)
    // then one refining step at a time (a plain solve first would repeat the last one's fit), unless the third step
    // gained less than the loop asks of a step and nothing is repaired or held at a rail (a repair may gain little at
    // one step and much at the next; the reference path always takes one more)
    var prev = if (FitPath.isReference || (!plainData && !quick)) Double.PositiveInfinity else bic + lastGain; var k = if (quick) 2 else 3
    val from = if (FitPath.isReference) 0 else 1; val step = 2 - from
    // a repair's EM moves the solution by about half its distance to the fixed point a step: after two steps the fast
    // path jumps along their line (SQUAREM, on the linear solution and the noise) and takes one step from there, kept
    // when it ends lower than the last step; and it stops when the steps' ratio puts the rest of the way below 0.5
    val fast = !FitPath.isReference && !plainData
    var jump = fast
    var hist: List[Step] = if (fast) List(Step.now) else Nil
    var gains: List[Double] = Nil // the plain steps' gains since the last jump, the last first
    def rest: Double = gains match { case g2 :: g1 :: _ if g1 > g2 && g2 > 0 => g2 * g2 / (g1 - g2); case _ => Double.PositiveInfinity }
    while (k < maxIters && prev - bic > 0.5 && !(fast && rest < 0.5)) {
      // a nonlinear parameter's step before the refit (`tune`, a line's frequency): after one of more than its sd the
      // steps before it are no jump's, and a plain solve comes first (the trajectory refined from the old residual
      // would take up the step's part again)
      val tuned = tune != null && tune() > 1
      if (tuned) { hist = Nil; gains = Nil }
      prev = bic; refit(2, refineTraj = true, from = if (tuned) 0 else from); k += step
      if (fast) { gains = (prev - bic) :: gains; hist = (Step.now :: hist).take(3) }
      if (jump && hist.size == 3 && prev - bic > 20 && k < maxIters) squarem(hist(2), hist(1), hist(0)).foreach { case (beta, nz) =>
        val at = bic; val back = save()
        set(beta, nz); refit(2, refineTraj = true, from = 1); k += 1
        if (SignalEngine.debug) System.err.println(f"jump: bic $bic%.8g against $at%.8g")
        if (bic <= at) { prev = at; _lastGain = at - bic; hist = List(Step.now); gains = Nil }
        else { back match { case Some(r) => r(); case None => prev = Double.PositiveInfinity }; jump = false }
      }
    }
  }

  /** A refit's linear solution and noise. */
  private final case class Step(beta: Array[Double], noise: Noise)
  private object Step { def now: Step = Step(sol.beta.clone(), _noise) }

  /** SQUAREM's point from three successive steps (Varadhan and Roland 2008): with r = t1 - t0 and v = t2 - 2 t1 + t0,
    * the solution t0 - 2 a r + a^2 v, a = -|r| / |v| (at most -1: -1 gives t2), and the noise alike. None when the
    * steps do not shrink by a third at least: a ratio near 1 is a drift, which a jump takes too far. The trajectory is
    * left out: in a stuck bit's round its changes still grew where the solution's shrank, and jumping it too ended no
    * lower (1 M bench).
    */
  private def squarem(t0: Step, t1: Step, t2: Step): Option[(Array[Double], Noise)] = {
    val m = t0.beta.length
    if (t1.beta.length != m || t2.beta.length != m) return None
    val r = Array.tabulate(m)(i => t1.beta(i) - t0.beta(i)); val v = Array.tabulate(m)(i => t2.beta(i) - 2 * t1.beta(i) + t0.beta(i))
    val nr = math.sqrt(sumSq(r)); val nv = math.sqrt(sumSq(v))
    if (!(nr > 0) || !(nr <= 3 * nv)) return None
    val a = -nr / nv
    def at(x0: Double, x1: Double, x2: Double): Double = x0 - 2 * a * (x1 - x0) + a * a * (x2 - 2 * x1 + x0)
    val beta = Array.tabulate(m)(i => at(t0.beta(i), t1.beta(i), t2.beta(i)))
    val (n0, n1, n2) = (t0.noise, t1.noise, t2.noise)
    def pos(x0: Double, x1: Double, x2: Double) = math.max(1e-3 * x2, at(x0, x1, x2))
    val nz = n2.copy(varS = pos(n0.varS, n1.varS, n2.varS), varC = pos(n0.varC, n1.varC, n2.varC), jitter2 = math.max(0.0, at(n0.jitter2, n1.jitter2, n2.jitter2)))
    if (SignalEngine.debug) System.err.println(f"jump: a $a%.3f")
    if (beta.forall(x => !x.isNaN && !x.isInfinite)) Some((beta, nz)) else None
  }

  /** The fit at the solution `beta` and noise `nz`, on the current trajectory and data. */
  private def set(beta: Array[Double], nz: Noise): Unit = {
    _base = beta.take(6); _colBase = _base
    val cols = groups()
    cols.addToBoth(resS, resC, beta, -1.0, repS, repC); holdExcluded(); predictionSlope(cols, beta.take(6))
    _noise = nz; _version += 1
  }

  /** The design of the current spec: the default part, each term's columns, then `extra` groups (held). The terms'
    * columns are held when they all fit in `holdBytes` (`HoldBytes`), else made a block at a time where they
    * are read (long records; INL's are held).
    */
  private def groups(extra: IndexedSeq[IndexedSeq[Col]] = IndexedSeq()): ColGroups = {
    val base0 = baseCols(s1, s2, c1, c2)
    val keep = n.toLong * 8 * 4 * spec.terms.size < holdBytes
    // the INL term's columns come from the residual, which the fit then overwrites: always held
    val held = (false +: spec.terms.toIndexedSeq.map(_.isInstanceOf[Term.Inl])) ++ extra.map(_ => true)
    val gens = null +: spec.terms.toIndexedSeq.map(t => if (keep) null else termGen(t).orNull)
    new ColGroups((() => base0) +: (spec.terms.toIndexedSeq.map(t => () => termCols(t)) ++ extra.map(c => () => c)), keep, held, gens)
  }

  /** The residual of the fit `sol` over `cols`: the repaired data less the prediction. */
  private def residual(cols: ColGroups): Unit = {
    cols.addToBoth(resS, resC, sol.beta, -1.0, repS, repC)
  }

  /** d(prediction)/d(2 pi fringe phase) per channel: the fundamental's (v), plus the harmonics' when the phase follows a
    * reference (a free trajectory takes the difference up; a fixed map would be biased by it).
    */
  private var slopeS: Array[Double] = null; private var slopeC: Array[Double] = null // null: the fundamental's (v)
  @inline final def gS(i: Int): Double = if (slopeS == null) vs(i) else slopeS(i)
  @inline final def gC(i: Int): Double = if (slopeC == null) vc(i) else slopeC(i)
  private def predictionSlope(design: ColGroups, b: Array[Double]): Unit = {
    slopeS = null; slopeC = null
    if (!traj.isInstanceOf[RefTrajectory]) return
    // v of the new default part b (the engine's `base` is still the one the columns were made from)
    val gS = Doubles.tabulate(n)(i => b(1) * s2(i) - b(2) * s1(i)); val gC = Doubles.tabulate(n)(i => b(4) * c2(i) - b(5) * c1(i))
    for ((t, g) <- spec.terms.zipWithIndex) t match {
      case Term.Harm(k, _) =>
        val cols = design(g + 1)
        val at = termIndex(t)
        for (j <- 0 until cols.size / 2) {
          val b0 = sol.beta(at + 2 * j); val b1 = sol.beta(at + 2 * j + 1)
          val (hs, hc, g) = if (cols(2 * j).s != null) (cols(2 * j).s, cols(2 * j + 1).s, gS) else (cols(2 * j).c, cols(2 * j + 1).c, gC)
          var i = 0
          while (i < n) { g(i) += k * (b0 * hc(i) - b1 * hs(i)); i += 1 }
        }
      case _ =>
    }
    slopeS = gS; slopeC = gC
  }


  /** The slopes of the spec's slope-dependent noise (jitter: against time; phase noise: against the fringe phase), or null. */
  def noiseSlopes(sp: ModelSpec): (Array[Double], Array[Double]) =
    if (sp.jitter) slopes() else if (sp.phaseNoise) phaseSlopes() else if (sp.intensityNoise) intensitySlopes() else null
  /** Slope of each channel against the fringe phase (full scale per radian), for the phase-noise model. */
  def phaseSlopes(): (Array[Double], Array[Double]) = (Doubles.tabulate(n)(i => vs(i)), Doubles.tabulate(n)(i => vc(i)))
  /** Each channel's value less its offset (full scale), for the intensity-noise model. */
  def intensitySlopes(): (Array[Double], Array[Double]) = (Doubles.tabulate(n)(i => us(i)), Doubles.tabulate(n)(i => uc(i)))
  /** Slope of each channel against time (full scale per second), for the jitter noise model. */
  def slopes(): (Array[Double], Array[Double]) = (Doubles.tabulate(n)(timeSlopeS), Doubles.tabulate(n)(timeSlopeC))
  /** The slopes against time at sample i (`slopes`, read where they are needed). */
  @inline final def timeSlopeS(i: Int): Double = vs(i) * 2 * math.Pi * freq(i)
  @inline final def timeSlopeC(i: Int): Double = vc(i) * 2 * math.Pi * freq(i)

  def sumSq(a: Array[Double]): Double =
    Par.sum(a.length) { (lo, hi) => var s = 0.0; var i = lo; while (i < hi) { s += a(i) * a(i); i += 1 }; s }
}

object SignalEngine {
  val debug: Boolean = sys.props.contains("moire.debug")
  /** The heap the terms' columns may take when held (else made a block at a time where they are read): an eighth of
    * the heap, at most 256 MB. More bought no time (20 M samples: 43.5 s holding 352 MB of a subsample's columns, 44.1 s
    * in a 1 GB heap holding none) and raised the peak heap with the heap's size.
    */
  val HoldBytes: Long = math.min(Runtime.getRuntime.maxMemory / 8, 256L << 20)
  /** The residual along the fringe over the residual across it above which the trajectory is made finer. */
  val MotionMisfit = 1.1
  /** Passes of `splitSegments` at most (a segment becomes 2^SplitPasses at most), and the standardised phase residual
    * a sample brings to them at most.
    */
  val SplitPasses = 6
  val SplitZ = 4.0
  /** The share of the segments a pass may halve at most (more is no local change of the motion). */
  val SplitShare = 0.1
  /** Noise widths a prediction lies beyond a saturation level where the sample held there is left out of the fit
    * (`deepCensored`; its tail mean is within 1e-4 noise widths of the prediction there).
    */
  val Deep = 4.0
  /** Harmonics of the fringe phase that `alongOverAcrossBeyondFringe` takes out: a harmonic of the catalogue's orders
    * (2 to 7) on one or both channels turns at its order less or plus one.
    */
  val FringeOrders = 8
  /** Bins of the channel response's table over the fringe frequencies. */
  val ResponseBins = 4096
}

/** Noise model: per-channel white variance plus jitter variance jitter2 * slope^2; m2ll = -2 ln L. */
final case class Noise(varS: Double, varC: Double, jitter2: Double, m2ll: Double)
object Noise {
  /** -2 ln (Q(d / sd) / bin) summed over censored samples (d = distance from prediction up to the level). A censored
    * sample's term is a probability (of a code at or beyond the level), the others' a density: `bin`, the quantization
    * step, is the width that makes a density the probability of its code (0: none; a repair that censors gives it).
    * Without it each censored sample cost 2 ln(1 / bin), 15.2 at 12 bits, and a clipping candidate that censors 36,000
    * samples came out 540,000 worse by BIC than the harmonics that bend the fit to the clipped shape.
    */
  private def censored(cen: Array[Double], sd: Int => Double, bin: Double): (Double, Int) = {
    if (cen == null) return (0.0, 0)
    val perBin = if (bin > 0) 2 * math.log(bin) else 0.0
    var m = 0.0; var k = 0; var i = 0
    while (i < cen.length) {
      if (!cen(i).isNaN) { m += perBin - 2 * math.log(math.max(1e-300, 0.5 * org.hipparchus.special.Erf.erfc(cen(i) / (sd(i) * math.sqrt(2))))); k += 1 }
      i += 1
    }
    (m, k)
  }

  private def binOf(r: Repaired): Double = if (r == null) 0.0 else r.bin

  /** The mean of a standard normal beyond a (the inverse Mills ratio, phi(a) / Q(a)); a + 1 / a far out. */
  def tailMean(a: Double): Double =
    if (a > 30) a + 1 / a
    else { val q = 0.5 * org.hipparchus.special.Erf.erfc(a / math.sqrt(2)); if (q > 0) math.exp(-0.5 * a * a) / math.sqrt(2 * math.Pi) / q else a }

  /** White noise on both channels, nothing censored, from the residual sums of squares of n samples each. */
  def white(rssS: Double, rssC: Double, n: Int): Noise = {
    val floor = 1e-30
    val vs = math.max(floor, rssS / n); val vc = math.max(floor, rssC / n)
    Noise(vs, vc, 0, n * (math.log(2 * math.Pi * vs) + 1) + n * (math.log(2 * math.Pi * vc) + 1))
  }

  /** White noise on both channels, nothing censored, from the residual sums of squares of n samples each, with a soft
    * repair's spread and entropy (`Repaired`) when `r` has them (a flat top's scaling has its term there too).
    */
  def white(rssS: Double, rssC: Double, n: Int, r: Repaired): Noise =
    if (r == null || (!r.soft && r.entropy == 0)) white(rssS, rssC, n)
    else { val w = white(rssS + r.pvSumS, rssC + r.pvSumC, n); w.copy(m2ll = w.m2ll - 2 * r.entropy) }

  /** White noise per channel from the residual's sums of squares over n samples (censored ones hold no residual). */
  def fromSums(ssS0: Double, ssC0: Double, n: Int, cens: Repaired): Noise = {
    val floor = 1e-30
    val cs = if (cens == null) null else cens.censS; val cc = if (cens == null) null else cens.censC
    if (cs == null && cc == null) return white(ssS0, ssC0, n, cens)
    val ssS = ssS0 + cens.pvSumS; val ssC = ssC0 + cens.pvSumC
    def count(c: Array[Double]) = if (c == null) 0 else c.count(!_.isNaN)
    val ns = math.max(1, n - count(cs)); val nc = math.max(1, n - count(cc))
    val vs = math.max(floor, ssS / ns); val vc = math.max(floor, ssC / nc)
    val (ms, _) = censored(cs, _ => math.sqrt(vs), binOf(cens)); val (mc, _) = censored(cc, _ => math.sqrt(vc), binOf(cens))
    Noise(vs, vc, 0, ns * (math.log(2 * math.Pi * vs) + 1) + nc * (math.log(2 * math.Pi * vc) + 1) + ms + mc - 2 * cens.entropy)
  }

  def fit(rs: Array[Double], rc: Array[Double], slope: (Array[Double], Array[Double]), cens: Repaired = null): Noise = {
    val n = rs.length
    val cs = if (cens == null) null else cens.censS; val cc = if (cens == null) null else cens.censC
    // a censored sample's residual is its tail mean's, no noise of a sample seen: left out of the sums
    def ss(a: Array[Double], c: Array[Double] = null) = Par.sum(n) { (lo, hi) =>
      var s = 0.0; var i = lo; while (i < hi) { if (c == null || c(i).isNaN) s += a(i) * a(i); i += 1 }; s
    }
    val floor = 1e-30
    // a soft repair's spread per sample (`Repaired`), added to the residual's squares (null: none)
    val ps = if (cens == null) null else cens.pvS; val pc = if (cens == null) null else cens.pvC
    val ent = if (cens == null) 0.0 else cens.entropy
    def count(c: Array[Double]) = if (c == null) 0 else c.count(!_.isNaN)
    if (slope == null) return fromSums(ss(rs, cs), ss(rc, cc), n, cens)
    val (ds, dc) = slope
    val white0 = ((ss(rs, cs) + (if (cens == null) 0.0 else cens.pvSumS)) / n, (ss(rc, cc) + (if (cens == null) 0.0 else cens.pvSumC)) / n)
    var vs = white0._1; var vc = white0._2; var j2 = 0.0
    // scoring steps until the estimates stop changing (at most 8; the reference path takes all 8): the white variances
    // by their own size, the slope's by the variance it adds at the mean square slope against the white one's (near
    // zero its own relative change is noise and never settles)
    lazy val dd = if (FitPath.isReference) 0.0 else (ss(ds) + ss(dc)) / (2.0 * n)
    var it = 0; var moved = true
    while (it < 8 && (moved || FitPath.isReference)) {
      it += 1
      val (vs0, vc0, j20) = (vs, vc, j2)
      // weighted least squares of r^2 on (1_sin, 1_cos, d^2) with weights 1 / var_i^2 (Gaussian ML scoring)
      val m = Array.ofDim[Double](3, 4)
      // both channels' sums in one pass (each channel's in the same order as a pass of its own)
      val q = Par.sums(n, 10) { (lo, hi, a) =>
        def acc(r: Array[Double], d: Array[Double], v0: Double, o: Int, pv: Array[Float], c: Array[Double]): Unit = {
          var s0 = 0.0; var s1 = 0.0; var s2 = 0.0; var s3 = 0.0; var s4 = 0.0; var i = lo
          while (i < hi) {
            if (c != null && !c(i).isNaN) { i += 1 } else {
            val d2 = d(i) * d(i); val v = math.max(floor, v0 + j2 * d2); val w = 1 / (v * v); val y = r(i) * r(i) + (if (pv == null) 0.0 else pv(i))
            s0 += w; s1 += w * d2; s2 += w * d2 * d2; s3 += w * y; s4 += w * d2 * y
            i += 1
            }
          }
          a(o) += s0; a(o + 1) += s1; a(o + 2) += s2; a(o + 3) += s3; a(o + 4) += s4
        }
        acc(rs, ds, vs, 0, ps, cs); acc(rc, dc, vc, 5, pc, cc)
      }
      for (ch <- 0 to 1) { val o = 5 * ch; m(ch)(ch) += q(o); m(ch)(2) += q(o + 1); m(2)(2) += q(o + 2); m(ch)(3) += q(o + 3); m(2)(3) += q(o + 4) }
      m(2)(0) = m(0)(2); m(2)(1) = m(1)(2)
      val a = Array(Array(m(0)(0), 0, m(0)(2), 0, m(0)(3)), Array(0, m(1)(1), m(1)(2), 0, m(1)(3)),
        Array(m(2)(0), m(2)(1), m(2)(2), 0, m(2)(3)), Array(0.0, 0, 0, 1, 0))
      val x = Trajectory.solve4(a)
      vs = math.max(floor, x(0)); vc = math.max(floor, x(1)); j2 = math.max(0, x(2))
      // a slope term the data want negative: the fit on the boundary is white noise (with nothing censored, each
      // channel's mean square), not the intercepts of the negative slope's fit (it went back and forth about zero)
      if (!(x(2) > 0) && cs == null && cc == null && !FitPath.isReference) { vs = math.max(floor, white0._1); vc = math.max(floor, white0._2) }
      def rel(a: Double, b: Double) = math.abs(a - b) > 1e-13 * math.max(math.abs(a), math.abs(b))
      moved = rel(vs, vs0) || rel(vc, vc0) || (j2 != j20 && math.abs(j2 - j20) * dd > 1e-13 * math.max(vs, vc))
    }
    // white noise on the boundary, nothing censored: -2 ln L from the sums (the pass below would add the same)
    if (j2 == 0 && vs == white0._1 && vc == white0._2 && cs == null && cc == null && !FitPath.isReference)
      return Noise(vs, vc, 0, n * (math.log(2 * math.Pi * vs) + 1) + n * (math.log(2 * math.Pi * vc) + 1) - 2 * ent)
    if (SignalEngine.debug) System.err.println(f"noise fit: $it scoring steps, jitter2 $j2%.4g")
    var m2 = Par.sum(n) { (lo, hi) =>
      var m = 0.0; var i = lo
      while (i < hi) {
        val a = vs + j2 * ds(i) * ds(i); val b = vc + j2 * dc(i) * dc(i)
        if (cs == null || cs(i).isNaN) m += math.log(2 * math.Pi * a) + (rs(i) * rs(i) + (if (ps == null) 0.0 else ps(i))) / a
        if (cc == null || cc(i).isNaN) m += math.log(2 * math.Pi * b) + (rc(i) * rc(i) + (if (pc == null) 0.0 else pc(i))) / b
        i += 1
      }
      m
    }
    m2 += censored(cs, k => math.sqrt(vs + j2 * ds(k) * ds(k)), binOf(cens))._1 + censored(cc, k => math.sqrt(vc + j2 * dc(k) * dc(k)), binOf(cens))._1
    Noise(vs, vc, j2, m2 - 2 * ent)
  }
}

/** Repaired data of both channels and their censoring distances (NaN = not censored; null = none). A soft repair's
  * data are the weighted means of the preimages: `pvS`/`pvC` their weights' variance per sample (null: none), `pvSumS`/
  * `pvSumC` its sums and `entropy` the weights' entropy summed over both channels; -2 ln L of the mixture is that of
  * the residual with the variance added to its squares, less twice the entropy (exact where the weights were made).
  * `lostS`/`lostC`: the information the weights leave out, in samples (the sum of each one's variance over its noise's).
  */
final case class Repaired(s: Array[Double], c: Array[Double], censS: Array[Double], censC: Array[Double],
                          pvS: Array[Float] = null, pvC: Array[Float] = null, pvSumS: Double = 0, pvSumC: Double = 0,
                          entropy: Double = 0, lostS: Double = 0, lostC: Double = 0, bin: Double = 0,
                          heldS: Array[Boolean] = null, heldC: Array[Boolean] = null) {
  def soft: Boolean = pvS != null || pvC != null
}
