package moire.explain

/** Effects a recording cannot tell apart from its own motion (issue 12, Build 2 and 3). Without a reference the
  * phase trajectory is fitted from the signals; when one of its segments spans only a few fringe periods, it can
  * bend within a period, and structure that repeats once per period (a harmonic of the mechanical angle of a
  * one-period-per-turn encoder, eccentricity) shows partly as motion and partly as whatever slow or periodic
  * effect fits the rest: drift, pickup, harmonics. Those are then "not identifiable without a reference", not findings.
  */
object Identifiable {
  /** A free trajectory segment must span at least this many fringe periods. */
  val MinPeriodsPerSegment = 2.0
  /** Effects whose shape a free trajectory over a few periods can share. */
  val Confounded: Set[String] = effects.Effects.signals.filter(e => e.confoundedWithMotion && e.searched).map(_.name).toSet

  /** Fringe periods one trajectory segment spans (the travel over the record divided by the segments). */
  def periodsPerSegment(e: SignalEngine): Double = e.travelPeriods / e.traj.nseg

  /** The highest typical fringe frequency (Hz) at which structure once per turn can repeat within a few fringe periods:
    * 4 periods a turn at 2000 turns per second (120,000 rpm, the fastest spindles). Above it a fringe period is no turn
    * of anything: a harmonic of 8 LSB and a drift of 20 LSB on a back-and-forth motion at up to 100 kHz (1.8 periods per
    * segment, another generator) were "not identifiable" and the report had no finding.
    */
  val MaxConfoundedHz = 8000.0

  /** The shortest segment (samples) the free trajectory may take. Under a fringe period a segment takes up part of
    * the fringe's own harmonics (a 3rd harmonic of 0.5 % came out at 0.27 % with segments of 0.4 period on a fast
    * back-and-forth motion): shorter ones, for motion that turns within a period (vibration, start and stop), only
    * where such effects are then called not identifiable anyway, at a typical fringe frequency up to MaxConfoundedHz.
    */
  def shortestSegment(n: Int, fs: Double, typicalHz: Double): Int =
    if (typicalHz <= MaxConfoundedHz) Trajectory.MinLength else Trajectory.segmentLength(n, fs, typicalHz, 1.0)

  /** True when the motion is free and too flexible within a period to tell distortion from it, at speeds where a few
    * fringe periods can be a turn.
    */
  def motionConfounded(e: SignalEngine): Boolean =
    e.reference.isEmpty && periodsPerSegment(e) < MinPeriodsPerSegment && e.typicalHz <= MaxConfoundedHz

  /** Effects seen only as a change with speed: at one speed each is a change of the amplitudes and phase. */
  val SpeedShaped: Set[String] = Set(effects.ChannelSkew.name, effects.Bandwidth.name, effects.Crosstalk.name)

  /** The fringe frequency spans less than 5 % of its highest value (or there is none): one speed. */
  def oneSpeed(fMin: Double, fMax: Double): Boolean = !(fMax > 0) || fMax - fMin < 0.05 * fMax

  def why(c: Cand, e: SignalEngine, fMin: Double, fMax: Double): Option[String] =
    if (Confounded(c.effect) && motionConfounded(e)) Some(untested(e))
    // at one speed the default part's amplitudes and phase already are that change (a crosstalk of 3.6 us, 2464 LSB
    // by its own columns, was named on a clean record at 50 kHz +- 0.1 % with 1/f noise)
    else if (SpeedShaped(c.effect) && oneSpeed(fMin, fMax))
      Some(f"${c.effect}: not identifiable at one speed: the fringe frequency spans only ${fMin}%.4g .. ${fMax}%.4g Hz, where it is a change of the amplitudes and phase")
    else if (c.effect == effects.Jitter.name) referenceNoise(e, fMin, fMax)
    // the reference's own noise (its quantization) moves the modelled phase: that is phase noise, whatever the speeds
    else if (c.effect == effects.PhaseNoise.name && e.reference.isDefined)
      Some(s"${c.effect}: not identifiable from the reference's own noise, which moves the modelled fringe phase the same way")
    else None

  /** Speed range (fastest / slowest fringe frequency) needed to tell clock jitter from the reference's own noise. */
  val JitterSpeedRange = 3.0

  /** With a reference, its noise (quantization) moves the modelled phase: residual noise that grows with the signal's
    * slope, like jitter; only a wide speed range tells them apart (jitter grows with speed, reference noise does not).
    */
  def referenceNoise(e: SignalEngine, fMin: Double, fMax: Double): Option[String] =
    if (e.reference.isDefined && !(fMax > JitterSpeedRange * fMin))
      Some(f"jitter: not identifiable from the reference's own noise: the fringe frequency spans ${fMin}%.4g .. ${fMax}%.4g Hz " +
        f"(a factor of ${JitterSpeedRange}%.0f is needed)")
    else None

  def untested(e: SignalEngine): String =
    f"${Confounded.toSeq.sorted.mkString(", ")}: not identifiable without a reference: the record covers " +
      f"${periodsPerSegment(e) * e.traj.nseg}%.3g fringe periods (${periodsPerSegment(e)}%.3g per trajectory segment) and the motion " +
      "is fitted from the signals, so a harmonic of the mechanical angle (eccentricity) or a slow change cannot be told from " +
      s"non-uniform motion; a reference column (${moire.recording.Reference.Columns.mkString(", ")}) makes them testable"

  /** Residual structure of a confounded recording, as one not-tested line (None when there is none). */
  def leftOver(left: Seq[Located]): Seq[String] =
    if (left.isEmpty) Nil
    else Seq(s"residual structure (${left.map(_.where).distinct.mkString("; ")}) is not identifiable without a reference: it may be " +
      s"non-uniform motion within a fringe period; largest: ${left.head.where}: ${left.head.summary}")
}
