package moire.explain

import moire.recording.Reference

/** The fringe phase as a smooth map of a reference (issue 12, Build 2):
  * phase = offset + k (ref - ref_mid) + k lag (d ref/dt - its mean), in periods, with k the fringe periods per
  * reference unit (from the metadata, its sign from the data, or fitted), offset and lag fitted. The motion is
  * then not free, so distortion of the signals cannot be absorbed into it.
  * The reference is smoothed by a local quadratic over `2 halfWidth + 1` samples (its quantization steps are
  * noise to the fit), which also gives its derivative.
  */
final class RefTrajectory(val ref: Reference, val fs: Double, val kFixed: Option[Double], val halfWidth: Int = RefTrajectory.HalfWidth)
    extends PhaseTrack {
  val n: Int = ref.values.length
  val nseg = 1
  /** Smoothed reference (centred) and its derivative by time (reference units per second, centred). */
  val (x, dx, xMid, dxMean) = {
    val (s, d) = RefTrajectory.smooth(ref.values, halfWidth)
    var lo = Double.MaxValue; var hi = -Double.MaxValue; var m = 0.0; var i = 0
    while (i < n) { lo = math.min(lo, s(i)); hi = math.max(hi, s(i)); d(i) *= fs; m += d(i); i += 1 }
    val mid = 0.5 * (lo + hi); m /= n
    i = 0
    while (i < n) { s(i) -= mid; d(i) -= m; i += 1 }
    (s, d, mid, m)
  }
  /** The reference's speed varies enough to tell a lag from the offset (else the lag is left out). */
  val hasLag: Boolean = {
    val sd = math.sqrt(dx.map(v => v * v).sum / n)
    sd > 0.05 * math.abs(dxMean) && sd > 0
  }
  /** Offset (periods at ref_mid and the mean speed), k, and k * lag. */
  var offset = 0.0
  var k: Double = kFixed.getOrElse(0.0)
  var kLag = 0.0
  def lagS: Double = if (k != 0) kLag / k else 0.0
  def keep(): () => Unit = { val (o, k0, l) = (offset, k, kLag); () => { offset = o; k = k0; kLag = l } }
  def params: Int = 1 + (if (kFixed.isEmpty) 1 else 0) + (if (hasLag) 1 else 0)

  def eval(phase: Array[Double], freq: Array[Double]): Unit = {
    Par.blocks(n) { (lo, hi) =>
      var i = lo
      while (i < hi) { phase(i) = offset + k * x(i) + kLag * dx(i); freq(i) = k * (dx(i) + dxMean); i += 1 }
    }
  }

  /** Adds the weighted least-squares correction of offset (and k, lag) to the phase difference d (periods). */
  /** The phase's derivatives by the free parameters (null: 1 for the offset), in the order of `addDelta`. */
  val basis: Seq[Array[Double]] = Seq(null) ++ (if (kFixed.isEmpty) Seq(x) else Nil) ++ (if (hasLag) Seq(dx) else Nil)

  /** Adds increments of offset (and k, k lag), in the order of `basis`. */
  def addDelta(sol: Array[Double]): Unit = {
    offset += sol(0)
    var at = 1
    if (kFixed.isEmpty) { k += sol(at); at += 1 }
    if (hasLag) kLag += sol(at)
  }

  def addFit(d: Array[Double], w: Array[Double]): Unit = {
    val cols = basis
    val m = Array.ofDim[Double](4, 5)
    for (r <- 0 to 3) m(r)(r) = 1.0
    for (r <- cols.indices; c <- cols.indices) m(r)(c) = 0.0
    var i = 0
    while (i < n) {
      val wi = if (w == null) 1.0 else w(i)
      var r = 0
      while (r < cols.length) {
        val a = if (cols(r) == null) 1.0 else cols(r)(i)
        var c = 0
        while (c <= r) { val b = if (cols(c) == null) 1.0 else cols(c)(i); m(r)(c) += wi * a * b; c += 1 }
        m(r)(4) += wi * a * d(i); r += 1
      }
      i += 1
    }
    for (r <- cols.indices; c <- 0 until r) m(c)(r) = m(r)(c)
    addDelta(Trajectory.solve4(m))
  }

  /** Starts from the raw (atan2) phase: k's sign (or k itself) from its slope against the reference, the offset
    * from the circular mean of the wrapped difference (so aliased or unwrapped-wrong raw phase cannot shift it).
    */
  def start(raw: Array[Double]): Unit = {
    rawSlope = slope(raw)
    k = kFixed match { case Some(f) => if (rawSlope < 0) -math.abs(f) else math.abs(f); case None => rawSlope }
    var c = 0.0; var s = 0.0; var i = 0
    while (i < n) { val a = 2 * math.Pi * (raw(i) - k * x(i)); c += math.cos(a); s += math.sin(a); i += 1 }
    offset = math.atan2(s, c) / (2 * math.Pi); kLag = 0.0
  }
  /** The slope of the raw phase against the reference at the start (periods per unit; for the metadata check). */
  var rawSlope = 0.0

  private def slope(raw: Array[Double]): Double = {
    var sxx = 0.0; var sxy = 0.0; var sy = 0.0; var i = 0
    while (i < n) { sy += raw(i); i += 1 }
    i = 0
    while (i < n) { sxx += x(i) * x(i); sxy += x(i) * (raw(i) - sy / n); i += 1 }
    if (sxx > 0) sxy / sxx else 0.0
  }
}

object RefTrajectory {
  /** Half width of the smoothing window, samples; `HalfWidths` are the ones tried. */
  val HalfWidth = 8
  val HalfWidths: Seq[Int] = Seq(8, 32, 128)
  /** A reference the signals follow less well than this (rms phase, fringe periods) is not used. */
  val MaxPhaseRms = 0.05
  /** A reference whose steps are coarser than this (fringe periods) knows the phase less well than the signals do. */
  val MaxStepPeriods: Double = 1.0 / 64

  /** The most a reference may move between two samples (fringe periods): more, and the signals would alias. */
  val MaxJumpPeriods = 0.5

  /** Why a reference with a scale from the metadata cannot be used: a step between two samples larger than the
    * signals allow (`MaxJumpPeriods`) and than a few of its own steps (a coarse count), which is a corrupted row,
    * not a motion. None: no such step, or no scale to judge it by.
    */
  def jump(r: Reference): Option[String] = r.periodsPerUnit.flatMap { ppu =>
    val v = r.values; var at = -1; var big = 0.0; var i = 1
    while (i < v.length) { val d = math.abs(v(i) - v(i - 1)); if (!(d <= big)) { big = d; at = i }; i += 1 }
    val periods = big * ppu
    if (at < 0 || periods <= math.max(MaxJumpPeriods, 4 * step(v) * ppu)) None
    else Some(f"${r.column} moves by ${periods}%.3g fringe periods between samples ${at - 1} and $at (counted from 0; the " +
      f"signals alias above $MaxJumpPeriods a sample): a corrupted row, so it is not used and the motion is fitted from the signals")
  }

  /** The reference's resolution: its smallest non-zero step between samples (0 when it never moves). When it changes
    * at nearly every sample (a fine reference on a fast stage), that step is its motion, not its resolution: then the
    * resolution of a uniform quantizer is taken from its scatter about a local quadratic (rms * sqrt 12), if smaller.
    */
  def step(a: Array[Double]): Double = {
    var m = Double.MaxValue; var still = 0; var i = 1
    while (i < a.length) { val d = math.abs(a(i) - a(i - 1)); if (d > 0 && d < m) m = d; if (d == 0) still += 1; i += 1 }
    if (m == Double.MaxValue) 0.0
    else if (still > MovingFraction * a.length || a.length < 4 * HalfWidth) m
    else {
      val (s, _) = smooth(a, HalfWidth)
      var q = 0.0; var k = 0; i = HalfWidth
      while (i + HalfWidth < a.length) { val d = a(i) - s(i); q += d * d; k += 1; i += 1 }
      // a quadratic fitted to 2 h + 1 samples leaves (1 - 3 / (2 h + 1)) of the variance at its centre
      val rms = math.sqrt(q / math.max(1, k) / (1 - 3.0 / (2 * HalfWidth + 1)))
      math.min(m, rms * math.sqrt(12))
    }
  }
  /** Fraction of samples without a change above which the smallest step between samples is the resolution. */
  val MovingFraction = 0.01

  /** Local quadratic (Savitzky-Golay) value and first difference per sample; the windows are cut short at the ends. */
  def smooth(a: Array[Double], h: Int): (Array[Double], Array[Double]) = {
    val n = a.length; val s = new Array[Double](n); val d = new Array[Double](n)
    // interior: fixed weights of the symmetric window
    val ts = (-h to h).map(_.toDouble); val s2 = ts.map(t => t * t).sum; val s4 = ts.map(t => t * t * t * t).sum
    val den = ts.size * s4 - s2 * s2
    val wv = ts.map(t => (s4 - s2 * t * t) / den).toArray; val wd = ts.map(t => t / s2).toArray
    var i = 0
    while (i < n) {
      if (i - h >= 0 && i + h < n) {
        var v = 0.0; var g = 0.0; var j = 0
        while (j <= 2 * h) { val y = a(i - h + j) - a(i); v += wv(j) * y; g += wd(j) * y; j += 1 }
        s(i) = a(i) + v; d(i) = g
      } else {
        val lo = math.max(0, i - h); val hi = math.min(n - 1, i + h)
        val deg = math.min(2, hi - lo)
        val m = Array.ofDim[Double](4, 5)
        for (r <- 0 to 3 if r > deg) m(r)(r) = 1.0
        for (j <- lo to hi) {
          val t = (j - i).toDouble; val p = Array(1.0, t, t * t)
          for (r <- 0 to deg) { for (c <- 0 to deg) m(r)(c) += p(r) * p(c); m(r)(4) += p(r) * (a(j) - a(i)) }
        }
        val x = Trajectory.solve4(m)
        s(i) = a(i) + x(0); d(i) = x(1)
      }
      i += 1
    }
    (s, d)
  }
}
