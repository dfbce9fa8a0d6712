package moire.explain.effects

import moire.explain._

/** A first-order low-pass of the read-head amplifier on one channel or both. */
object Bandwidth extends Effect {
  val name = "bandwidth"
  val params = Seq(Param("cutoff_hz", "Hz", "1..1e12"))
  val what = "first-order read-head amplifier low-pass (channel=sin|cos|both)"
  override val perChannel = true
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

  /** A low-pass of one channel whose amplitude hardly drops over the record's speeds is mostly a phase lag growing
    * with speed: a skew between the channels predicts nearly the same (a trapezoid move's 50 ns skew came out as a
    * 3.2 MHz low-pass of the sin channel, with no look-alike named).
    */
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = {
    val fc = f.params.getOrElse("cutoff_hz", Double.NaN); val u = e.fMax / fc
    val drop = 1 - 1 / math.sqrt(1 + u * u); val lag = math.atan(u)
    if (f.channel == "both" || !(drop < SkewLike)) Nil
    else {
      // a lag of sin is cos ahead: cos sampled later
      val tau = lag / (2 * math.Pi * e.fMax)
      Seq(f"${ChannelSkew.name} (the cos channel sampled ${tau * 1e9}%.1f ns ${if (f.channel == "sin") "after" else "before"} sin) predicts the same phase lag growing " +
        f"with speed; only the amplitude's drop of ${100 * drop}%.2f %% at ${e.fMax / 1e3}%.1f kHz tells the low-pass apart, and " +
        "a record to higher speeds separates them")
    }
  }
  /** The largest amplitude drop over the record's speeds at which a one-channel low-pass still looks like a skew. */
  val SkewLike = 0.01

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
