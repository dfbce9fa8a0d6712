package moire.explain.effects

import moire.explain._

/** Calibration data: the error function needs one more harmonic of the turn (fitted by CalibrationExplain). */
object HarmonicOrder extends Effect {
  val name = "harmonic_order"
  val params = Seq(Param("order", "", ">= 1"), Param("amplitude_arcsec", "arcsec", ">= 0"), Param("phase_deg", "degree", "-180..180"))
  val what = "the error function needs harmonic `order` of the turn"
  val shows = "against angle"
  override def example: Example = Example(EffectSpec(name, Map("order" -> 3, "amplitude_arcsec" -> 2)))
  override def backwardNeeds: Option[String] = Some("calibration data (moire-calibration v1); simulate writes signals")
  override val calibration = true
  override val searched = false
  val domain: Domain = Domain.Periodic
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = throw new ExplainError(s"$name applies to calibration data, not to signals")
  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"harmonic ${Effect.g(p, "order").toInt} of the turn: ${Effect.g(p, "amplitude_arcsec")}%.3g arcsec"
}
