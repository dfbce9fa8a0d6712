package moire.explain.effects

import moire.explain._

/** A first-order low-pass of the read-head amplifier on one channel or both. */
object Bandwidth extends Effect {
  val name = "bandwidth"
  val params = Seq(Param("cutoff_hz", "Hz", "1..1e12"))
  val what = "first-order read-head amplifier low-pass (channel=sin|cos|both)"
  val shows = "amplitude (and lag) against speed"
  override val claims: Seq[String] = Seq("against speed")
  override def example: Example = Example(EffectSpec(name, Map("cutoff_hz" -> 400e3)))
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Speed(phaseOnly = false)

  override def check(e: EffectSpec): Option[String] = Effect.within(e, "cutoff_hz", 1, 1e12, "from 1 Hz to 1e12 Hz")
  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (!(e.p("cutoff_hz") > 0)) throw new ExplainError("bandwidth needs cutoff_hz > 0")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(bw = sp.bw + (e.channel -> e.p("cutoff_hz", 1e6)))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq("both", "sin", "cos").map(ch => () => c.bandwidth(ch).toSeq)
  /** A low-pass of both channels that a later finding took apart into one on each is the sin channel's (the later
    * one is the cos channel's, `Candidates.splitBandwidth`).
    */
  override def refresh(f: Finding, e: SignalEngine): Finding = {
    val g = if (f.channel == "both" && !e.spec.bw.contains("both") && e.spec.bw.contains("sin")) f.copy(channel = "sin") else f
    g.copy(params = g.params + ("cutoff_hz" -> e.spec.bw.getOrElse(g.channel, g.params("cutoff_hz"))))
  }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val sin = Forward.on(specs, isSin = true).map(_.p("cutoff_hz")); private val cos = Forward.on(specs, isSin = false).map(_.p("cutoff_hz"))
    override def cutoffs(isSin: Boolean): Seq[Double] = if (isSin) sin else cos
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    val fc = Effect.g(p, "cutoff_hz"); val u = fMax / fc
    val who = if (channel == "both") "read-head amplifiers (both channels)" else s"$channel channel amplifier"
    f"$who low-pass at ${fc / 1e3}%.1f kHz: amplitude down to ${100 / math.sqrt(1 + u * u)}%.1f %% and phase lag ${math.toDegrees(math.atan(u))}%.2f degree at ${fMax / 1e3}%.1f kHz"
  }
}
