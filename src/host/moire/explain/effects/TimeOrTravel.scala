package moire.explain.effects

import moire.explain._

/** Time and position along the travel go together in a one-way scan: a change in time (drift, warm-up) and a change
  * along the travel (contrast) predict the same signal there. The finding names the other and the measurement that
  * separates them.
  */
object TimeOrTravel {
  /** |r| of position and time above which the record cannot separate them well. */
  val Correlated = 0.9

  def lookAlikes(e: SignalEngine, other: String): Seq[String] = {
    val r = Identify.correlation(e)
    if (math.abs(r) < Correlated) Nil
    else Seq(f"$other predicts nearly the same signal here: position along the travel and time correlate (r = $r%.3f); " +
      "a scan back over the same travel, or a wait at one position, separates a change in time from one along the travel")
  }

  /** Speed follows the position (or the time) in a ramp: the amplitudes' change with speed of a read-head low-pass or
    * of crosstalk then looks like a contrast changing along the travel, or an amplitude drifting in time (a 700 kHz
    * low-pass on sin was called a contrast while its cut-off was off). Named where |r| of the axis and the speed is
    * `Correlated` or more.
    */
  def speedLookAlike(e: SignalEngine, alongTravel: Boolean): Seq[String] =
    correlated(e, alongTravel, s"${Bandwidth.name} predicts a similar change of the amplitudes here: a read-head low-pass lowers them with speed",
      s"${Crosstalk.name} predicts a similar change of the amplitudes here: it changes each in proportion to the speed")

  /** Crosstalk's amplitudes change with speed: on a ramp, as a drift's in time or a contrast's along the travel do
    * (a gain drift on a chirp came out as crosstalk of -144 and +147 ns, with no drift).
    */
  def changeLookAlikes(e: SignalEngine): Seq[String] =
    correlated(e, alongTravel = false, s"${Drift.name} predicts a similar change of the amplitudes here: they change in time") ++
      correlated(e, alongTravel = true, s"${ContrastAlongTravel.name} predicts a similar change of the amplitudes here: the contrast changes along the travel")

  /** A skew's phase error grows with speed: on a ramp, as a phase error between the channels that wanders in time
    * does (a 0.2 degree random walk of it on a ramp came out as a skew of 4.7 +- 0.014 ns, with no skew planted).
    */
  def phaseLookAlike(e: SignalEngine): Seq[String] =
    correlated(e, alongTravel = false, "a phase error between the channels that changes in time (the read head's alignment or " +
      "its electronics drifting) predicts a similar phase here: it changes in time as a skew's grows with speed")

  /** Each of `heads`, then the correlation of the axis with the speed and the measurement that separates them;
    * nothing where |r| is below `Correlated`.
    */
  private def correlated(e: SignalEngine, alongTravel: Boolean, heads: String*): Seq[String] = {
    val r = speedCorrelation(e, alongTravel)
    val (what, scan) = if (alongTravel) ("position along the travel", "a scan over the same travel at another speed")
      else ("time", "a record at one speed, or with the speed going down and up again,")
    if (math.abs(r) < Correlated) Nil else heads.map(h => f"$h, and $what and speed correlate (r = $r%.3f); $scan separates them")
  }

  /** The correlation of the speed (the fringe frequency's size) with the position along the travel or with time. */
  def speedCorrelation(e: SignalEngine, alongTravel: Boolean): Double = {
    val m = e.travelMean; val n = e.n; val mid = 0.5 * (n - 1)
    @inline def axis(i: Int): Double = if (alongTravel) e.phase(i) - m else (i - mid) / e.fs
    var sf = 0.0; var i = 0
    while (i < n) { sf += math.abs(e.freq(i)); i += 1 }
    val mf = sf / math.max(1, n)
    var sxy = 0.0; var sxx = 0.0; var syy = 0.0; i = 0
    while (i < n) { val x = axis(i); val y = math.abs(e.freq(i)) - mf; sxy += x * y; sxx += x * x; syy += y * y; i += 1 }
    if (sxx > 0 && syy > 0) sxy / math.sqrt(sxx * syy) else 0.0
  }

  /** Whether a finding changes an amplitude: one of its `gains` parameters beyond 3 of its sd. */
  def changesGain(f: Finding, gains: Seq[String]): Boolean =
    gains.exists(g => f.params.get(g).exists(v => math.abs(v) > 3 * f.unc.getOrElse(g, 0.0) && v != 0))
}
