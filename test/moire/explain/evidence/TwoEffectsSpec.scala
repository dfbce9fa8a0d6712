package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 8: two effects at once, each reported with its parameter within 20 %, nothing else. */
class TwoEffectsSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  private def param(r: moire.explain.Report, effect: String, key: String): Double =
    r.findings.find(_.effect == effect).map(_.params(key)).getOrElse(Double.NaN)

  "explain" should "report a 3rd harmonic on sin and a 20 kHz switching-supply line together" in {
    val fs = 10e6
    val b = Bench(harmonics = Seq(Harmonic(3, 1e-3, channel = "sin")), lines = Seq(20e3 -> 2.0), noiseLsb = 1.2, seed = 81)
    val r = explain("3rd harmonic 0.1 % + 2 LSB at 20 kHz", Interferometer.text(Motions.chirp(150000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("harmonic", "interference")
      param(r, "harmonic", "order") shouldBe 3.0
      param(r, "harmonic", "amplitude_rel") shouldBe 1e-3 +- 2e-4
      param(r, "interference", "frequency_hz") shouldBe 20e3 +- 20.0
      param(r, "interference", "amplitude_fs") shouldBe 2.0 / 2048 +- 0.4 / 2048
    }
  }

  it should "report a 500 kHz read-head cut-off and a stuck bit on sin together" in {
    val fs = 10e6
    val b = Bench(cutoffHz = 500e3, stuck = Some(("sin", 1, 0)), noiseLsb = 1.2, seed = 84)
    val r = explain("cut-off 500 kHz + sin bit 1 stuck at 0", Interferometer.text(Motions.chirp(150000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("bandwidth", "adc_bit_fault")
      param(r, "bandwidth", "cutoff_hz") shouldBe 500e3 +- 100e3
      param(r, "adc_bit_fault", "bit") shouldBe 1.0
      r.findings.find(_.effect == "adc_bit_fault").get.channel shouldBe "sin"
    }
  }

  it should "report a read-head cut-off on sin alone and a channel skew together, the delay shared as it is" in {
    // a one-channel low-pass delays that channel as a skew does: the first one found took the other's share of the
    // delay (638 kHz and 2 ns), and the amplitude left over was called a contrast along the travel
    val fs = 10e6
    val b = Bench(cutoffHz = 700e3, cutoffChannel = "sin", rampFilter = true, skewS = 20e-9, noiseLsb = 1.0, seed = 85)
    val r = explain("sin cut-off 700 kHz + cos 20 ns late", Interferometer.text(Motions.chirp(150000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("bandwidth", "channel_skew")
      r.findings.find(_.effect == "bandwidth").get.channel shouldBe "sin"
      // within 20 % as the others: the generator's filter sees the signal linear between samples, 0.13 % less
      // amplitude at 200 kHz than the analog low-pass, which the fit takes as a cut-off 2 % lower (688 kHz) whose
      // longer delay takes 3.5 ns of the skew
      param(r, "bandwidth", "cutoff_hz") shouldBe 700e3 +- 140e3
      param(r, "channel_skew", "skew_s") shouldBe 20e-9 +- 4e-9
    }
  }

  it should "report a read-head cut-off on each channel, each its own" in {
    // the two amplifiers' cut-offs differ by 25 %: the common low-pass alone fits less than other shapes. Before, a
    // contrast along the travel, a skew of -46 ns and crosstalk; `simulate`'s record of the same: crosstalk, a cos
    // cut-off at 3.8 MHz and a contrast
    // at 50 MS/s: the generator's filters, digital, differ from the analog ones by 0.002 of a sample in delay and
    // 0.005 % in amplitude (at 10 MS/s by 1 ns and 0.13 %, which were fitted as a skew or crosstalk of 3 LSB)
    val fs = 50e6
    val b = Bench(cutoffHz = 750e3, cutoffChannel = "sin", cosCutoffHz = 600e3, rampFilter = true, noiseLsb = 1.0, seed = 86)
    val r = explain("sin cut-off 750 kHz, cos 600 kHz", Interferometer.text(Motions.chirp(150000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      r.findings.map(f => (f.effect, f.channel)).toSet shouldBe Set(("bandwidth", "sin"), ("bandwidth", "cos"))
      def cut(ch: String) = r.findings.find(_.channel == ch).get.params("cutoff_hz")
      cut("sin") shouldBe 750e3 +- 150e3
      cut("cos") shouldBe 600e3 +- 120e3
    }
  }

  it should "report crosstalk onto a channel behind its own low-pass, the cut-off searched again with it" in {
    // cos += 5 ns x d(sin)/dt ahead of the cos amplifier's 800 kHz low-pass: the low-pass found first took the amplitude's
    // change with speed that the crosstalk makes (a lower cut-off), and a skew then took the lag that came with it
    val fs = 50e6
    val b = Bench(cutoffHz = 800e3, cutoffChannel = "cos", crosstalkTauS = 5e-9, rampFilter = true, noiseLsb = 1.0, seed = 87)
    val r = explain("cos cut-off 800 kHz, 5 ns crosstalk onto cos", Interferometer.text(Motions.chirp(150000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      r.findings.map(f => (f.effect, f.channel)).toSet shouldBe Set(("bandwidth", "cos"), ("crosstalk", "both"))
      param(r, "bandwidth", "cutoff_hz") shouldBe 800e3 +- 160e3
      // the bench couples the unamplified sin (gain 1) into cos (gain 1.012): the fit's tau is per the fitted amplitudes
      param(r, "crosstalk", "cos_from_sin_tau_s") shouldBe 5e-9 +- 1e-9
    }
  }

  it should "report a stuck bit and mains hum together" in {
    val fs = 100e3
    val b = Bench(stuck = Some(("cos", 2, 1)), lines = Seq(50.0 -> 5.0), noiseLsb = 1.0, seed = 82)
    val r = explain("cos bit 2 stuck at 1 + hum 5 LSB", Interferometer.text(Motions.chirp(60000, fs, 2e3, 6e3), fs, b))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("adc_bit_fault", "interference")
      r.findings.find(_.effect == "adc_bit_fault").get.channel shouldBe "cos"
      param(r, "adc_bit_fault", "bit") shouldBe 2.0
      param(r, "interference", "frequency_hz") shouldBe 50.0 +- 0.5
      param(r, "interference", "amplitude_fs") shouldBe 5.0 / 2048 +- 1.0 / 2048
    }
  }

  it should "report a contamination band and a 3rd harmonic of a linear scale with ref_um together" in {
    val fs = 20e3
    val w = 2 * math.Pi * 2.3
    val tr = Motions.formula(20000, fs)(t => 500 * t + 5 * math.sin(w * t), t => 500 + 5 * w * math.cos(w * t))
    val b = Bench(contrast = LinearStage.band(20, 3000, 4000, 0.08), harmonics = Seq(Harmonic(3, 3e-3)), noiseLsb = 1.0, seed = 83)
    val r = explain("contamination 8 % + 3rd harmonic 0.3 %", LinearStage.text(LinearStage.Spec(tr, fs, b)))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("contrast_along_travel", "harmonic")
      param(r, "harmonic", "order") shouldBe 3.0
      param(r, "harmonic", "amplitude_rel") shouldBe 3e-3 +- 6e-4
    }
  }
}
