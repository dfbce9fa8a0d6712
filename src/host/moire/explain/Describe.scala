package moire.explain

import moire.signal.Adc

/** Parameters (units in the names), uncertainties and plain-word locations of fitted effects. */
object Describe {
  type Out = (Map[String, Double], Map[String, Double], String)

  private def amp(b0: Double, b1: Double, s0: Double, s1: Double): (Double, Double) = {
    val a = math.hypot(b0, b1)
    (a, if (a > 0) math.sqrt(b0 * b0 * s0 * s0 + b1 * b1 * s1 * s1) / a else math.hypot(s0, s1))
  }
  private def deg(b0: Double, b1: Double, a: Double, sa: Double) = (math.toDegrees(math.atan2(b1, b0)), if (a > 0) math.toDegrees(sa / a) else 180.0)

  /** Linear terms: coefficients b (after the six default columns) and their standard deviations sd. */
  def term(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): (Map[String, Double], Map[String, Double], String, String) = t match {
    case Term.Harm(k, ch) if ch != "both" =>
      val (a, sa) = amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = deg(b(0), b(1), a, sa)
      (Map("order" -> k, "amplitude_rel" -> a, "phase_deg" -> ph), Map("order" -> 0, "amplitude_rel" -> sa, "phase_deg" -> sph),
        s"against fringe phase: $ch channel, order $k", ch)
    case Term.Harm(k, _) =>
      val (a, sa) = amp(b(0), b(1), sd(0), sd(1)); val (c, sc) = amp(b(2), b(3), sd(2), sd(3))
      (Map("order" -> k, "amplitude_sin_rel" -> a, "amplitude_cos_rel" -> c, "amplitude_rel" -> 0.5 * (a + c)),
        Map("order" -> 0, "amplitude_sin_rel" -> sa, "amplitude_cos_rel" -> sc, "amplitude_rel" -> 0.5 * math.hypot(sa, sc)),
        s"against fringe phase: both channels, order $k", "both")
    case Term.Drift =>
      val names = Seq("offset_sin_per_s", "offset_cos_per_s", "gain_sin_per_s", "gain_cos_per_s")
      (names.zip(b).toMap, names.zip(sd).toMap, "against time: offset and amplitude", "both")
    case Term.Contrast =>
      val names = Seq("offset_sin_per_period", "offset_cos_per_period", "gain_sin_per_period", "gain_cos_per_period")
      val span = { val x = e.travel; x.max - x.min }
      (names.zip(b).toMap + ("travel_periods" -> span), names.zip(sd).toMap + ("travel_periods" -> 0.0), "against position: offset and amplitude", "both")
    case Term.Warmup(tau) =>
      // the basis is the part still to come, exp(-t / tau): a step s of the offset is -b; the amplitudes are fitted at
      // their final value A (1 + g), so a relative gain step g is -b / (1 + b)
      def gain(x: Double) = -x / (1 + x)
      (Map("offset_sin_step_fs" -> -b(0), "offset_cos_step_fs" -> -b(1), "gain_sin_step_rel" -> gain(b(2)), "gain_cos_step_rel" -> gain(b(3)),
        "time_constant_s" -> tau),
        Map("offset_sin_step_fs" -> sd(0), "offset_cos_step_fs" -> sd(1), "gain_sin_step_rel" -> sd(2), "gain_cos_step_rel" -> sd(3),
          "time_constant_s" -> Double.NaN), f"against time: offset and amplitude settling with a time constant of ${tau}%.3g s", "both")
    case Term.Am =>
      val (a, sa) = amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = deg(b(0), -b(1), a, sa)
      (Map("depth" -> a, "phase_deg" -> ph), Map("depth" -> sa, "phase_deg" -> sph), "against mechanical angle: amplitude", "both")
    case Term.Inl =>
      (Map("inl2_lsb" -> b(0), "inl3_lsb" -> b(1)), Map("inl2_lsb" -> sd(0), "inl3_lsb" -> sd(1)), "against signal level: both ADCs", "both")
    case Term.Crosstalk =>
      (Map("sin_from_cos_tau_s" -> b(0), "cos_from_sin_tau_s" -> b(1)), Map("sin_from_cos_tau_s" -> sd(0), "cos_from_sin_tau_s" -> sd(1)),
        "against speed: amplitude of each channel", "both")
    case Term.AngleHarm(m) =>
      // b(0) cos + b(1) sin of m x the mechanical angle, in fringe periods = A sin(m angle + phase)
      val (a, sa) = amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = deg(b(1), b(0), a, sa)
      val p = e.periodsPerTurn.getOrElse(Double.NaN); val arcsec = 1296000 / p
      val common = Map("phase_deg" -> ph, "phase_error_deg" -> 360 * a, "angle_error_arcsec" -> arcsec * a)
      val cu = Map("phase_deg" -> sph, "phase_error_deg" -> 360 * sa, "angle_error_arcsec" -> arcsec * sa)
      if (m == 1) (common + ("eccentricity_rel" -> 2 * math.Pi * a / p), cu + ("eccentricity_rel" -> 2 * math.Pi * sa / p),
        "against mechanical angle (reference): fringe phase, once per turn", "both")
      else (common + ("order" -> m), cu + ("order" -> 0.0), s"against mechanical angle (reference): fringe phase, $m times per turn", "both")
    case Term.Interference(hz) =>
      val (a, sa) = amp(b(0), b(1), sd(0), sd(1)); val (c, sc) = amp(b(2), b(3), sd(2), sd(3))
      (Map("frequency_hz" -> hz, "amplitude_sin_fs" -> a, "amplitude_cos_fs" -> c, "amplitude_fs" -> 0.5 * (a + c)),
        Map("frequency_hz" -> e.fs / e.n, "amplitude_sin_fs" -> sa, "amplitude_cos_fs" -> sc, "amplitude_fs" -> 0.5 * math.hypot(sa, sc)),
        f"spectrum: a line at $hz%.1f Hz on both channels", "both")
  }

  def skew(tau: Double, sd: Double, f0: Double, f1: Double): Out =
    (Map("skew_s" -> tau), Map("skew_s" -> sd), f"against speed: cos channel phase, ${f0 / 1e3}%.1f to ${f1 / 1e3}%.1f kHz")

  def bandwidth(ch: String, fc: Double, sd: Double): Out =
    (Map("cutoff_hz" -> fc), Map("cutoff_hz" -> sd), s"against speed: ${if (ch == "both") "amplitude of both channels" else s"$ch channel amplitude and phase"}")

  def jitter(j: Double, sd: Double, white: Double): Out =
    (Map("jitter_s" -> j, "white_noise_fs" -> white), Map("jitter_s" -> sd, "white_noise_fs" -> 0.0), "noise against signal slope (speed and fringe phase)")

  def fault(f: Fault, adc: Adc): Out = {
    val p = Map("bit" -> f.bit.toDouble) ++ (if (f.stuckAt >= 0) Map("stuck_at" -> f.stuckAt.toDouble) else Map("bridged_to" -> f.bridgedTo.toDouble))
    (p, p.map { case (k, _) => k -> 0.0 }, s"code histogram: ${if (f.ch == 0) "sin" else "cos"} channel, bit ${f.bit}")
  }

  /** Clip levels are read off the codes: uncertain by half an LSB. */
  def clip(c: Clip, lsb: Double): Out = {
    val p = Seq("low_fs" -> c.lo, "high_fs" -> c.hi).filter(!_._2.isInfinite).toMap
    (p, p.map { case (k, _) => k -> 0.5 * lsb }, s"code histogram: ${if (c.ch == 0) "sin" else "cos"} channel pile-up at the extremes")
  }

  /** One plain sentence for a finding. */
  def summary(c: Cand, fMin: Double, fMax: Double): String = {
    val p = c.params
    def g(k: String) = p.getOrElse(k, Double.NaN)
    c.effect match {
      case "channel_skew" =>
        val tau = g("skew_s"); val who = if (tau >= 0) "cos channel sampled %.1f ns after sin" else "cos channel sampled %.1f ns before sin"
        val d0 = 360 * fMin * tau; val d1 = 360 * fMax * tau
        f"${who.format(math.abs(tau) * 1e9)}: the phase error grows with speed, ${math.abs(d0)}%.2f degree at ${fMin / 1e3}%.1f kHz to ${math.abs(d1)}%.2f degree at ${fMax / 1e3}%.1f kHz"
      case "bandwidth" =>
        val fc = g("cutoff_hz"); val u = fMax / fc
        val who = if (c.channel == "both") "read-head amplifiers (both channels)" else s"${c.channel} channel amplifier"
        f"$who low-pass at ${fc / 1e3}%.1f kHz: amplitude down to ${100 / math.sqrt(1 + u * u)}%.1f %% and phase lag ${math.toDegrees(math.atan(u))}%.2f degree at ${fMax / 1e3}%.1f kHz"
      case "harmonic" =>
        f"harmonic ${g("order").toInt} of the fringe on ${if (c.channel == "both") "both channels" else s"the ${c.channel} channel"}: ${100 * g("amplitude_rel")}%.3f %% of the fundamental"
      case "drift" =>
        f"offsets drift ${g("offset_sin_per_s")}%.3g / ${g("offset_cos_per_s")}%.3g full scale per second (sin/cos), amplitudes ${100 * g("gain_sin_per_s")}%.3g / ${100 * g("gain_cos_per_s")}%.3g %% per second"
      case "contrast_along_travel" =>
        val l = g("travel_periods")
        f"contrast changes along the travel: amplitudes ${100 * g("gain_sin_per_period") * l}%.3g / ${100 * g("gain_cos_per_period") * l}%.3g %%, offsets ${g("offset_sin_per_period") * l}%.3g / ${g("offset_cos_per_period") * l}%.3g full scale over the ${l}%.0f periods travelled (sin/cos)"
      case "warmup" =>
        f"warm-up: offsets settle by ${g("offset_sin_step_fs")}%.3g / ${g("offset_cos_step_fs")}%.3g full scale, amplitudes by ${100 * g("gain_sin_step_rel")}%.3g / ${100 * g("gain_cos_step_rel")}%.3g %% (sin/cos) with a time constant of ${g("time_constant_s")}%.3g s"
      case "coarse_quantization" =>
        f"the codes use only ${g("effective_bits").toInt} of the ${g("format_bits").toInt} bits: quantization steps of ${g("step_lsb").toInt} LSB, whose error is not white noise"
      case "eccentricity" =>
        f"eccentricity of the disk or magnet: the read angle is off by ${g("angle_error_arcsec")}%.3g arcsec once per turn " +
          f"(${100 * g("eccentricity_rel")}%.3g %% of the reading radius; ${g("phase_error_deg")}%.3g degree of fringe phase)"
      case "angle_harmonic" =>
        f"harmonic ${g("order").toInt} of the mechanical angle in the read angle: ${g("angle_error_arcsec")}%.3g arcsec (${g("phase_error_deg")}%.3g degree of fringe phase)"
      case "amplitude_modulation" => f"amplitude follows the mechanical angle: ${100 * g("depth")}%.2f %% modulation once per revolution"
      case "adc_nonlinearity" => f"ADC integral nonlinearity: bow ${g("inl2_lsb")}%.2f LSB, S-shape ${g("inl3_lsb")}%.2f LSB at full scale"
      case "crosstalk" => f"capacitive crosstalk: sin gets ${g("sin_from_cos_tau_s") * 1e9}%.2f ns x d(cos)/dt, cos gets ${g("cos_from_sin_tau_s") * 1e9}%.2f ns x d(sin)/dt"
      case "interference" => f"pickup at ${g("frequency_hz")}%.1f Hz, ${g("amplitude_fs")}%.3g full scale amplitude"
      case "jitter" => f"sampling clock jitter ${g("jitter_s") * 1e12}%.1f ps rms: noise grows with the signal slope, beside ${g("white_noise_fs")}%.3g full scale white noise"
      case "adc_bit_fault" =>
        if (p.contains("stuck_at")) f"${c.channel} ADC data line ${g("bit").toInt} stuck at ${g("stuck_at").toInt}"
        else f"${c.channel} ADC data lines ${g("bit").toInt} and ${g("bridged_to").toInt} bridged (wired AND)"
      case "clipping" => s"${c.channel} channel saturates" + p.map { case (k, v) => f" ${k.stripSuffix("_fs")} at $v%.4f FS" }.mkString(",")
      case other => other
    }
  }
}
