package moire.explain

import moire.recording.Recording
import moire.signal._

import moire.explain.{effects => fx}
import moire.explain.effects.{Effect, Effects}

import scala.util.Random

/** The physics model of the measurement chain, forward direction (`simulate`).
  *
  * Default part: moire.signal.SignalParams (offsets, amplitudes, phase error, harmonics, white noise),
  * a Motion, and the ADC at its bit count. Every further effect is an EffectSpec from the catalogue.
  * Order per sample: sampling instants (skew, jitter) -> fringe (SignalSim.analog) -> read-head low-pass
  * (quasi-static: gain and lag at the instantaneous fringe frequency) -> drift, amplitude modulation,
  * crosstalk, interference -> white noise -> clipping -> INL -> ADC -> bit faults on the pins.
  */
final case class PhysicsModel(
  base: SignalParams,
  motion: Motion,
  sampleRateHz: Double,
  samples: Int,
  adc: Adc = Adc(12),
  linesPerRev: Option[Double] = None,
  effects: Seq[EffectSpec] = Nil
) {
  require(sampleRateHz > 0, s"sample rate must be > 0, got $sampleRateHz")
  require(samples > 0, s"samples must be > 0, got $samples")
  private def all(x: Effect) = effects.filter(_.effect == x.name)

  /** The harmonics of the model: those of `base` and the `harmonic` effects. */
  def signalParams: SignalParams = base.copy(harmonics = base.harmonics ++ all(fx.Harmonic).map { e =>
    val ch = e.channel match { case "sin" => Channel.Sin; case "cos" => Channel.Cos; case _ => Channel.Both }
    Harmonic(e.p("order", 2).toInt, e.p("amplitude_rel", 0.0), e.p("phase_deg", 0.0), ch)
  })

  def validate(): Unit = effects.foreach(e => Effects(e.effect).foreach(_.validate(e, this)))

  /** Generates the recording (codes on the pins) and the true fringe phase in periods. */
  def generate(): (Recording, Array[Double]) = {
    validate()
    val p = signalParams
    val rnd = new Random(p.seed); val rndJ = new Random(p.seed * 31 + 7)
    val n = samples; val fs = sampleRateHz
    val sin = new Array[Int](n); val cos = new Array[Int](n); val truth = new Array[Double](n)
    val skew = all(fx.ChannelSkew).map(_.p("skew_s", 0.0)).sum
    val jitter = all(fx.Jitter).map(_.p("jitter_s", 0.0)).headOption.getOrElse(0.0)
    val bw = all(fx.Bandwidth)
    def bwOn(ch: String) = bw.filter(e => e.channel == ch || e.channel == "both").map(_.p("cutoff_hz"))
    val bwS = bwOn("sin"); val bwC = bwOn("cos")
    val drift = all(fx.Drift)
    def d(k: String) = drift.map(_.p(k, 0.0)).sum
    val (dos, doc, dgs, dgc) = (d("offset_sin_per_s"), d("offset_cos_per_s"), d("gain_sin_per_s"), d("gain_cos_per_s"))
    val am = all(fx.AmplitudeModulation)
    val ct = all(fx.ContrastAlongTravel); def cp(k: String) = ct.map(_.p(k, 0.0)).sum
    val (cos0, coc, cgs, cgc) = (cp("offset_sin_per_period"), cp("offset_cos_per_period"), cp("gain_sin_per_period"), cp("gain_cos_per_period"))
    val x0 = motion.periods(0)
    val warm = all(fx.Warmup); def wp(k: String) = warm.map(_.p(k, 0.0)).sum
    val (wos, woc, wgs, wgc) = (wp("offset_sin_step_fs"), wp("offset_cos_step_fs"), wp("gain_sin_step_rel"), wp("gain_cos_step_rel"))
    val wtau = warm.map(_.p("time_constant_s", 1.0)).headOption.getOrElse(1.0)
    val coarse = all(fx.CoarseQuantization).map(_.p("effective_bits", adc.bits.toDouble).toInt).headOption.filter(_ < adc.bits)
    val xt = all(fx.Crosstalk); val tauSC = xt.map(_.p("sin_from_cos_tau_s", 0.0)).sum; val tauCS = xt.map(_.p("cos_from_sin_tau_s", 0.0)).sum
    val inter = all(fx.Interference)
    val clip = all(fx.Clipping)
    // INL per ADC: the effects on that channel (or both)
    def inlOn(isSin: Boolean, k: String) = all(fx.AdcNonlinearity).filter(e => e.channel == "both" || (e.channel == "sin") == isSin).map(_.p(k, 0.0)).sum
    val (inl2S, inl3S, inl2C, inl3C) = (inlOn(true, "inl2_lsb"), inlOn(true, "inl3_lsb"), inlOn(false, "inl2_lsb"), inlOn(false, "inl3_lsb"))
    val faults = all(fx.AdcBitFault)
    // read-angle errors of the mechanical angle (eccentricity, its harmonics), in turns
    val angleErr = all(fx.Eccentricity).map(e => (1, e.p("eccentricity_rel", 0.0) / (2 * math.Pi), e.p("phase_deg", 0.0))) ++
      all(fx.AngleHarmonic).map(e => (e.p("order", 2).toInt, e.p("amplitude_arcsec", 0.0) / 1296000, e.p("phase_deg", 0.0)))
    def periods(t: Double): Double = {
      val q = motion.periods(t)
      if (angleErr.isEmpty) q
      else { val l = linesPerRev.get; val th = 2 * math.Pi * q / l; q + l * angleErr.map { case (m, a, p) => a * math.sin(m * th + math.toRadians(p)) }.sum }
    }
    val phaseNoise = all(fx.PhaseNoise).map(_.p("phase_noise_rad", 0.0)).headOption.getOrElse(0.0) / (2 * math.Pi)
    val rndP = new Random(p.seed * 17 + 5); var dph = 0.0 // this sample's phase noise (periods), the same on both channels
    val plain = phaseNoise == 0 && skew == 0 && jitter == 0 && bw.isEmpty && drift.isEmpty && am.isEmpty && xt.isEmpty && inter.isEmpty && ct.isEmpty && warm.isEmpty && angleErr.isEmpty
    val eps = 1e-6

    /** One channel's value: fringe through the low-pass and the slow effects. */
    def channel(isSin: Boolean, t: Double): Double = {
      val f = motion.frequency(t)
      var ph = periods(t) + dph; var g = 1.0
      (if (isSin) bwS else bwC).foreach { fc => val u = f / fc; g /= math.sqrt(1 + u * u); ph -= math.atan(u) / (2 * math.Pi) }
      val o = if (isSin) p.offsetSin else p.offsetCos
      def raw(q: Double) = { val a = SignalSim.analog(p, q); (if (isSin) a._1 else a._2) - o }
      var v = raw(ph) * g
      v *= 1 + (if (isSin) dgs else dgc) * t
      val x = motion.periods(t) - x0; val w = if (warm.isEmpty) 0.0 else 1 - math.exp(-t / wtau)
      v *= (1 + (if (isSin) cgs else cgc) * x) * (1 + (if (isSin) wgs else wgc) * w)
      am.foreach { e => v *= 1 + e.p("depth", 0.0) * math.cos(2 * math.Pi * ph / linesPerRev.get + math.toRadians(e.p("phase_deg", 0.0))) }
      val tau = if (isSin) tauSC else tauCS
      if (tau != 0) {
        val q = motion.periods(t)
        val a1 = SignalSim.analog(p, q + eps); val a0 = SignalSim.analog(p, q - eps)
        v += tau * f * (if (isSin) a1._2 - a0._2 else a1._1 - a0._1) / (2 * eps)
      }
      inter.foreach { e => v += e.p("amplitude_fs", 0.0) * math.sin(2 * math.Pi * e.p("frequency_hz", 0.0) * t + math.toRadians(e.p("phase_deg", 0.0))) }
      v + o + (if (isSin) dos else doc) * t + (if (isSin) cos0 else coc) * x + (if (isSin) wos else woc) * w
    }
    def finish(v0: Double, isSin: Boolean): Int = {
      var v = v0
      clip.filter(e => e.channel == "both" || (e.channel == "sin") == isSin).foreach { e =>
        v = math.min(e.p("high_fs", 2.0), math.max(e.p("low_fs", -2.0), v))
      }
      val inl2 = if (isSin) inl2S else inl2C; val inl3 = if (isSin) inl3S else inl3C
      if (inl2 != 0 || inl3 != 0) v += (inl2 * (2 * v * v - 1) + inl3 * (4 * v * v * v - 3 * v)) * adc.lsb
      var code = coarse match {
        case Some(eb) => adc.pins(math.max(-adc.half, Adc(eb).signedCode(v).code << (adc.bits - eb)))
        case None => adc.sample(v).code
      }
      faults.filter(e => (e.channel == "sin") == isSin).foreach(e => code = PhysicsModel.fault(code, e))
      code
    }
    var i = 0
    while (i < n) {
      val t = i / fs
      truth(i) = motion.periods(t)
      var s = 0.0; var c = 0.0
      if (plain) { val a = SignalSim.analog(p, truth(i)); s = a._1; c = a._2 }
      else {
        val tj = t + (if (jitter > 0) jitter * rndJ.nextGaussian() else 0.0)
        dph = if (phaseNoise > 0) phaseNoise * rndP.nextGaussian() else 0.0
        s = channel(isSin = true, tj); c = channel(isSin = false, tj + skew)
      }
      s += p.noiseRms * rnd.nextGaussian(); c += p.noiseRms * rnd.nextGaussian()
      sin(i) = finish(s, isSin = true); cos(i) = finish(c, isSin = false)
      i += 1
    }
    val meta = Map("source" -> "moire simulate", "model" -> ujson.write(json)) ++ linesPerRev.map(l => "lines_per_rev" -> l.toString)
    (Recording(fs, adc, sin, cos, meta), truth)
  }

  def json: ujson.Obj = ujson.Obj(
    "sample_rate_hz" -> sampleRateHz, "samples" -> samples, "adc_bits" -> adc.bits, "adc" -> adc.format.name,
    "motion" -> PhysicsModel.motionJson(motion), "amplitude" -> base.amplitude, "offset_sin" -> base.offsetSin,
    "offset_cos" -> base.offsetCos, "gain_sin" -> base.gainSin, "gain_cos" -> base.gainCos,
    "phase_error_deg" -> base.phaseErrorDeg, "noise_rms" -> base.noiseRms, "seed" -> base.seed.toDouble,
    "lines_per_rev" -> linesPerRev.map(ujson.Num(_)).getOrElse(ujson.Null),
    "effects" -> ujson.Arr(effects.map(_.json): _*))
}

object PhysicsModel {
  /** A bit fault applied to a pin code: stuck_at 0/1, or wired-AND with bit `bridged_to`. */
  def fault(code: Int, e: EffectSpec): Int = {
    val b = e.p("bit").toInt; val m = 1 << b
    if (!e.p("stuck_at").isNaN) { if (e.p("stuck_at") >= 0.5) code | m else code & ~m }
    else if (!e.p("bridged_to").isNaN) {
      val o = e.p("bridged_to").toInt; val both = ((code >> b) & (code >> o) & 1) != 0
      if (both) code | m | (1 << o) else code & ~m & ~(1 << o)
    } else code
  }

  def motionJson(m: Motion): ujson.Obj = m match {
    case Motion.Constant(hz, s) => ujson.Obj("kind" -> "constant", "hz" -> hz, "start" -> s)
    case Motion.Ramp(a, b, d, s) => ujson.Obj("kind" -> "ramp", "hz0" -> a, "hz1" -> b, "duration_s" -> d, "start" -> s)
    case Motion.Oscillate(pk, r, s) => ujson.Obj("kind" -> "oscillate", "periods_peak" -> pk, "rate_hz" -> r, "start" -> s)
  }

  /** `constant:HZ`, `ramp:HZ0:HZ1:SECONDS` or `oscillate:PERIODS:RATE_HZ`. */
  def parseMotion(s: String): Motion = {
    val parts = s.split(":").map(_.trim)
    def num(i: Int) = parts.lift(i).flatMap(moire.numbers.Decimal.double).filter(v => !v.isNaN && !v.isInfinite).getOrElse(
      throw new ExplainError(s"--motion '$s': expected constant:HZ, ramp:HZ0:HZ1:SECONDS or oscillate:PERIODS:RATE_HZ"))
    parts.head match {
      case "constant" => Motion.Constant(num(1))
      case "ramp" if num(3) > 0 => Motion.Ramp(num(1), num(2), num(3))
      case "oscillate" => Motion.Oscillate(num(1), num(2))
      case _ => num(99); Motion.Constant(0)
    }
  }

  def motionFromJson(v: ujson.Value, where: String): Motion = {
    val o = v.objOpt.getOrElse(throw new ExplainError(s"$where: motion must be a JSON object"))
    def n(k: String, d: Option[Double] = None) = o.get(k).flatMap(_.numOpt).orElse(d)
      .getOrElse(throw new ExplainError(s"$where: motion.$k must be a number"))
    o.get("kind").flatMap(_.strOpt) match {
      case Some("constant") => Motion.Constant(n("hz"), n("start", Some(0)))
      case Some("ramp") => Motion.Ramp(n("hz0"), n("hz1"), n("duration_s"), n("start", Some(0)))
      case Some("oscillate") => Motion.Oscillate(n("periods_peak"), n("rate_hz"), n("start", Some(0)))
      case other => throw new ExplainError(s"$where: motion.kind '${other.getOrElse("")}' must be constant, ramp or oscillate")
    }
  }

  /** Reads a model JSON (the format `json` writes); missing keys take the defaults of `d`. */
  /** The object of a model file, or one line saying why the text is not one. */
  def jsonObject(text: String, where: String): collection.Map[String, ujson.Value] = {
    val v = try ujson.read(text) catch { case e: Exception => throw new ExplainError(s"$where: not valid JSON (${e.getMessage.linesIterator.next()})") }
    v.objOpt.getOrElse(throw new ExplainError(s"$where: the model must be a JSON object"))
  }

  /** The `effects` list of a model file's object (`default` when it has none). */
  def effectsFromJson(o: collection.Map[String, ujson.Value], where: String, default: Seq[EffectSpec]): Seq[EffectSpec] =
    o.get("effects").map(_.arrOpt.getOrElse(throw new ExplainError(s"$where: effects must be a list")).toSeq
      .map(EffectSpec.fromJson(_, where))).getOrElse(default)

  def fromJson(text: String, where: String, d: PhysicsModel): PhysicsModel = {
    val o = jsonObject(text, where)
    def n(k: String, dv: Double) = o.get(k).map(x => x.numOpt.getOrElse(throw new ExplainError(s"$where: $k must be a number"))).getOrElse(dv)
    val b = d.base
    val base = b.copy(amplitude = n("amplitude", b.amplitude), offsetSin = n("offset_sin", b.offsetSin), offsetCos = n("offset_cos", b.offsetCos),
      gainSin = n("gain_sin", b.gainSin), gainCos = n("gain_cos", b.gainCos), phaseErrorDeg = n("phase_error_deg", b.phaseErrorDeg),
      noiseRms = n("noise_rms", b.noiseRms), seed = n("seed", b.seed.toDouble).toLong)
    val fmt = o.get("adc").flatMap(_.strOpt).map(s => AdcFormat.parse(s).fold(e => throw new ExplainError(s"$where: $e"), identity)).getOrElse(d.adc.format)
    val effects = effectsFromJson(o, where, d.effects)
    try PhysicsModel(base, o.get("motion").map(motionFromJson(_, where)).getOrElse(d.motion), n("sample_rate_hz", d.sampleRateHz),
      n("samples", d.samples).toInt, Adc(n("adc_bits", d.adc.bits).toInt, fmt),
      o.get("lines_per_rev").flatMap(_.numOpt).orElse(d.linesPerRev), effects)
    catch { case e: IllegalArgumentException => throw new ExplainError(s"$where: ${e.getMessage.stripPrefix("requirement failed: ")}") }
  }
}
