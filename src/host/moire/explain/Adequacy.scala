package moire.explain

/** Adequacy first (issue 28): whether the model follows the signal at all, judged against a noise floor that does not
  * depend on the motion model. The floor comes from second differences of neighbouring residual samples: white noise gives
  * var(r(i-1) - 2 r(i) + r(i+1)) = 6 sigma^2, while a misfit that varies over more than a few samples cancels in them.
  * Where the residual's rms exceeds that floor by `Margin` (in any of `Windows` contiguous windows), the model does not
  * follow the signal there: the report says where (time, position, speed). When it does not follow over the record as
  * a whole, nothing fitted on it is a finding.
  */
object Adequacy {
  /** Residual rms over the noise floor above which the model does not follow (3: white noise gives 1; noise whose band
    * ends at half the Nyquist frequency, as an oversampled analog bandwidth makes, gives 2.6).
    */
  val Margin = 3.0
  val Windows = 32

  /** Noise floor (full scale rms) from second differences of neighbouring residual samples on both channels, over
    * [a, b): white noise gives var(r(i-1) - 2 r(i) + r(i+1)) = 6 sigma^2. A misfit at a fraction x of the sample rate
    * passes with (2 sin(pi x))^2 / sqrt(6) of its size (first differences let 2 sin(pi x) / sqrt(2) through: a misfit
    * near a tenth of the sample rate, as vibration faster than a trajectory segment makes, would count as noise).
    */
  def floor(e: SignalEngine, a: Int = 1, b: Int = -1): Double = {
    val end = if (b < 0) e.n else b
    var s = 0.0; var k = 0; var i = math.max(1, a)
    while (i + 1 < end) {
      val ds = e.resS(i - 1) - 2 * e.resS(i) + e.resS(i + 1); val dc = e.resC(i - 1) - 2 * e.resC(i) + e.resC(i + 1)
      s += ds * ds + dc * dc; k += 2; i += 1
    }
    if (k == 0) 0.0 else math.sqrt(s / k / 6)
  }

  /** The noise floor of one channel's residual (full scale rms), from second differences. */
  def floorOf(r: Array[Double]): Double = {
    var s = 0.0; var i = 1
    while (i + 1 < r.length) { val d = r(i - 1) - 2 * r(i) + r(i + 1); s += d * d; i += 1 }
    if (r.length < 3) 0.0 else math.sqrt(s / (r.length - 2) / 6)
  }

  private def rms(e: SignalEngine, a: Int, b: Int): Double = {
    var s = 0.0; var i = a
    while (i < b) { s += e.resS(i) * e.resS(i) + e.resC(i) * e.resC(i); i += 1 }
    if (b > a) math.sqrt(s / (2.0 * (b - a))) else 0.0
  }

  /** The model's rms over the floor for the whole record. */
  def ratio(e: SignalEngine): Double = { val f = floor(e); if (f > 0) rms(e, 0, e.n) / f else Double.PositiveInfinity }

  /** The windows where the model does not follow the signal, merged into runs, as located departures. */
  def misfit(e: SignalEngine): Seq[Located] = {
    val w = math.max(16, e.n / Windows)
    val bad = (0 until e.n by w).map(a => (a, math.min(e.n, a + w))).filter { case (a, b) => b - a >= 16 }.map { case (a, b) =>
      val f = floor(e, a + 1, b); (a, b, if (f > 0) rms(e, a, b) / f else 0.0)
    }.filter(_._3 > Margin)
    // runs of neighbouring windows
    val runs = bad.foldLeft(List.empty[(Int, Int, Double)]) {
      case ((a0, b0, r0) :: rest, (a, b, r)) if a == b0 => (a0, b, math.max(r0, r)) :: rest
      case (acc, x) => x :: acc
    }.reverse
    val p0 = e.phase(0)
    runs.map { case (a, b, r) =>
      var x0 = Double.MaxValue; var x1 = -Double.MaxValue; var f0 = Double.MaxValue; var f1 = 0.0; var i = a
      while (i < b) { val x = e.phase(i) - p0; x0 = math.min(x0, x); x1 = math.max(x1, x); val f = math.abs(e.freq(i)); f0 = math.min(f0, f); f1 = math.max(f1, f); i += 1 }
      Located("the default model does not follow the signal here",
        f"residual rms ${r}%.1f x the noise floor (from neighbouring samples) at ${a / e.fs}%.4g..${b / e.fs}%.4g s, position ${x0}%.4g..${x1}%.4g " +
          f"fringe periods from the start, fringe frequency ${f0 / 1e3}%.4g..${f1 / 1e3}%.4g kHz",
        Map("ratio" -> r, "t0_s" -> a / e.fs, "t1_s" -> b / e.fs, "position0_periods" -> x0, "position1_periods" -> x1, "f0_hz" -> f0, "f1_hz" -> f1),
        significant = true)
    }
  }
}
