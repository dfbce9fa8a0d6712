package moire.explain.effects

import moire.explain._

/** Slow linear change of offsets and gains in time (temperature). */
object Drift extends Effect {
  val name = "drift"
  val params = Seq(Param("offset_sin_per_s", "full scale/s", "any"), Param("offset_cos_per_s", "full scale/s", "any"),
    Param("gain_sin_per_s", "1/s", "any"), Param("gain_cos_per_s", "1/s", "any"))
  override val needs: Seq[String] = params.map(_.name)
  val what = "offsets (full scale) and gains (relative) changing linearly with time"
  val shows = "against time"
  override val claims: Seq[String] = Seq("against time")
  override def example: Example = Example(EffectSpec(name, Map("offset_sin_per_s" -> 0.2, "gain_cos_per_s" -> 0.5)), "oscillate:400:300")
  val domain: Domain = Domain.Time
  override val plot: PlotKind = PlotKind.Time

  /** A gain drifting through zero over the record is no drift of an amplifier's gain. */
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = {
    val len = m.samples / m.sampleRateHz
    for (k <- Seq("gain_sin_per_s", "gain_cos_per_s"); g <- e.params.get(k) if !(1 + g * len > 0))
      throw new ExplainError(f"$name $k = ${Effect.show(g)} takes the gain through zero within the record ($len%.4g s)")
  }
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Drift)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.linear(Term.Drift).map(_._1).toSeq)
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    val names = params.map(_.name)
    (names.zip(b).toMap, names.zip(sd).toMap, "against time: offset and amplitude", "both")
  }
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = TimeOrTravel.lookAlikes(e, ContrastAlongTravel.name) ++
    (if (TimeOrTravel.changesGain(f, Seq("gain_sin_per_s", "gain_cos_per_s"))) TimeOrTravel.speedLookAlike(e, alongTravel = false) else Nil)

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private def d(k: String) = specs.map(_.p(k, 0.0)).sum
    private val sin = Slow(gainT = d("gain_sin_per_s"), offsetT = d("offset_sin_per_s"))
    private val cos = Slow(gainT = d("gain_cos_per_s"), offsetT = d("offset_cos_per_s"))
    override def slow(isSin: Boolean): Slow = if (isSin) sin else cos
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    f"offsets drift ${g("offset_sin_per_s")}%.3g / ${g("offset_cos_per_s")}%.3g full scale per second (sin/cos), amplitudes ${100 * g("gain_sin_per_s")}%.3g / ${100 * g("gain_cos_per_s")}%.3g %% per second"
  }
}
