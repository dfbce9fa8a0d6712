package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 4: a linear scale read beside an interferometer (`ref_um`, `period_um`) whose contrast is lower
  * over a 1 mm band (contamination): explain reports contrast along the travel, and that finding represents the
  * band (the residual falls to the bench's noise floor and nothing is left unexplained); nothing else is named.
  */
class ContaminationSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  private val fs = 20e3

  private def stage(depth: Double, fromUm: Double, seed: Long, bits: Int = 12) = {
    // 10 mm at 10 mm/s, with the drive's uneven speed; 500 periods of 20 um
    val w = 2 * math.Pi * 3.1
    val tr = Motions.formula(20000, fs)(t => 500 * t + 6 * math.sin(w * t), t => 500 + 6 * w * math.cos(w * t))
    val b = Bench(contrast = LinearStage.band(20, fromUm, fromUm + 1000, depth), noiseLsb = 1.0, bits = bits, seed = seed)
    (LinearStage.text(LinearStage.Spec(tr, fs, b)), b)
  }

  /** (depth, start of the band in um, seed) -> the bench and explain's report. */
  private lazy val runs = Seq((0.08, 4000.0, 41L), (0.05, 2500.0, 42L), (0.12, 7000.0, 43L)).map { case (depth, from, seed) =>
    val (text, b) = stage(depth, from, seed)
    (b, explain(f"contamination ${100 * depth}%.0f %% at ${from / 1000}%.1f mm", text))
  }

  "explain on a linear scale with ref_um" should "report a contamination band (contrast 5-12 % lower over 1 mm) as contrast along the travel, and nothing else" in {
    for ((_, r) <- runs) withClue(line(r)) { effects(r) shouldBe Seq("contrast_along_travel") }
  }

  it should "represent the band: residual at the noise floor, nothing unexplained (needs: smooth contrast along the travel)" in {
    for ((b, r) <- runs) withClue(f"${line(r)}; floor ${b.floorRms}%.4g") {
      effects(r) should contain("contrast_along_travel")
      r.finalRms should be <= 1.05 * b.floorRms
      r.unexplained shouldBe empty
    }
  }
  "explain" should "name a read-head low-pass as a look-alike of a contrast change where the speed follows the position, and not where it does not" in {
    // a low-pass's amplitude falls with speed: on a ramp of speed it looks like a contrast changing along the travel
    val tr = Motions.formula(20000, fs)(t => 300 * t + 400 * t * t, t => 300 + 800 * t)
    val b = Bench(contrast = LinearStage.band(20, 4000, 5000, 0.08), noiseLsb = 1.0, seed = 44)
    val ramp = explain("contamination 8 % at 4.0 mm, speed growing with the position", LinearStage.text(LinearStage.Spec(tr, fs, b)))
    def speedAlike(r: moire.explain.Report) =
      r.findings.filter(_.effect == "contrast_along_travel").flatMap(_.lookAlikes).exists(_.startsWith("bandwidth predicts"))
    withClue(line(ramp)) { effects(ramp) should contain("contrast_along_travel"); speedAlike(ramp) shouldBe true }
    for ((_, r) <- runs) withClue(line(r)) { speedAlike(r) shouldBe false }
  }
}
