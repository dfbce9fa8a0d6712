package moire.monitor

/** The tolerance marks of the readouts; the page shows them and lets the user change them (POST /api/tolerances).
  * Amplitudes and offsets in % of full scale, the ratio as a relative departure from 1 in %, the phase in degrees.
  */
final case class Tolerances(amplitudeMinPct: Double = 40, amplitudeMaxPct: Double = 95, offsetPct: Double = 2,
                            ratioPct: Double = 5, phaseDeg: Double = 2) {
  def json: ujson.Obj = ujson.Obj("amplitude_min_pct" -> amplitudeMinPct, "amplitude_max_pct" -> amplitudeMaxPct,
    "offset_pct" -> offsetPct, "ratio_pct" -> ratioPct, "phase_deg" -> phaseDeg)
}

object Tolerances {
  val defaults: Tolerances = Tolerances()
  val keys: Seq[String] = defaults.json.obj.keys.toSeq
  /** The largest mark of each: a signal spans at most the full scale (an amplitude or offset above 100 % is none a
    * converter shows); the cos channel's phase is at most 90 degrees off quadrature before the channels swap roles.
    */
  private val Max: Map[String, Double] = keys.map(k => k -> (if (k == "phase_deg") 90.0 else 100.0)).toMap

  /** Changes from a JSON object of some of [[keys]]; Left with a message for anything else. */
  def update(t: Tolerances, body: String): Either[String, Tolerances] = {
    val j = try moire.options.StrictJson.read(body) catch { case e: Exception => return Left(s"not JSON: ${e.getMessage.linesIterator.next().take(80)}") }
    val o = j.objOpt.getOrElse(return Left("expected a JSON object like {\"phase_deg\": 1.5}"))
    val bad = o.keys.filterNot(keys.contains)
    if (bad.nonEmpty) return Left(s"unknown tolerance ${bad.mkString(", ")}; known: ${keys.mkString(", ")}")
    val v = o.map { case (k, x) => k -> x.numOpt.filter(d => d > 0 && d <= Max(k)).getOrElse(return Left(s"$k must be a number above 0 and at most ${Max(k).toInt}, got ${ujson.write(x).take(30)}")) }
    val r = t.copy(amplitudeMinPct = v.getOrElse("amplitude_min_pct", t.amplitudeMinPct), amplitudeMaxPct = v.getOrElse("amplitude_max_pct", t.amplitudeMaxPct),
      offsetPct = v.getOrElse("offset_pct", t.offsetPct), ratioPct = v.getOrElse("ratio_pct", t.ratioPct), phaseDeg = v.getOrElse("phase_deg", t.phaseDeg))
    if (r.amplitudeMinPct >= r.amplitudeMaxPct) Left(s"amplitude_min_pct (${r.amplitudeMinPct}) must be below amplitude_max_pct (${r.amplitudeMaxPct})")
    else Right(r)
  }
}
