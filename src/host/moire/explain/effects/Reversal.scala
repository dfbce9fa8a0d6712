package moire.explain.effects

import moire.explain._

/** Calibration data: the error differs by direction (backlash, hysteresis). */
object Reversal extends Effect {
  val name = "reversal"
  val params = Seq(Param("reversal_arcsec", "arcsec", "any"))
  val what = "error(cw) - error(ccw): direction-dependent error (backlash, hysteresis)"
  val shows = "by direction"
  override def example: Example = Example(EffectSpec(name, Map("reversal_arcsec" -> 3)))
  override def backwardNeeds: Option[String] = Some("calibration data with a direction column (moire-calibration v1); simulate writes signals")
  override val calibration = true
  override val searched = false
  val domain: Domain = Domain.Time
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = throw new ExplainError(s"$name applies to calibration data, not to signals")
  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"reversal error ${Effect.g(p, "reversal_arcsec")}%.3g arcsec between the directions"
}
