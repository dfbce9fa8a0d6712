package moire.explain.effects

import moire.explain._

/** Sampling-clock jitter: noise growing with the signal's slope, common to both channels. */
object Jitter extends Effect {
  val name = "jitter"
  val params = Seq(Param("jitter_s", "s rms", "0..1e-3"))
  val what = "sampling clock jitter, seconds rms, common to both channels"
  val shows = "noise against signal slope"
  override val claims: Seq[String] = Seq("noise against speed")
  override def example: Example = Example(EffectSpec(name, Map("jitter_s" -> 300e-12)), "ramp:50000:250000:0.01")
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Slope

  override val needs: Seq[String] = Seq("jitter_s")
  override def check(e: EffectSpec): Option[String] = Effect.within(e, "jitter_s", 0, 1e-3, "from 0 to 1e-3 s rms (1 ms)")
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = {
    val j = e.p("jitter_s", 0.0)
    if (j * m.sampleRateHz > 0.25)
      throw new ExplainError(f"$name jitter_s must be at most a quarter of the sample period (${0.25 / m.sampleRateHz}%.3g s at ${m.sampleRateHz}%.6g samples/s), got ${Effect.show(j)}: a clock that wanders by more is no sampling clock")
  }
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(jitter = true)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.jitter().toSeq)
  override def refresh(f: Finding, e: SignalEngine): Finding = f.copy(params = f.params + ("jitter_s" -> math.sqrt(e.noise.jitter2)))
  /** The noise it adds (rms, full scale) at the steepest slope of the fastest 2 % of the record. */
  override def size(c: Cand, e: SignalEngine): Double = 2 * math.Pi * e.fMax * math.max(e.ampS, e.ampC) * c.params.getOrElse("jitter_s", 0.0)
  /** Phase noise of the motion (vibration) adds noise in proportion to the signal's slope against the fringe phase, as
    * jitter does at one speed; jitter's grows with speed. Over a narrow speed range the two predict the same noise.
    */
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] =
    if (e.fMax > Identifiable.JitterSpeedRange * e.fMin) Nil
    else {
      val rad = 2 * math.Pi * e.fMax * f.params.getOrElse("jitter_s", 0.0)
      Seq(f"phase noise of the motion (vibration of ${rad * 1e3}%.3g mrad of fringe phase rms) predicts the same noise here: the fringe " +
        f"frequency spans only ${e.fMin}%.4g .. ${e.fMax}%.4g Hz; a record over a speed range of ${Identifiable.JitterSpeedRange}%.0f or more " +
        "separates them (jitter's noise grows with speed, vibration's does not)")
    }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val jitter = specs.map(_.p("jitter_s", 0.0)).headOption.getOrElse(0.0)
    private val rnd = new scala.util.Random(p.seed * 31 + 7)
    override val analog: Boolean = jitter != 0
    override def timeShift(): Double = if (jitter > 0) jitter * rnd.nextGaussian() else 0.0
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"sampling clock jitter ${Effect.g(p, "jitter_s") * 1e12}%.1f ps rms: noise grows with the signal slope, beside ${Effect.g(p, "white_noise_fs")}%.3g full scale white noise"
}
