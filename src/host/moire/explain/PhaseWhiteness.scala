package moire.explain

/** Jitter and phase noise of the motion are phase departures the trajectory cannot follow: white from sample to
  * sample (jitter) or a vibration faster than its segments. Departures that still correlate over a good part of a
  * segment are motion the trajectory should have followed and did not (vibration at a few hundred hertz under
  * segments too long for it): the model not following the signal, not noise.
  *
  * A phase departure d moves both channels along their slopes against the fringe phase (r_sin = v_sin d, r_cos = v_cos d);
  * the channels' own noise is independent between them (and its mean over the phase vanishes even where it is common).
  * So the products a_i b_j of a = r_sin v_sin / A_sin^2 and b = r_cos v_cos / A_cos^2 hold the departures alone: at
  * j = i their variance, at j = i + lag its part that carries over (each times the mean of sin^2 cos^2 of the phase).
  * The independent bench's fast vibration (an AR(1) process of 0.1 us at 50 MS/s) carries 81 % to the next sample and
  * nothing at a 16th of an 823-sample segment; a trajectory behind vibrations at 137 and 311 Hz carries more than all
  * of it (the estimate's noise) at a 16th of its 595-sample segments.
  */
object PhaseWhiteness {
  /** The share of the departures' variance carried over `SegmentShare` of a segment above which they are motion. */
  val MaxCarried = 0.5
  /** The lag, as a share of a trajectory segment's samples. */
  val SegmentShare = 1.0 / 16

  /** The departures' variance (at lag 0) and its part carried over `lag` samples (both orders averaged), with its sd. */
  final case class Lags(lag: Int, p0: Double, p1: Double, sd1: Double) {
    def carried: Double = p1 / p0
  }

  /** `radial`: the departures of the amplitude (intensity noise moves both channels along their values, r_sin = u_sin g,
    * r_cos = u_cos g), projected on the values instead of the slopes.
    */
  def lags(e: SignalEngine, lag: Int, radial: Boolean = false): Lags = {
    val n = e.n; val as = e.ampS * e.ampS; val ac = e.ampC * e.ampC
    @inline def a(i: Int) = e.resS(i) * (if (radial) e.us(i) else e.vs(i)) / as
    @inline def b(i: Int) = e.resC(i) * (if (radial) e.uc(i) else e.vc(i)) / ac
    val m = n - lag
    val sums = Par.sums(math.max(0, m), 3) { (lo, hi, acc) =>
      var i = lo
      while (i < hi) {
        val a0 = a(i); val b0 = b(i); val l1 = 0.5 * (a0 * b(i + lag) + a(i + lag) * b0)
        acc(0) += a0 * b0; acc(1) += l1; acc(2) += l1 * l1; i += 1
      }
    }
    val k = math.max(1, m).toDouble; val p1 = sums(1) / k
    Lags(lag, sums(0) / k, p1, math.sqrt(math.max(0.0, sums(2) / k - p1 * p1) / k))
  }

  /** Why a slope noise is not noise (its departures correlate over a 16th of a trajectory segment), or None. */
  def why(e: SignalEngine, radial: Boolean = false): Option[String] = {
    val lag = math.max(1, math.round(e.n.toDouble / e.traj.nseg * SegmentShare).toInt)
    val l = lags(e, lag, radial)
    if (SignalEngine.debug) System.err.println(f"whiteness: lag $lag: ${l.p0}%.4g, ${l.p1}%.4g +- ${l.sd1}%.2g, carried ${l.carried}%.3f")
    if (!(l.p0 > 0) || l.carried <= MaxCarried || l.p1 < 3 * l.sd1) None
    else if (radial) Some(f"the amplitude departures it takes for noise still correlate $lag samples apart (${100 * math.min(l.carried, 1.0)}%.0f %% " +
      "of their variance carried over): they are changes of the amplitudes slower than the samples (a modulation, or the motion's " +
      "misfit at second order), not white noise")
    else Some(f"the phase departures it takes for noise still correlate $lag samples apart (${100 * math.min(l.carried, 1.0)}%.0f %% of their " +
      "variance carried over): they are motion the trajectory does not follow (its segments too long for it), not noise")
  }
}
