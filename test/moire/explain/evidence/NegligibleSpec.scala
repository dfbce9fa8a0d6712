package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 3: structure of no physical size beside a real effect, in long records where a BIC drop of
  * 10 is easy: only the real effect is a finding; what is significant but below the materiality floor is listed
  * as too small to matter, with its size.
  */
class NegligibleSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  private val fs = 10e6
  private def ramp(n: Int) = Motions.chirp(n, fs, 20e3, 250e3)

  /** A contrast change of -0.005 % over the whole travel (0.08 LSB), as in the issue (there in 10^6 samples). */
  private lazy val contrast = {
    val tr = ramp(250000); val travel = tr.periods.last
    explain("cut-off 350 kHz + contrast -0.005 %", Interferometer.text(tr, fs, Bench(cutoffHz = 350e3, contrast = p => 1 - 5e-5 * p / travel, noiseLsb = 1.5, seed = 31)))
  }
  private lazy val crosstalk =
    explain("cut-off 350 kHz + crosstalk 0.7 ps", Interferometer.text(ramp(250000), fs, Bench(cutoffHz = 350e3, crosstalkTauS = 0.7e-12, noiseLsb = 1.5, seed = 32)))
  private lazy val bit = {
    val f = 50e6
    explain("stuck bit 3 + 0.1 LSB at 21 MHz", Interferometer.text(Motions.chirp(100000, f, 100e3, 400e3), f,
      Bench(stuck = Some(("sin", 3, 0)), lines = Seq(21e6 -> 0.1), noiseLsb = 1.0, seed = 33)))
  }
  private lazy val hum = {
    val f = 100e3
    explain("hum 6 LSB + warm-up 1.5 LSB", Interferometer.text(Motions.chirp(100000, f, 2e3, 5e3), f,
      Bench(lines = Seq(50.0 -> 6.0), warmOffsetLsb = 1.5, warmGainRel = 3e-4, warmTauS = 0.08, noiseLsb = 1.0, seed = 34)))
  }

  "explain beside a 350 kHz read-head cut-off" should "report only the cut-off when the contrast changes by -0.005 % along the travel" in {
    withClue(line(contrast)) {
      effects(contrast) shouldBe Seq("bandwidth")
      contrast.findings.head.params("cutoff_hz") shouldBe 350e3 +- 35e3
    }
  }

  it should "report only the cut-off beside 0.7 ps of capacitive crosstalk" in {
    withClue(line(crosstalk)) {
      effects(crosstalk) shouldBe Seq("bandwidth")
      crosstalk.findings.head.params("cutoff_hz") shouldBe 350e3 +- 35e3
    }
  }

  "explain beside a stuck ADC bit" should "report only the bit, not a 0.1 LSB line at 21 MHz" in {
    withClue(line(bit)) {
      effects(bit) shouldBe Seq("adc_bit_fault")
      bit.findings.head.channel shouldBe "sin"
      bit.findings.head.params("bit") shouldBe 3.0
    }
  }

  // A planted warm-up of 1.5 LSB (1 LSB noise) is real and above the materiality floor: it is reported beside the hum.
  // (The warm-ups of 1-2 LSB were not in the signal: they absorbed part of a badly fitted hum.)
  "explain beside mains hum" should "report the hum and a real 1.5 LSB warm-up at its size" in {
    withClue(line(hum)) {
      effects(hum).sorted shouldBe Seq("interference", "warmup")
      hum.findings.find(_.effect == "interference").get.params("frequency_hz") shouldBe 50.0 +- 0.5
      val w = hum.findings.find(_.effect == "warmup").get
      for (ch <- Seq("sin", "cos")) w.params(s"offset_${ch}_step_fs") * 2048 shouldBe 1.5 +- 0.3
    }
  }

  "explain" should "list the significant 0.1 LSB line beside a stuck bit as too small to matter, with its size" in {
    withClue(line(bit) + " | " + bit.notes.mkString("; ")) { negligible(bit).exists(n => n.contains("21") && n.contains("LSB")) shouldBe true }
  }
}
