package moire.explain.effects

import moire.explain._

/** Capacitive coupling between the channels: each gets tau times the other's derivative. */
object Crosstalk extends Effect {
  val name = "crosstalk"
  val params = Seq(Param("sin_from_cos_tau_s", "s", "any"), Param("cos_from_sin_tau_s", "s", "any"))
  override val needs: Seq[String] = params.map(_.name)
  val what = "capacitive coupling: channel += tau * d(other channel)/dt"
  val shows = "amplitude against speed"
  override val claims: Seq[String] = Seq("against speed")
  override def example: Example = Example(EffectSpec(name, Map("sin_from_cos_tau_s" -> 2e-9)))
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Speed(phaseOnly = false)

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Crosstalk)
  /** The linear term with the skew and cut-offs held, or with them searched again when that fits better. */
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq { () =>
    val held = c.linear(Term.Crosstalk).map(_._1)
    c.crosstalkJoint(held).orElse(held).toSeq
  }
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described =
    (Map("sin_from_cos_tau_s" -> b(0), "cos_from_sin_tau_s" -> b(1)), Map("sin_from_cos_tau_s" -> sd(0), "cos_from_sin_tau_s" -> sd(1)),
      "against speed: amplitude of each channel", "both")

  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = TimeOrTravel.changeLookAlikes(e)

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val tauSC = specs.map(_.p("sin_from_cos_tau_s", 0.0)).sum; private val tauCS = specs.map(_.p("cos_from_sin_tau_s", 0.0)).sum
    private val eps = 1e-6
    /** The other channel's derivative in time, times the coupling's time constant. */
    override def add(v: Double, a: At): Double = {
      val tau = if (a.isSin) tauSC else tauCS
      if (tau == 0) v
      else {
        val a1 = moire.signal.SignalSim.analog(p, a.q + eps); val a0 = moire.signal.SignalSim.analog(p, a.q - eps)
        v + tau * a.f * (if (a.isSin) a1._2 - a0._2 else a1._1 - a0._1) / (2 * eps)
      }
    }
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"capacitive crosstalk: sin gets ${Effect.g(p, "sin_from_cos_tau_s") * 1e9}%.2f ns x d(cos)/dt, cos gets ${Effect.g(p, "cos_from_sin_tau_s") * 1e9}%.2f ns x d(sin)/dt"
}
