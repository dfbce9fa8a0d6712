package moire.explain.effects

import moire.explain._

/** The read angle off twice per turn (an elliptic disk, a tilted magnet). */
object AngleHarmonic extends AngleHarmonics(2) {
  val name = "angle_harmonic"
  val params = Seq(Param("order", "", "2"), Param("amplitude_arcsec", "arcsec", ">= 0"), Param("phase_deg", "degree", "-180..180"))
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "order", 1, 100, "a whole number from 1 to 100 (per turn)", whole = true)
      .orElse(Effect.within(e, "amplitude_arcsec", 0, 36000, "from 0 to 36000 arcsec (10 degree)"))
  override val needs: Seq[String] = Seq("amplitude_arcsec")
  val what = "read angle off by amplitude_arcsec sin(order angle + phase), a harmonic of the mechanical angle; needs lines_per_rev (explain: a reference naming turns)"
  val shows = "against mechanical angle (reference)"
  override def example: Example = Example(EffectSpec(name, Map("order" -> 2, "amplitude_arcsec" -> 200)), "constant:100000", Some(100.0))
  override def backwardNeeds: Option[String] = Some("a reference column naming turns (ref_deg, ref_turns, ref_counts with counts per turn): without it the read angle's error is motion")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.AngleHarm(e.p("order", 2).toInt))
  def own(common: Map[String, Double], cu: Map[String, Double], a: Double, sa: Double, p: Double): Effect.Described =
    (common + ("order" -> 2.0), cu + ("order" -> 0.0), "against mechanical angle (reference): fringe phase, 2 times per turn", "both")
  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val angleErrors: Seq[(Int, Double, Double)] = specs.map(e => (e.p("order", 2).toInt, e.p("amplitude_arcsec", 0.0) / 1296000, e.p("phase_deg", 0.0)))
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    f"harmonic ${g("order").toInt} of the mechanical angle in the read angle: ${g("angle_error_arcsec")}%.3g arcsec (${g("phase_error_deg")}%.3g degree of fringe phase)"
  }
}
