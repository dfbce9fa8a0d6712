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

  // A 2 kHz shake of 2 fringe periods at 1 MS/s turns within 250 samples: 94-sample cubics (a period at its typical
  // speed) left 4 x the noise floor in every window, "no effect assessed"; 56-sample ones a misfit of 1.5 x along the
  // path that five pickup lines took up. Shorter segments, down to 16 samples, where the motion turns within a few.
  it should "follow a fast shake with segments shorter than 64 samples, and find nothing in it" in {
    for (seed <- Seq(21L, 22L)) {
      val r = explainAll("shake", FringeGenerator.Spec(n = 300000, fs = 1e6, motion = "reverse", travel = 2, rateHz = 2000, noiseLsb = 1.0, seed = seed))
      withClue(s"seed $seed: ${clue(r)}: ") {
        (r.findings, r.unexplained, r.misfit) shouldBe ((Nil, Nil, Nil))
        r.finalRms should be < 1.15 * lsb12
        r.baseline("trajectory_segments") should be > 300000.0 / 64
      }
    }
  }
}
