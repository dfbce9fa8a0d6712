package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A standstill shaken at 2 kHz and 370 Hz over 1.2 fringe periods, sampled at 1 MS/s (another generator's record):
  * the blocks' path undercounted its speed, every segment length tried was far off, and the fit collapsed to 743 LSB
  * rms with amplitudes of 0.04 full scale and a phase error of 70 degree, reported without error. Where every length is
  * far off, shorter ones are tried down to the trajectory's least.
  */
class VibrationSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "follow a standstill shaken faster than its longest segments, with no finding" in {
    val rec = FringeGenerator.recording(FringeGenerator.Spec(n = 300000, fs = 1e6, motion = "vibration", travel = 1.5, rateHz = 2000,
      noiseLsb = 1.7, seed = 8))
    val r = explain(rec)
    withClue(s"${describe(r)}; misfit ${r.misfit.map(_.summary)}; baseline ${r.baseline}") {
      r.findings shouldBe empty
      r.misfit shouldBe empty
      r.finalRms should be < 2.0 * lsb12
      r.baseline("amplitude_sin_fs") shouldBe 0.8 +- 0.01
    }
  }
}
