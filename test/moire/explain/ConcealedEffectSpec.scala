package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Each effect concealed (smaller than the noise per sample, or behind a larger default-model effect):
  * explain must name it first and recover its parameter within 20 %.
  */
class ConcealedEffectSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def first(r: Report, effect: String): Finding = {
    info(describe(r) + " | unexplained: " + r.unexplained.map(_.where).mkString(", "))
    withClue(describe(r)) { r.findings should not be empty; r.findings.head.effect shouldBe effect }
    // a noise model (jitter) lowers the criterion, not the residual: its rms stays within rounding
    r.findings.head.rmsAfter should be <= r.findings.head.rmsBefore * (1 + 1e-12)
    r.finalRms should be <= r.baselineRms * (1 + 1e-12)
    r.finalBic should be < r.baselineBic - SignalExplain.Threshold
    r.findings.head
  }

  "explain" should "find a channel skew hidden behind a phase error (several speeds in one ramp)" in {
    val f = first(explain(sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), phaseErrorDeg = 2.0)), "channel_skew")
    assert(within(f.params("skew_s"), 30e-9), f.params)
    f.summary should include("after sin")
    // on a ramp time and speed go together: a phase error that changes in time is the skew's look-alike
    f.lookAlikes.exists(_.startsWith("a phase error between the channels that changes in time")) shouldBe true
    // and a low-pass of the sin channel alone lags as much, its amplitude dropping by 0.09 % at 200 kHz
    f.lookAlikes.exists(_.startsWith("bandwidth of the sin channel alone")) shouldBe true
  }

  it should "call a skew at one constant speed a phase error, not a skew" in {
    val r = explain(sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), motion = Motion.Constant(150e3)))
    withClue(describe(r)) { r.findings.map(_.effect) should not contain "channel_skew" }
  }

  it should "find a read-head bandwidth that looks like amplitude drift on a ramp" in {
    val r = explain(sim(Seq(EffectSpec("bandwidth", Map("cutoff_hz" -> 400e3))), motion = Motion.Ramp(20e3, 250e3, 0.01)))
    val f = first(r, "bandwidth")
    r.findings.map(_.effect) should not contain "drift"
    assert(within(f.params("cutoff_hz"), 400e3), f.params)
    f.channel shouldBe "both"
  }

  it should "find a one-channel bandwidth (gain and lag of the cos channel only)" in {
    val f = first(explain(sim(Seq(EffectSpec("bandwidth", Map("cutoff_hz" -> 1.5e6), "cos")))), "bandwidth")
    assert(within(f.params("cutoff_hz"), 1.5e6), f.params)
    f.channel shouldBe "cos"
    // its amplitude drops by 0.88 % at 200 kHz: a skew with cos sampled before sin lags as much and is named
    f.lookAlikes.exists(_.startsWith("channel_skew (the cos channel sampled")) shouldBe true
    f.lookAlikes.head should include("before sin")
  }

  it should "find clock jitter that looks like white noise" in {
    val f = first(explain(sim(Seq(EffectSpec("jitter", Map("jitter_s" -> 300e-12))), motion = Motion.Constant(200e3))), "jitter")
    assert(within(f.params("jitter_s"), 300e-12), f.params)
  }

  it should "find a harmonic smaller than the noise per sample" in {
    val f = first(explain(sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 5e-4), "sin")))), "harmonic")
    f.params("order") shouldBe 3.0
    f.channel shouldBe "sin"
    assert(within(f.params("amplitude_rel"), 5e-4), f.params)
  }

  it should "find offset and gain drift" in {
    val r = explain(sim(Seq(EffectSpec("drift", Map("offset_sin_per_s" -> 0.02, "gain_cos_per_s" -> 0.05))),
      motion = Motion.Ramp(5e3, 40e3, 0.1), fs = 1e6))
    val f = first(r, "drift")
    assert(within(f.params("offset_sin_per_s"), 0.02), f.params)
    assert(within(f.params("gain_cos_per_s"), 0.05), f.params)
  }

  it should "find amplitude modulation with the mechanical angle" in {
    val f = first(explain(sim(Seq(EffectSpec("amplitude_modulation", Map("depth" -> 0.002))), motion = Motion.Constant(100e3),
      linesPerRev = Some(100))), "amplitude_modulation")
    assert(within(f.params("depth"), 0.002), f.params)
  }

  it should "find a stuck ADC data line" in {
    val f = first(explain(sim(Seq(EffectSpec("adc_bit_fault", Map("bit" -> 3, "stuck_at" -> 1), "cos")))), "adc_bit_fault")
    f.channel shouldBe "cos"; f.params("bit") shouldBe 3.0; f.params("stuck_at") shouldBe 1.0
  }

  it should "find two bridged ADC data lines" in {
    val f = first(explain(sim(Seq(EffectSpec("adc_bit_fault", Map("bit" -> 5, "bridged_to" -> 6), "sin")))), "adc_bit_fault")
    f.channel shouldBe "sin"; f.params("bit") shouldBe 5.0; f.params("bridged_to") shouldBe 6.0
  }

  it should "find heavy clipping of both ends on both channels as clipping, not as harmonics of the fringe" in {
    // simulate's 0.9 clipped at +- 0.8 on sin, and another generator's on both channels: the pile-ups' samples censored
    // cost 2 ln(1 / LSB) each against the others' density, and harmonics 3, 5 and 7 were named in their place
    val own = explain(sim(Seq(EffectSpec("clipping", Map("high_fs" -> 0.8, "low_fs" -> -0.8), "sin")), amplitude = 0.9, n = 200000, fs = 5e6))
    val other = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 5e6, motion = "chirp", f0 = 20e3, f1 = 150e3,
      amp = 0.9, clipFs = 0.8, seed = 33)))
    // and with the converter's noise after the saturation: a flat top spread over a few codes, no pile-up at one
    val after = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 5e6, motion = "chirp", f0 = 20e3, f1 = 150e3,
      amp = 0.9, clipFs = 0.8, noiseLsb = 0.3, noiseAfterLsb = 1.0, seed = 34)))
    // and 2 LSB before with 0.5 after: the flat tops scatter by a quarter of the rest's noise (a jitter of 10.8 ns was found)
    val mixed = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 5e6, motion = "chirp", f0 = 20e3, f1 = 150e3,
      amp = 0.9, clipFs = 0.85, noiseLsb = 2.0, noiseAfterLsb = 0.5, seed = 36)))
    for ((name, r, chans) <- Seq(("simulate", own, Seq("sin")), ("another generator", other, Seq("sin", "cos")),
      ("another generator, noise after", after, Seq("sin", "cos")), ("another generator, 2 LSB before and 0.5 after", mixed, Seq("sin", "cos")))) {
      info(s"$name: ${describe(r)}")
      withClue(s"$name: ${describe(r)}") {
        r.findings.map(_.effect).distinct shouldBe Seq("clipping")
        r.findings.map(_.channel).sorted shouldBe chans.sorted
        val level = if (r eq mixed) 0.85 else 0.8
        for (f <- r.findings) { f.params("high_fs") shouldBe level +- 0.001; f.params("low_fs") shouldBe -level +- 0.001 }
        r.misfit shouldBe empty
      }
    }
  }

  it should "find half the samples clipped, and tops clipped for a sample or two a period, as clipping alone" in {
    // another generator's 1.0 clipped at 0.7 on both channels (half the samples): the fit stopped after 12 refits at 10
    // LSB rms and named harmonics 3, 5 and 7; tops clipped by 12 LSB at 28 kHz and 2 MS/s were five "glitches" and INL
    val pile = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 1e6, motion = "chirp", f0 = 1e3, f1 = 20e3,
      amp = 1.0, offS = 0, offC = 0, gainC = 1.0, clipFs = 0.7, seed = 61)))
    val flat = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 1e6, motion = "constant", f0 = 3e3,
      amp = 1.0, offS = 0, offC = 0, gainC = 1.0, clipFs = 0.7, noiseLsb = 0.3, noiseAfterLsb = 1.0, seed = 62)))
    val tops = explain(FringeGenerator.recording(FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "constant", f0 = 28e3,
      amp = 0.8, offS = 0.006, offC = -0.004, clipFs = 0.8, noiseLsb = 0.3, noiseAfterLsb = 1.0, seed = 63)))
    for ((name, r, level) <- Seq(("half, pile-up", pile, 0.7), ("half, noise after", flat, 0.7), ("tops at 28 kHz", tops, 0.8))) {
      info(s"$name: ${describe(r)}")
      withClue(s"$name: ${describe(r)}; misfit ${r.misfit.map(_.summary)}") {
        r.findings should not be empty
        r.findings.map(_.effect).distinct shouldBe Seq("clipping")
        for (f <- r.findings; k <- Seq("high_fs", "low_fs") if f.params.contains(k)) math.abs(f.params(k)) shouldBe level +- 0.001
        r.misfit shouldBe empty
        r.notes.exists(_.contains("isolated sample")) shouldBe false
      }
    }
  }

  it should "find amplifier clipping below the ADC range" in {
    val f = first(explain(sim(Seq(EffectSpec("clipping", Map("high_fs" -> 0.8), "sin")))), "clipping")
    f.channel shouldBe "sin"
    f.params("high_fs") shouldBe 0.8 +- 0.002
  }

  it should "find ADC integral nonlinearity (not two harmonics)" in {
    val f = first(explain(sim(Seq(EffectSpec("adc_nonlinearity", Map("inl2_lsb" -> 2.0, "inl3_lsb" -> 1.5))))), "adc_nonlinearity")
    assert(within(f.params("inl2_lsb"), 2.0) && within(f.params("inl3_lsb"), 1.5), f.params)
    // one curve on both ADCs: the amplifiers before them are its look-alike
    f.lookAlikes.exists(_.startsWith("a curve of the read head's amplifiers before both ADCs")) shouldBe true
  }

  it should "find capacitive crosstalk (amplitude changing with speed)" in {
    val f = first(explain(sim(Seq(EffectSpec("crosstalk", Map("sin_from_cos_tau_s" -> 2e-9))))), "crosstalk")
    assert(within(f.params("sin_from_cos_tau_s"), 2e-9), f.params)
  }

  it should "find a line at a multiple of the sample rate over its search stride (no aliasing to DC), on both halves" in {
    // 400,000 samples at 10 MS/s: the line search takes one sample in 8 (the halves one in 4), and 1.25 MHz is fs / 8
    val r = explain(sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 1.25e6, "amplitude_fs" -> 2 * lsb12))), n = 400000,
      motion = Motion.Ramp(20e3, 200e3, 0.04)))
    withClue(describe(r) + " / " + r.unexplained.map(_.summary).mkString("; ")) {
      val f = first(r, "interference")
      f.params("frequency_hz") shouldBe (1.25e6 +- 1.0)
    }
  }

  it should "find interference below the noise" in {
    val f = first(explain(sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 12345.0, "amplitude_fs" -> 0.6 * lsb12))))), "interference")
    f.params("frequency_hz") shouldBe 12345.0 +- 50
    assert(within(f.params("amplitude_fs"), 0.6 * lsb12), f.params)
  }

  it should "separate two effects in one recording" in {
    val r = explain(sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 20e-9)),
      EffectSpec("harmonic", Map("order" -> 2, "amplitude_rel" -> 1e-3), "cos"))))
    withClue(describe(r)) { r.findings.map(_.effect).toSet shouldBe Set("channel_skew", "harmonic") }
    assert(within(r.findings.find(_.effect == "channel_skew").get.params("skew_s"), 20e-9))
  }
}
