package moire.explain.effects

import moire.explain._

/** Harmonic k of the fringe on one channel or both: the grating's profile, a non-sinusoidal read head. */
object Harmonic extends Effect {
  val name = "harmonic"
  val params = Seq(Param("order", "", "2..100, searched 2..7"), Param("amplitude_rel", "of the fundamental", "0..1"), Param("phase_deg", "degree", "-180..180"))
  val what = "order k of the fringe on one channel or both (channel=sin|cos|both)"
  override val perChannel = true
  val shows = "against fringe phase"
  override val claims: Seq[String] = Seq("against fringe phase")
  override def example: Example = Example(EffectSpec(name, Map("order" -> 3, "amplitude_rel" -> 2e-3), "sin"))
  val domain: Domain = Domain.Periodic
  val Orders: Range = 2 to 7

  override val needs: Seq[String] = Seq("amplitude_rel")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "order", 2, 100, "a whole number from 2 to 100", whole = true)
      .orElse(Effect.within(e, "amplitude_rel", 0, 1, "from 0 to 1 (of the fundamental)"))
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Harm(e.p("order", 2).toInt, e.channel))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    // one step per order: its three variants share their columns (`LinearFamily`)
    for (k <- Orders) yield () => Seq("sin", "cos", "both").flatMap(ch => c.linear(Term.Harm(k, ch)).map(_._1))

  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = t match {
    case Term.Harm(k, ch) if ch != "both" =>
      val (a, sa) = Effect.amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = Effect.deg(b(0), b(1), a, sa)
      (Map("order" -> k, "amplitude_rel" -> a, "phase_deg" -> ph), Map("order" -> 0, "amplitude_rel" -> sa, "phase_deg" -> sph),
        s"against fringe phase: $ch channel, order $k", ch)
    case Term.Harm(k, _) =>
      val (a, sa) = Effect.amp(b(0), b(1), sd(0), sd(1)); val (c, sc) = Effect.amp(b(2), b(3), sd(2), sd(3))
      // each channel's phase as a one-channel harmonic's `phase_deg` (their difference tells a harmonic turning with the
      // fringe from one turning against it)
      val (ps, sps) = Effect.deg(b(0), b(1), a, sa); val (pc, spc) = Effect.deg(b(2), b(3), c, sc)
      (Map("order" -> k, "amplitude_sin_rel" -> a, "amplitude_cos_rel" -> c, "amplitude_rel" -> 0.5 * (a + c), "phase_sin_deg" -> ps, "phase_cos_deg" -> pc),
        Map("order" -> 0, "amplitude_sin_rel" -> sa, "amplitude_cos_rel" -> sc, "amplitude_rel" -> 0.5 * math.hypot(sa, sc), "phase_sin_deg" -> sps, "phase_cos_deg" -> spc),
        s"against fringe phase: both channels, order $k", "both")
    case _ => super.describe(t, b, sd, e)
  }

  private def rel(p: Map[String, Double]): Double =
    Seq("amplitude_rel", "amplitude_sin_rel", "amplitude_cos_rel").flatMap(p.get).filter(!_.isNaN).maxOption.getOrElse(0.0)
  override def valueAmplitude(c: Cand, e: SignalEngine): Option[Double] = Some(rel(c.params) * math.max(e.ampS, e.ampC))

  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = {
    val k = f.params.getOrElse("order", 0.0).toInt
    val (lo, hi) = e.speedRange
    // at one speed a harmonic is a line at k times the fringe frequency: pickup there predicts the same signal
    val line = if (!(hi <= lo * (1 + Interference.SameLine)) || k < 2) Nil
      else Seq(f"${Interference.name} at ${Interference.hz(k * 0.5 * (lo + hi))} ($k x the fringe frequency) predicts the same signal while the " +
        f"head moves at one speed, as it does here (${Interference.hz(lo)} .. ${Interference.hz(hi)}); a record at another speed separates them " +
        "(a harmonic moves with the fringe frequency, pickup stays at its own)")
    line ++ (if (f.channel == "both" || (k != 2 && k != 3)) Nil
    else Seq(s"${AdcNonlinearity.name} of the ${f.channel} ADC alone (a ${if (k == 2) "bow" else "S shape"} of its transfer curve) predicts " +
      s"the same signal while the ${f.channel} amplitude stays constant, as it does here; a record at another amplitude or offset of " +
      s"the ${f.channel} channel separates them (a harmonic scales with the amplitude, INL stays with the code)"))
  }

  override def harmonics(specs: Seq[EffectSpec]): Seq[moire.signal.Harmonic] = specs.map { e =>
    val ch = e.channel match { case "sin" => moire.signal.Channel.Sin; case "cos" => moire.signal.Channel.Cos; case _ => moire.signal.Channel.Both }
    moire.signal.Harmonic(e.p("order", 2).toInt, e.p("amplitude_rel", 0.0), e.p("phase_deg", 0.0), ch)
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"harmonic ${Effect.g(p, "order").toInt} of the fringe on ${sinCos(channel)}: ${100 * Effect.g(p, "amplitude_rel")}%.3f %% of the fundamental"
}
