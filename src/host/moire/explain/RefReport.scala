package moire.explain

/** What the report says about the reference: which column, the fitted map, and how well the signals follow it. */
object RefReport {
  def notes(e: SignalEngine): Seq[String] = e.reference match {
    case Some(r) =>
      val rms = e.phaseRms
      val kFrom = if (r.kFixed.isDefined) "from the metadata" else "fitted"
      val lag = if (r.hasLag) f", lag ${r.lagS * 1e6}%.4g us" else " (no lag: the reference's speed hardly varies)"
      val check = r.kFixed.filter(k => r.rawSlope != 0 && math.abs(math.abs(r.rawSlope) / k - 1) > 0.1).map(k =>
        f"; the signals move ${math.abs(r.rawSlope)}%.6g periods per ${r.ref.unit} against the metadata's $k%.6g: check the scale keys").getOrElse("")
      Seq(f"reference ${r.ref.describe}: fringe phase = k ref + offset + k lag d(ref)/dt with k = ${r.k}%.6g periods per ${r.ref.unit} " +
        f"($kFrom)$lag, the reference smoothed over ${2 * r.halfWidth + 1} samples; the signals follow it within ${rms * 360}%.3g degree of fringe phase rms (${rms}%.3g of a period)$check")
    case None => e.referenceRefused.map(r => s"reference ${e.refColumn.map(_.column).getOrElse("")}: $r").toSeq
  }

  def params(e: SignalEngine): Map[String, Double] = e.reference.map { r =>
    val rms = e.phaseRms
    Map("reference_periods_per_unit" -> r.k, "reference_lag_s" -> (if (r.hasLag) r.lagS else Double.NaN),
      "reference_phase_rms_deg" -> rms * 360, "reference_phase_rms_periods" -> rms)
  }.getOrElse(Map.empty)
}
