package moire.explain.effects

import moire.explain._

/** Offsets and gains settling as 1 - exp(-t / tau) after switch-on. */
object Warmup extends Effect {
  val name = "warmup"
  val params = Seq(Param("offset_sin_step_fs", "full scale", "any"), Param("offset_cos_step_fs", "full scale", "any"),
    Param("gain_sin_step_rel", "relative", "> -1"), Param("gain_cos_step_rel", "relative", "> -1"), Param("time_constant_s", "s", "> 0"))
  override val needs: Seq[String] = params.map(_.name).filter(_.contains("step"))
  val what = "offsets and gains settling by step * (1 - exp(-t / time_constant_s)) after switch-on"
  val shows = "against time"
  override val claims: Seq[String] = Seq("against time")
  override def example: Example = Example(EffectSpec(name, Map("offset_sin_step_fs" -> 0.005, "gain_cos_step_rel" -> 0.01, "time_constant_s" -> 0.002)), "oscillate:400:300")
  val domain: Domain = Domain.Settling
  override val plot: PlotKind = PlotKind.Time

  // a relative gain step of -1 or less leaves no signal, or turns it over: no warm-up
  override def check(e: EffectSpec): Option[String] =
    Seq("gain_sin_step_rel", "gain_cos_step_rel").flatMap(k => e.params.get(k).filter(v => !(v > -1)).map(v =>
      s"$k must be above -1 (a gain step of -1 leaves no signal), got ${Effect.show(v)}")).headOption
  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (!(e.p("time_constant_s") > 0)) throw new ExplainError("warmup needs time_constant_s > 0")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Warmup(e.p("time_constant_s", 1.0)))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.warmup().toSeq)
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = t match {
    case Term.Warmup(tau) =>
      // the basis is the part still to come, exp(-t / tau): a step s of the offset is -b; the amplitudes are fitted at
      // their final value A (1 + g), so a relative gain step g is -b / (1 + b)
      def gain(x: Double) = -x / (1 + x)
      (Map("offset_sin_step_fs" -> -b(0), "offset_cos_step_fs" -> -b(1), "gain_sin_step_rel" -> gain(b(2)), "gain_cos_step_rel" -> gain(b(3)),
        "time_constant_s" -> tau),
        Map("offset_sin_step_fs" -> sd(0), "offset_cos_step_fs" -> sd(1), "gain_sin_step_rel" -> sd(2), "gain_cos_step_rel" -> sd(3),
          "time_constant_s" -> Double.NaN), f"against time: offset and amplitude settling with a time constant of ${tau}%.3g s", "both")
    case _ => super.describe(t, b, sd, e)
  }
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = TimeOrTravel.lookAlikes(e, ContrastAlongTravel.name) ++
    (if (TimeOrTravel.changesGain(f, Seq("gain_sin_step_rel", "gain_cos_step_rel"))) TimeOrTravel.speedLookAlike(e, alongTravel = false) else Nil)

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private def d(k: String) = specs.map(_.p(k, 0.0)).sum
    private val sin = Slow(gainW = d("gain_sin_step_rel"), offsetW = d("offset_sin_step_fs"))
    private val cos = Slow(gainW = d("gain_cos_step_rel"), offsetW = d("offset_cos_step_fs"))
    override def slow(isSin: Boolean): Slow = if (isSin) sin else cos
    override val warmupTau: Option[Double] = Some(specs.map(_.p("time_constant_s", 1.0)).headOption.getOrElse(1.0))
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    f"warm-up: offsets settle by ${g("offset_sin_step_fs")}%.3g / ${g("offset_cos_step_fs")}%.3g full scale, amplitudes by ${100 * g("gain_sin_step_rel")}%.3g / ${100 * g("gain_cos_step_rel")}%.3g %% (sin/cos) with a time constant of ${g("time_constant_s")}%.3g s"
  }
}
