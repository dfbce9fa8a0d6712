package moire.explain.effects

import moire.explain._

/** Intensity noise of the light source (an LED's or laser diode's power, the read head's photocurrent): both channels'
  * amplitudes noisy together from sample to sample. It adds noise in proportion to the signal's distance from its
  * centre, where phase noise adds it in proportion to the slope: on each channel the one is largest where the other
  * is zero.
  */
object IntensityNoise extends Effect {
  val name = "intensity_noise"
  val params = Seq(Param("intensity_noise_rel", "relative rms", "0..0.5"))
  val what = "intensity noise of the light source: both amplitudes scaled by (1 + r n) with n white and the same on both channels, r relative rms per sample"
  val shows = "noise against the signal's value (largest at the fringe's peaks)"
  override def example: Example = Example(EffectSpec(name, Map("intensity_noise_rel" -> 0.004)), "ramp:50000:250000:0.01")
  val domain: Domain = Domain.Periodic
  override val plot: PlotKind = PlotKind.SignalValue

  override val needs: Seq[String] = Seq("intensity_noise_rel")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "intensity_noise_rel", 0, 0.5, "from 0 to 0.5 (50 % of the amplitude rms)")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(intensityNoise = true)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.intensityNoise().toSeq)
  override def refresh(f: Finding, e: SignalEngine): Finding = f.copy(params = f.params + ("intensity_noise_rel" -> math.sqrt(e.noise.jitter2)))
  /** The noise it adds (full scale), rms over the fringe period: a noise of its own kind, not a change at one phase of
    * it (at the peaks, 0.26 LSB beside 1 LSB of white noise was a finding on a clean record at 5 samples a period).
    */
  override def size(c: Cand, e: SignalEngine): Double =
    math.max(e.ampS, e.ampC) * c.params.getOrElse("intensity_noise_rel", 0.0) / math.sqrt(2)
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] =
    Seq("a fast amplitude modulation (the read head's gap or the scale's contrast changing faster than the fit's amplitudes " +
      "follow) predicts the same noise; a spectrum of the amplitude (the radius of the Lissajous figure) tells a white " +
      "source from a band-limited vibration")

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val r = specs.map(_.p("intensity_noise_rel", 0.0)).headOption.getOrElse(0.0)
    private val rnd = new scala.util.Random(p.seed * 43 + 11)
    // one draw per sample (this hook is called once a sample, before both channels), the same factor on both
    private var factor = 1.0
    override val analog: Boolean = r != 0
    override def phaseShift(): Double = { factor = 1 + r * rnd.nextGaussian(); 0.0 }
    override def gain(v: Double, a: At): Double = v * factor
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"intensity noise of the light source ${Effect.g(p, "intensity_noise_rel") * 100}%.3g %% of the amplitude rms: noise grows with the signal's value on both channels together, beside ${Effect.g(p, "white_noise_fs")}%.3g full scale white noise"
}
