package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Intensity noise of the light source from the independent generator: found with its size, and not taken for phase
  * noise; phase noise not taken for it.
  */
class IntensityNoiseSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.describe

  private def run(s: FringeGenerator.Spec): Report = {
    val r = SignalExplain.run("light", FringeGenerator.recording(s), Nil, Progress.none).report
    println(s"intensity ${s.intensityRel}: findings [${describe(r)}]; unexplained [${r.unexplained.map(_.where).mkString("; ")}]")
    r
  }

  private val ramp = FringeGenerator.Spec(n = 300000, fs = 2e6, motion = "chirp", f0 = 5e3, f1 = 40e3, noiseLsb = 1.0)

  "explain" should "find the light source's intensity noise with its size" in {
    // 0.1 % of the amplitude rms: 1.6 LSB at the fringe's peaks beside 1 LSB of white noise
    val r = run(ramp.copy(intensityRel = 0.001))
    r.findings.map(_.effect) shouldBe Seq("intensity_noise")
    val f = r.findings.head
    println(f"intensity noise ${f.params("intensity_noise_rel")}%.6f +- ${f.unc("intensity_noise_rel")}%.1e (true 0.001)")
    f.params("intensity_noise_rel") shouldBe 0.001 +- math.max(3 * f.unc("intensity_noise_rel"), 2e-5)
  }

  it should "not take a slow modulation of the amplitudes for white intensity noise" in {
    // the same 0.15 % rms, correlated over some 200 samples (an AR(1) of 0.995 a sample): amplitude changes the model does
    // not follow. Before the whiteness test, a numpy record of 2 kHz band-limited noise came out as 0.137 % of
    // intensity noise and a contrast "band over 0.000 periods"
    val r = run(ramp.copy(intensityRel = 0.0015, intensityRho = 0.995))
    r.findings.map(_.effect) should not contain "intensity_noise"
    r.unexplained.exists(u => u.where.startsWith("intensity_noise") && u.summary.contains("still correlate")) shouldBe true
  }

  it should "name nothing on the same record without it" in {
    run(ramp).findings shouldBe empty
  }
}
