package moire.monitor

/** How counts map to length or angle, and codes to volts: each `None` when not known.
  * @param countsPerPeriod M, counts per grating period (the board's register, or the recording's metadata)
  * @param periodUm        grating period in micrometres (linear scales)
  * @param linesPerRev     grating lines per revolution (rotary scales)
  * @param fullScaleV      volts at full scale 1.0 of the ADC input (the AD9226: 1 V at 2 Vpp span)
  */
final case class Scale(countsPerPeriod: Option[Double], periodUm: Option[Double], linesPerRev: Option[Double], fullScaleV: Option[Double]) {
  def um(counts: Double): Option[Double] = for (m <- countsPerPeriod; p <- periodUm) yield counts / m * p
  def degrees(counts: Double): Option[Double] = for (m <- countsPerPeriod; l <- linesPerRev) yield counts / m / l * 360
  def json: ujson.Obj = ujson.Obj("counts_per_period" -> opt(countsPerPeriod), "period_um" -> opt(periodUm),
    "lines_per_rev" -> opt(linesPerRev), "full_scale_v" -> opt(fullScaleV))
  private def opt(v: Option[Double]): ujson.Value = v.fold[ujson.Value](ujson.Null)(ujson.Num(_))
}

object Scale {
  /** From a recording's metadata (keys of docs/recording.md), with the user's values first. */
  def of(meta: Map[String, String], user: Scale): Scale = {
    def m(k: String) = meta.get(k).flatMap(_.trim.toDoubleOption).filter(v => v > 0 && !v.isInfinite)
    Scale(user.countsPerPeriod.orElse(m("counts_per_period")), user.periodUm.orElse(m("period_um")),
      user.linesPerRev.orElse(m("lines_per_rev")), user.fullScaleV.orElse(m("adc_full_scale_v")))
  }
  val none: Scale = Scale(None, None, None, None)
}
