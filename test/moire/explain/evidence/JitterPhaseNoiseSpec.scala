package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 6: 2 ns sampling-clock jitter at 50 MS/s (10 % of the sample period), and separately phase
  * noise of the motion (vibration faster than the trajectory: a fixed rms in fringe phase). Both add noise that
  * grows with the signal's slope; jitter's grows with speed, the vibration's does not, so on a speed ramp they are
  * told apart; at one constant speed the record cannot tell, and both must be named.
  */
class JitterPhaseNoiseSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  private val fs = 50e6
  private val n = 200000
  private def ramp = Motions.chirp(n, fs, 50e3, 250e3)

  private lazy val jitter = explain("jitter 2 ns, ramp 50-250 kHz", Interferometer.text(ramp, fs, Bench(jitterS = 2e-9, seed = 61)))
  private lazy val vibration = explain("phase noise 0.12 deg rms, ramp 50-250 kHz",
    Interferometer.text(ramp, fs, Bench(phaseNoiseDeg = 0.12, phaseNoiseTauS = 0.1e-6, seed = 62)))

  "explain on a speed ramp" should "report 2 ns jitter (10 % of the sample period), within 20 %, and nothing else" in {
    withClue(line(jitter)) {
      effects(jitter) shouldBe Seq("jitter")
      jitter.findings.head.params("jitter_s") shouldBe 2e-9 +- 0.4e-9
    }
  }

  it should "report 150 ps of jitter at 10 MS/s, near the white noise: its noise departure measured against the model's noise" in {
    // the noise against speed was measured against the white noise alone, so a jitter in the model could not lower it
    // and a true jitter was refused ("does not lower the located departure it claims")
    val r = explain("jitter 150 ps, 10 MS/s, ramp 20-250 kHz", Interferometer.text(Motions.chirp(150000, 10e6, 20e3, 250e3), 10e6,
      Bench(jitterS = 150e-12, noiseLsb = 1.0, seed = 87)))
    withClue(line(r)) {
      effects(r) shouldBe Seq("jitter")
      r.findings.head.params("jitter_s") shouldBe 150e-12 +- 30e-12
    }
  }

  it should "not call phase noise of the motion jitter" in {
    withClue(line(vibration)) { effects(vibration) should not contain "jitter" }
  }

  it should "report phase noise of the motion as such (needs: phase noise of the motion)" in {
    withClue(line(vibration)) {
      effects(vibration).filter(isPhaseNoise) should have size 1
      effects(vibration).filterNot(isPhaseNoise) shouldBe empty
    }
  }

  "explain at one constant speed" should "name jitter and phase noise of the motion as look-alikes (needs: look-alikes)" in {
    val r = explain("jitter 2 ns at constant 200 kHz", Interferometer.text(Motions.constant(n, fs, 200e3), fs, Bench(jitterS = 2e-9, seed = 63)))
    withClue(line(r) + " | " + r.findings.map(_.summary).mkString("; ")) {
      r.findings should not be empty
      r.findings.exists(f => (f.effect == "jitter" && namesLookAlike(f, "phase noise")) || (isPhaseNoise(f.effect) && namesLookAlike(f, "jitter"))) shouldBe true
    }
  }
}
