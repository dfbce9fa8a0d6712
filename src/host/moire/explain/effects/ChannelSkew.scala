package moire.explain.effects

import moire.explain._

/** The cos channel sampled later than sin: a phase error growing with speed. */
object ChannelSkew extends Effect {
  val name = "channel_skew"
  val params = Seq(Param("skew_s", "s", "-1e-3..1e-3; |skew| < 1 / (4 pi f_max)"))
  val what = "cos channel sampled skew_s seconds after sin"
  val shows = "phase error growing with speed"
  override val claims: Seq[String] = Seq("against speed")
  override def example: Example = Example(EffectSpec(name, Map("skew_s" -> 30e-9)))
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Speed(phaseOnly = true)

  override val needs: Seq[String] = Seq("skew_s")
  override def check(e: EffectSpec): Option[String] = Effect.within(e, "skew_s", -1e-3, 1e-3, "from -1e-3 to 1e-3 s (1 ms either way)")
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = {
    val k = e.p("skew_s", 0.0); val len = m.samples / m.sampleRateHz
    if (math.abs(k) >= len) throw new ExplainError(f"$name |skew_s| must be below the record's length ($len%.3g s), got ${Effect.show(k)}")
  }
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(hasSkew = true, skewS = e.p("skew_s", 0.0))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.skew().toSeq)
  override def refresh(f: Finding, e: SignalEngine): Finding = f.copy(params = f.params + ("skew_s" -> e.spec.skewS))
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = {
    // a low-pass of the channel ahead with the same lag at the top speed, while its amplitude drop is small
    val tau = f.params.getOrElse("skew_s", Double.NaN); val lag = 2 * math.Pi * e.fMax * math.abs(tau)
    val lowPass = if (!(lag < math.Pi / 2)) Nil else {
      val fc = e.fMax / math.tan(lag); val drop = 1 - math.cos(lag)
      if (!(drop < Bandwidth.SkewLike)) Nil
      else Seq(f"${Bandwidth.name} of the ${if (tau >= 0) "sin" else "cos"} channel alone (a low-pass at ${fc / 1e3}%.0f kHz) predicts " +
        f"the same phase lag growing with speed and an amplitude drop of ${100 * drop}%.2f %% at ${e.fMax / 1e3}%.1f kHz, which " +
        "this fit did not need; a record to higher speeds separates them")
    }
    lowPass ++ TimeOrTravel.phaseLookAlike(e)
  }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val cosDelay: Double = specs.map(_.p("skew_s", 0.0)).sum
    override val analog: Boolean = cosDelay != 0
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    val tau = Effect.g(p, "skew_s"); val who = if (tau >= 0) "cos channel sampled %.1f ns after sin" else "cos channel sampled %.1f ns before sin"
    val d0 = 360 * fMin * tau; val d1 = 360 * fMax * tau
    f"${who.format(math.abs(tau) * 1e9)}: the phase error grows with speed, ${math.abs(d0)}%.2f degree at ${fMin / 1e3}%.1f kHz to ${math.abs(d1)}%.2f degree at ${fMax / 1e3}%.1f kHz"
  }
}
