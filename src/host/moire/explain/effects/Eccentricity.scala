package moire.explain.effects

import moire.explain._

/** Disk or magnet off the axis: the read angle off once per turn. */
object Eccentricity extends AngleHarmonics(1) {
  val name = "eccentricity"
  val params = Seq(Param("eccentricity_rel", "of the reading radius", "0..0.1"), Param("phase_deg", "degree", "-180..180"))
  override def check(e: EffectSpec): Option[String] = Effect.within(e, "eccentricity_rel", 0, 0.1, "from 0 to 0.1 of the reading radius")
  override val needs: Seq[String] = Seq("eccentricity_rel")
  val what = "disk or magnet off the axis by eccentricity_rel of the reading radius: the read angle is off by eccentricity_rel sin(angle + phase) radians once per turn; needs lines_per_rev (explain: a reference naming turns)"
  val shows = "against mechanical angle (reference)"
  override def example: Example = Example(EffectSpec(name, Map("eccentricity_rel" -> 1e-3)), "constant:100000", Some(100.0))
  override def backwardNeeds: Option[String] = Some("a reference column naming turns (ref_deg, ref_turns, ref_counts with counts per turn): without it the read angle's error is motion")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.AngleHarm(1))
  def own(common: Map[String, Double], cu: Map[String, Double], a: Double, sa: Double, p: Double): Effect.Described =
    (common + ("eccentricity_rel" -> 2 * math.Pi * a / p), cu + ("eccentricity_rel" -> 2 * math.Pi * sa / p),
      "against mechanical angle (reference): fringe phase, once per turn", "both")
  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val angleErrors: Seq[(Int, Double, Double)] = specs.map(e => (1, e.p("eccentricity_rel", 0.0) / (2 * math.Pi), e.p("phase_deg", 0.0)))
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    f"eccentricity of the disk or magnet: the read angle is off by ${g("angle_error_arcsec")}%.3g arcsec once per turn " +
      f"(${100 * g("eccentricity_rel")}%.3g %% of the reading radius; ${g("phase_error_deg")}%.3g degree of fringe phase)"
  }
}
