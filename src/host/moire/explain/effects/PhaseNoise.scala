package moire.explain.effects

import moire.explain._

/** Phase noise of the motion: the fringe phase itself noisy from sample to sample (vibration faster than the trajectory
  * follows, a laser's phase noise). It adds noise in proportion to the signal's slope against the fringe phase, as
  * jitter does at one speed; jitter's grows with speed, this does not. The look-alike of jitter.
  */
object PhaseNoise extends Effect {
  val name = "phase_noise"
  val params = Seq(Param("phase_noise_rad", "rad rms", "0..2 pi"))
  val what = "phase noise of the motion (vibration, laser phase noise), radians of fringe phase rms per sample, the same on both channels"
  val shows = "noise against signal slope, not growing with speed"
  override def example: Example = Example(EffectSpec(name, Map("phase_noise_rad" -> 0.01)), "ramp:50000:250000:0.01")
  override val claims: Seq[String] = Seq("noise against speed")
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Slope

  override val needs: Seq[String] = Seq("phase_noise_rad")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "phase_noise_rad", 0, 2 * math.Pi, "from 0 to 6.283 rad rms (one fringe period)")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(phaseNoise = true)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.phaseNoise().toSeq)
  override def refresh(f: Finding, e: SignalEngine): Finding = f.copy(params = f.params + ("phase_noise_rad" -> math.sqrt(e.noise.jitter2)))
  /** The noise it adds (rms, full scale) at the steepest slope. */
  override def size(c: Cand, e: SignalEngine): Double = math.max(e.ampS, e.ampC) * c.params.getOrElse("phase_noise_rad", 0.0)
  /** At one speed jitter predicts the same noise: it stands back for jitter there, and names it. */
  override def yieldsTo(c: Cand, other: Cand): Boolean = other.effect == Jitter.name
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] =
    if (e.fMax > Identifiable.JitterSpeedRange * e.fMin) Nil
    else Seq(f"sampling-clock ${Jitter.name} of ${f.params.getOrElse("phase_noise_rad", 0.0) / (2 * math.Pi * math.max(e.fMax, 1e-30)) * 1e12}%.4g ps rms " +
      f"predicts the same noise here: the fringe frequency spans only ${e.fMin}%.4g .. ${e.fMax}%.4g Hz; a record over a speed range of " +
      f"${Identifiable.JitterSpeedRange}%.0f or more separates them")

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val periods = specs.map(_.p("phase_noise_rad", 0.0)).headOption.getOrElse(0.0) / (2 * math.Pi)
    private val rnd = new scala.util.Random(p.seed * 17 + 5)
    override val analog: Boolean = periods != 0
    override def phaseShift(): Double = if (periods > 0) periods * rnd.nextGaussian() else 0.0
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"phase noise of the motion ${Effect.g(p, "phase_noise_rad") * 1e3}%.3g mrad rms of fringe phase: noise grows with the signal's slope, not with speed, beside ${Effect.g(p, "white_noise_fs")}%.3g full scale white noise"
}
