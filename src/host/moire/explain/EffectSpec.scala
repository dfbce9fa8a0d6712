package moire.explain


/** One named effect of the physics model with its physical parameters (units in the names). */
final case class EffectSpec(effect: String, params: Map[String, Double] = Map.empty, channel: String = "both") {
  def p(name: String, default: Double = Double.NaN): Double = params.getOrElse(name, default)
  def json: ujson.Obj = {
    val o = ujson.Obj("effect" -> effect, "channel" -> channel)
    params.toSeq.sortBy(_._1).foreach { case (k, v) => o(k) = v }
    o
  }
}

/** The catalogue: each effect, the parameters it takes and what it means. */
object EffectSpec {
  val catalogue: Seq[(String, Seq[String], String)] = Seq(
    ("harmonic", Seq("order", "amplitude_rel", "phase_deg"), "order k of the fringe on one channel or both (channel=sin|cos|both)"),
    ("channel_skew", Seq("skew_s"), "cos channel sampled skew_s seconds after sin"),
    ("bandwidth", Seq("cutoff_hz"), "first-order read-head amplifier low-pass (channel=sin|cos|both)"),
    ("drift", Seq("offset_sin_per_s", "offset_cos_per_s", "gain_sin_per_s", "gain_cos_per_s"), "offsets (full scale) and gains (relative) changing linearly with time"),
    ("amplitude_modulation", Seq("depth", "phase_deg"), "amplitude * (1 + depth cos(mechanical angle + phase)); needs lines_per_rev"),
    ("eccentricity", Seq("eccentricity_rel", "phase_deg"), "disk or magnet off the axis by eccentricity_rel of the reading radius: the read angle is off by eccentricity_rel sin(angle + phase) radians once per turn; needs lines_per_rev (explain: a reference naming turns)"),
    ("angle_harmonic", Seq("order", "amplitude_arcsec", "phase_deg"), "read angle off by amplitude_arcsec sin(order angle + phase), a harmonic of the mechanical angle; needs lines_per_rev (explain: a reference naming turns)"),
    ("jitter", Seq("jitter_s"), "sampling clock jitter, seconds rms, common to both channels"),
    ("adc_bit_fault", Seq("bit", "stuck_at", "bridged_to"), "data line stuck at 0/1, or wired-AND with another bit (channel=sin|cos)"),
    ("clipping", Seq("high_fs", "low_fs"), "amplifier saturation levels in full-scale units (channel=sin|cos|both)"),
    ("adc_nonlinearity", Seq("inl2_lsb", "inl3_lsb"), "INL = inl2 T2(v) + inl3 T3(v) LSB, Chebyshev bow and S shape over full scale"),
    ("crosstalk", Seq("sin_from_cos_tau_s", "cos_from_sin_tau_s"), "capacitive coupling: channel += tau * d(other channel)/dt"),
    ("contrast_along_travel", Seq("offset_sin_per_period", "offset_cos_per_period", "gain_sin_per_period", "gain_cos_per_period"),
      "offsets (full scale) and gains (relative) changing linearly with the position along the travel (beam walk, scale contamination), per fringe period from the start"),
    ("warmup", Seq("offset_sin_step_fs", "offset_cos_step_fs", "gain_sin_step_rel", "gain_cos_step_rel", "time_constant_s"),
      "offsets and gains settling by step * (1 - exp(-t / time_constant_s)) after switch-on"),
    ("coarse_quantization", Seq("effective_bits"), "the codes use only the top effective_bits of the ADC word (a narrower converter in a wider format)"),
    ("interference", Seq("frequency_hz", "amplitude_fs", "phase_deg"), "a fixed-frequency pickup (mains, switching supply) on both channels")
  )
  val calibrationEffects: Seq[(String, Seq[String], String)] = Seq(
    ("harmonic_order", Seq("order", "amplitude_arcsec", "phase_deg"), "the error function needs harmonic `order` of the turn"),
    ("reversal", Seq("reversal_arcsec"), "error(cw) - error(ccw): direction-dependent error (backlash, hysteresis)")
  )
  val names: Seq[String] = catalogue.map(_._1) ++ calibrationEffects.map(_._1)

  /** Parses `name:key=value,key=value` (channel=sin|cos|both allowed among the keys). */
  def parse(s: String): EffectSpec = {
    val (name, rest) = s.indexOf(':') match { case -1 => (s.trim, ""); case i => (s.take(i).trim, s.drop(i + 1)) }
    val allowed = (catalogue ++ calibrationEffects).find(_._1 == name)
      .getOrElse(throw new ExplainError(s"--effect: '$name' is not an effect; allowed: ${names.mkString(", ")}"))
    var channel = "both"; val ps = Map.newBuilder[String, Double]
    rest.split(",").map(_.trim).filter(_.nonEmpty).foreach { kv =>
      kv.split("=", 2) match {
        case Array("channel", v) => channel = checkChannel(v.trim)
        case Array(k, v) if allowed._2.contains(k.trim) =>
          ps += k.trim -> moire.numbers.Decimal.double(v).filter(x => !x.isNaN && !x.isInfinite)
            .getOrElse(throw new ExplainError(s"--effect $name: $k '$v' is not a finite number"))
        case _ => throw new ExplainError(s"--effect $name: '$kv' is not key=value with a key in ${(allowed._2 :+ "channel").mkString(", ")}")
      }
    }
    EffectSpec(name, ps.result(), channel)
  }

  def checkChannel(v: String): String =
    if (Set("sin", "cos", "both").contains(v)) v else throw new ExplainError(s"channel '$v' must be sin, cos or both")

  def fromJson(v: ujson.Value, where: String): EffectSpec = {
    val o = v.objOpt.getOrElse(throw new ExplainError(s"$where: each effect must be a JSON object"))
    val name = o.get("effect").flatMap(_.strOpt).getOrElse(throw new ExplainError(s"$where: an effect has no \"effect\" name"))
    val text = o.toSeq.filter(_._1 != "effect").map { case (k, x) =>
      s"$k=${x.strOpt.getOrElse(x.numOpt.map(_.toString).getOrElse(throw new ExplainError(s"$where: $name.$k must be a number")))}"
    }.mkString(",")
    try parse(s"$name:$text") catch { case e: moire.MoireError => throw new ExplainError(s"$where: ${e.getMessage.stripPrefix("--effect ")}") }
  }
}
