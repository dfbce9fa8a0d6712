package moire.explain

import moire.recording.Recording
import moire.signal._

import moire.explain.effects.{At, Effect, Effects, Forward, Slow}

import scala.util.Random

/** The physics model of the measurement chain, forward direction (`simulate`).
  *
  * Default part: moire.signal.SignalParams (offsets, amplitudes, phase error, harmonics, white noise),
  * a Motion, and the ADC at its bit count. Every further effect is an EffectSpec from the catalogue; each effect's
  * forward step is its `Forward` (effects/Forward.scala), called in the registry's order at each hook.
  * Order per sample: sampling instants -> read angle and fringe (SignalSim.analog) -> read-head low-pass
  * (quasi-static: gain and lag at the instantaneous fringe frequency) -> slow gain terms -> gain -> additive terms
  * -> slow offset terms -> white noise -> front end -> ADC transfer -> quantizer (the ADC's) -> pins.
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

  /** The harmonics of the model: those of `base` and those the effects add. */
  def signalParams: SignalParams = base.copy(harmonics = base.harmonics ++ Effects.all.flatMap { x =>
    val s = all(x); if (s.isEmpty) Nil else x.harmonics(s)
  })

  /** Checks each effect: its values (`check`), a key it needs to change anything (`needs`), and against this model. */
  def validate(): Unit = effects.foreach(e => Effects(e.effect).foreach { x =>
    x.check(e).foreach(m => throw new ExplainError(s"${x.name}: $m"))
    if (x.needs.nonEmpty && !x.needs.exists(e.params.contains)) {
      val keys = if (x.needs.size == 1) x.needs.head else x.needs.init.mkString(", ") + " or " + x.needs.last
      throw new ExplainError(s"${x.name} changes nothing without $keys: give ${if (x.needs.size == 1) "it" else "one"}, e.g. ${x.example.effect.text}")
    }
    x.validate(e, this)
  })

  /** Generates the recording (codes on the pins) and the true fringe phase in periods. */
  def generate(): (Recording, Array[Double]) = {
    validate()
    val p = signalParams
    val fw = Effects.all.flatMap { x => val s = all(x); if (s.isEmpty) None else Some(x.forward(s, this, p)) }.filter(_ ne Forward.none)
    val fa = fw.toArray; val fan = fw.filter(_.analog).toArray // per sample, in the registry's order
    val rnd = new Random(p.seed)
    val n = samples; val fs = sampleRateHz
    val sin = new Array[Int](n); val cos = new Array[Int](n); val truth = new Array[Double](n)
    val skew = fw.map(_.cosDelay).sum
    val cutS = fw.flatMap(_.cutoffs(isSin = true)); val cutC = fw.flatMap(_.cutoffs(isSin = false))
    val slowS = fw.map(_.slow(isSin = true)).foldLeft(Slow())(_ + _); val slowC = fw.map(_.slow(isSin = false)).foldLeft(Slow())(_ + _)
    val warm = fw.exists(_.warmupTau.nonEmpty); val tau = fw.flatMap(_.warmupTau).headOption.getOrElse(1.0)
    val x0 = motion.periods(0)
    val quantize: Double => Int = fw.flatMap(_.quantizer).headOption.getOrElse((v: Double) => adc.sample(v).code)
    // read-angle errors of the mechanical angle, in turns
    val angleErr = fw.flatMap(_.angleErrors)
    def periods(t: Double): Double = {
      val q = motion.periods(t)
      if (angleErr.isEmpty) q
      else { val l = linesPerRev.get; val th = 2 * math.Pi * q / l; q + l * angleErr.map { case (m, a, p) => a * math.sin(m * th + math.toRadians(p)) }.sum }
    }
    var dph = 0.0 // this sample's phase shift (periods), the same on both channels
    val plain = !fw.exists(_.analog)
    val bare = p.copy(harmonics = Nil) // the fundamental alone (the harmonics added apart behind a low-pass)

    /** One channel's value: fringe through the low-pass and the slow effects. */
    def channel(isSin: Boolean, t: Double): Double = {
      val f = motion.frequency(t)
      var ph = periods(t) + dph; var g = 1.0
      (if (isSin) cutS else cutC).foreach { fc => val u = f / fc; g /= math.sqrt(1 + u * u); ph -= math.atan(u) / (2 * math.Pi) }
      val o = if (isSin) p.offsetSin else p.offsetCos
      val cuts = if (isSin) cutS else cutC
      // with a low-pass, each harmonic of the fringe passes it at k f, with its own gain and lag (the fundamental's, k
      // times, was a quasi-static shortcut: a 0.4 % third harmonic behind 550 kHz at 350 kHz is half as large)
      val split = cuts.nonEmpty && p.harmonics.nonEmpty
      def raw(q: Double) = { val a = SignalSim.analog(if (split) bare else p, q); (if (isSin) a._1 else a._2) - o }
      val sl = if (isSin) slowS else slowC
      var v = raw(ph) * g
      if (split) {
        val q0 = periods(t) + dph; val amp = p.amplitude * (if (isSin) p.gainSin else p.gainCos)
        p.harmonics.foreach { h =>
          if (h.channel != (if (isSin) Channel.Cos else Channel.Sin)) {
            var gk = 1.0; var lag = 0.0
            cuts.foreach { fc => val u = h.order * f / fc; gk /= math.sqrt(1 + u * u); lag += math.atan(u) }
            val a = h.order * 2 * math.Pi * q0 + math.toRadians(h.phaseDeg) - lag
            v += amp * h.amplitude * gk * (if (isSin) math.sin(a) else math.cos(a))
          }
        }
      }
      v *= 1 + sl.gainT * t
      val q = motion.periods(t); val x = q - x0; val w = if (warm) 1 - math.exp(-t / tau) else 0.0
      v *= (1 + sl.gainX * x) * (1 + sl.gainW * w)
      val at = At(isSin, t, f, q, x, ph)
      var k = 0; while (k < fan.length) { v = fan(k).gain(v, at); k += 1 }
      k = 0; while (k < fan.length) { v = fan(k).add(v, at); k += 1 }
      v + o + sl.offsetT * t + sl.offsetX * x + sl.offsetW * w
    }
    def finish(v0: Double, isSin: Boolean): Int = {
      var v = v0
      var k = 0; while (k < fa.length) { v = fa(k).frontEnd(v, isSin); k += 1 }
      k = 0; while (k < fa.length) { v = fa(k).transfer(v, isSin); k += 1 }
      var code = quantize(v)
      k = 0; while (k < fa.length) { code = fa(k).pins(code, isSin); k += 1 }
      code
    }
    var i = 0
    while (i < n) {
      val t = i / fs
      truth(i) = motion.periods(t)
      var s = 0.0; var c = 0.0
      if (plain) { val a = SignalSim.analog(p, truth(i)); s = a._1; c = a._2 }
      else {
        var dt = 0.0; dph = 0.0
        var k = 0; while (k < fan.length) { dt += fan(k).timeShift(); dph += fan(k).phaseShift(); k += 1 }
        val tj = t + dt
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
  /** The largest seed a model line keeps exactly (a JSON number is a double: 2^53). */
  val MaxSeed: Long = 1L << 53
  def motionJson(m: Motion): ujson.Obj = m match {
    case Motion.Constant(hz, s) => ujson.Obj("kind" -> "constant", "hz" -> hz, "start" -> s)
    case Motion.Ramp(a, b, d, s) => ujson.Obj("kind" -> "ramp", "hz0" -> a, "hz1" -> b, "duration_s" -> d, "start" -> s)
    case Motion.Oscillate(pk, r, s) => ujson.Obj("kind" -> "oscillate", "periods_peak" -> pk, "rate_hz" -> r, "start" -> s)
  }

  /** The forms of `--motion`, by kind. */
  private val MotionForms = Seq("constant" -> "constant:HZ", "ramp" -> "ramp:HZ0:HZ1:SECONDS", "oscillate" -> "oscillate:PERIODS:RATE_HZ")

  /** `constant:HZ`, `ramp:HZ0:HZ1:SECONDS` or `oscillate:PERIODS:RATE_HZ`, each value given once, none left over. */
  def parseMotion(s: String): Motion = {
    val parts = s.split(":", -1).map(_.trim)
    def bad(why: String) = throw new ExplainError(s"--motion '$s': $why")
    val form = MotionForms.collectFirst { case (k, f) if k == parts.head => f }
      .getOrElse(bad(s"expected ${MotionForms.map(_._2).mkString(", ")}"))
    val want = form.count(_ == ':') + 1
    if (parts.length != want) bad(s"${if (parts.length > want) "too many" else "too few"} values, expected $form")
    def num(i: Int) = moire.numbers.Decimal.double(parts(i)).filter(v => !v.isNaN && !v.isInfinite)
      .getOrElse(bad(s"'${parts(i)}' is not a finite number ($form)"))
    val m = parts.head match {
      case "constant" => Motion.Constant(num(1))
      case "ramp" => Motion.Ramp(num(1), num(2), if (num(3) > 0) num(3) else bad("SECONDS must be > 0"))
      case _ => Motion.Oscillate(num(1), num(2))
    }
    checkMotion(m).foreach(bad)
    m
  }

  /** Why a motion makes no sense (an oscillation needs a positive size and rate), or None. */
  def checkMotion(m: Motion): Option[String] = m match {
    case Motion.Oscillate(pk, _, _) if !(pk > 0) => Some(s"PERIODS (the peak excursion) must be > 0, got ${effects.Effect.show(pk)}")
    case Motion.Oscillate(_, r, _) if !(r > 0) => Some(s"RATE_HZ must be > 0, got ${effects.Effect.show(r)}")
    case _ => None
  }

  def motionFromJson(v: ujson.Value, where: String): Motion = {
    val o = v.objOpt.getOrElse(throw new ExplainError(s"$where: motion must be a JSON object"))
    def n(k: String, d: Option[Double] = None) = o.get(k).flatMap(_.numOpt).orElse(d)
      .getOrElse(throw new ExplainError(s"$where: motion.$k must be a number"))
    val m = o.get("kind").flatMap(_.strOpt) match {
      case Some("constant") => Motion.Constant(n("hz"), n("start", Some(0)))
      case Some("ramp") if n("duration_s") > 0 => Motion.Ramp(n("hz0"), n("hz1"), n("duration_s"), n("start", Some(0)))
      case Some("ramp") => throw new ExplainError(s"$where: motion.duration_s must be > 0")
      case Some("oscillate") => Motion.Oscillate(n("periods_peak"), n("rate_hz"), n("start", Some(0)))
      case other => throw new ExplainError(s"$where: motion.kind '${other.getOrElse("")}' must be constant, ramp or oscillate")
    }
    // a key the kind does not read (a misspelled one) is refused, as at the model's top level
    val keys = "kind" +: "start" +: (m match {
      case _: Motion.Constant => Seq("hz"); case _: Motion.Ramp => Seq("hz0", "hz1", "duration_s"); case _ => Seq("periods_peak", "rate_hz") })
    o.keys.find(k => !keys.contains(k)).foreach(k =>
      throw new ExplainError(s"$where: motion: unknown key '$k' (a ${o("kind").str} motion has ${keys.mkString(", ")})"))
    checkMotion(m).foreach(w => throw new ExplainError(s"$where: motion: $w"))
    m
  }

  /** The model's numbers as a model file's keys, with `simulate`'s options that set them. */
  val NumberKeys: Seq[(String, String)] = Seq("sample_rate_hz" -> "--sample-rate-hz", "samples" -> "--samples",
    "adc_bits" -> "--adc-bits", "amplitude" -> "--amplitude", "offset_sin" -> "--offset-sin", "offset_cos" -> "--offset-cos",
    "gain_sin" -> "--gain-sin", "gain_cos" -> "--gain-cos", "phase_error_deg" -> "--phase-error-deg", "noise_rms" -> "--noise",
    "seed" -> "--seed", "lines_per_rev" -> "--lines-per-rev")
  /** The keys of a model file (those `json` writes). */
  val Keys: Seq[String] = NumberKeys.map(_._1) ++ Seq("adc", "motion", "effects")

  /** Why the model's numbers make no sense, the number named by `name` (a key: a model file's, or an option), or
    * None. The same rules for a model file as for the command line.
    */
  def check(v: Map[String, Double], name: String => String): Option[String] = {
    def at(k: String) = v.getOrElse(k, Double.NaN)
    NumberKeys.map(_._1).filter(v.contains).collectFirst { case k if at(k).isNaN || at(k).isInfinite => s"${name(k)} must be a finite number, got ${at(k)}" }
      .orElse(Option.when(!(at("sample_rate_hz") >= Recording.MinSampleRateHz && at("sample_rate_hz") <= Recording.MaxSampleRateHz))(
        s"${name("sample_rate_hz")} must be from 1e-6 to 1e11 Hz, got ${at("sample_rate_hz")}"))
      .orElse(Option.when(at("noise_rms") < 0)(s"${name("noise_rms")} must be 0 or more (full-scale rms), got ${at("noise_rms")}"))
      .orElse(Option.when(at("samples") < 1)(s"${name("samples")} must be at least 1, got ${at("samples").toLong}"))
      .orElse(Option.when(!(at("amplitude") > 0))(s"${name("amplitude")} must be above 0, got ${at("amplitude")}"))
      .orElse(Seq("gain_sin", "gain_cos").filter(v.contains).collectFirst { case k if !(at(k) > 0) => s"${name(k)} must be above 0 (a channel's gain), got ${at(k)}" })
      .orElse(v.get("phase_error_deg").filter(p => !(math.abs(p) < 90)).map(p =>
        s"${name("phase_error_deg")} must be between -90 and 90 degree (at 90 the two channels carry one signal: no quadrature), got $p"))
      .orElse(v.get("lines_per_rev").filter(l => !(l >= 1 && l == math.rint(l) && l <= 1e9))
        .map(l => s"${name("lines_per_rev")} must be a whole number of grating lines, 1 or more, got ${effects.Effect.show(l)}"))
  }

  /** Reads a model JSON (the format `json` writes); missing keys take the defaults of `d`. A key it does not know, a
    * number out of its range or a count that is not whole is one line naming the key.
    */
  /** The object of a model file, or one line saying why the text is not one. */
  def jsonObject(text: String, where: String): collection.Map[String, ujson.Value] = {
    val v = try moire.options.StrictJson.read(text) catch {
      case e: moire.options.StrictJson.DuplicateKey => throw new ExplainError(s"$where: ${e.getMessage}")
      case e: Exception => throw new ExplainError(s"$where: not valid JSON (${e.getMessage.linesIterator.next()})")
    }
    v.objOpt.getOrElse(throw new ExplainError(s"$where: the model must be a JSON object"))
  }

  /** The `effects` list of a model file's object (`default` when it has none). */
  def effectsFromJson(o: collection.Map[String, ujson.Value], where: String, default: Seq[EffectSpec]): Seq[EffectSpec] =
    o.get("effects").map(_.arrOpt.getOrElse(throw new ExplainError(s"$where: effects must be a list")).toSeq
      .map(EffectSpec.fromJson(_, where))).getOrElse(default)

  /** A model file's model, `d`'s values where it names none. `given`: the keys an option given on the command line set
    * (samples for --samples): the file setting one too is refused (one of the two would be dropped without a word).
    */
  def fromJson(text: String, where: String, d: PhysicsModel, given: Map[String, String] = Map.empty): PhysicsModel = {
    val o = jsonObject(text, where)
    o.keys.find(k => !Keys.contains(k)).foreach(k => throw new ExplainError(s"$where: unknown key '$k' (a model file has ${Keys.mkString(", ")})"))
    // (null and an empty list set nothing: a recording's `# model:` line names every key, lines_per_rev null, effects [])
    given.toSeq.sortBy(_._2).find(g => o.get(g._1).exists(v => v != ujson.Null && !v.arrOpt.exists(_.isEmpty))).foreach { case (k, opt) =>
      throw new ExplainError(s"$where sets $k, and $opt was given too; give one of the two (the model file's value or the option)") }
    def n(k: String, dv: Double) = o.get(k).map(x => x.numOpt.getOrElse(throw new ExplainError(s"$where: $k must be a number"))).getOrElse(dv)
    val b = d.base
    val lpr = o.get("lines_per_rev") match {
      case None => d.linesPerRev
      case Some(ujson.Null) => d.linesPerRev // (--lines-per-rev's, if given)
      case Some(x) => Some(x.numOpt.getOrElse(throw new ExplainError(s"$where: lines_per_rev must be a number or null")))
    }
    val v = Map("sample_rate_hz" -> d.sampleRateHz, "samples" -> d.samples.toDouble, "adc_bits" -> d.adc.bits.toDouble,
      "amplitude" -> b.amplitude, "offset_sin" -> b.offsetSin, "offset_cos" -> b.offsetCos, "gain_sin" -> b.gainSin,
      "gain_cos" -> b.gainCos, "phase_error_deg" -> b.phaseErrorDeg, "noise_rms" -> b.noiseRms, "seed" -> b.seed.toDouble)
      .map { case (k, x) => k -> n(k, x) } ++ lpr.map("lines_per_rev" -> _)
    for ((k, max) <- Seq("samples" -> Int.MaxValue.toDouble, "adc_bits" -> 64.0, "seed" -> MaxSeed.toDouble))
      if (!(v(k).isWhole && math.abs(v(k)) <= max)) throw new ExplainError(s"$where: $k must be a whole number (up to ${max.toLong}), got ${v(k)}")
    check(v, identity).foreach(w => throw new ExplainError(s"$where: $w"))
    val base = b.copy(amplitude = v("amplitude"), offsetSin = v("offset_sin"), offsetCos = v("offset_cos"), gainSin = v("gain_sin"),
      gainCos = v("gain_cos"), phaseErrorDeg = v("phase_error_deg"), noiseRms = v("noise_rms"), seed = v("seed").toLong)
    // a value that is no name (5, true) is refused, not passed over for the default format
    val fmt = o.get("adc").filter(_ != ujson.Null).map(x => x.strOpt.getOrElse(throw new ExplainError(s"$where: adc must be a name (offset-binary or twos-complement), got ${x.render()}")))
      .map(s => AdcFormat.parse(s).fold(e => throw new ExplainError(s"$where: $e"), identity)).getOrElse(d.adc.format)
    val effects = effectsFromJson(o, where, d.effects) match { case Nil => d.effects; case es => es } // (an empty list: --effect's)
    try PhysicsModel(base, o.get("motion").map(motionFromJson(_, where)).getOrElse(d.motion), v("sample_rate_hz"), v("samples").toInt,
      Adc(v("adc_bits").toInt, fmt), lpr, effects)
    catch { case e: IllegalArgumentException => throw new ExplainError(s"$where: ${e.getMessage.stripPrefix("requirement failed: ")}") }
  }
}
