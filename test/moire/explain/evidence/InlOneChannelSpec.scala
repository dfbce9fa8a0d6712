package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 5: a bowed transfer curve (INL) on the cos converter only. Where the signal's amplitude
  * changes (beam walk along the travel) the bow stays fixed in LSB while a harmonic would scale, so explain can
  * and must say INL on the cos channel; at constant amplitude a one-channel bow is exactly a 2nd harmonic on that
  * channel, and the finding must name the alternative.
  */
class InlOneChannelSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  private val fs = 200e3

  private def bowed(bowLsb: Double, contrastEnd: Double, seed: Long): String = {
    val tr = Motions.chirp(60000, fs, 1.5e3, 3e3)
    val b = Bench(inlCosLsb = bowLsb, contrast = p => 1 + (contrastEnd - 1) * p / tr.periods.last, noiseLsb = 0.8, seed = seed)
    LinearStage.text(LinearStage.Spec(tr, fs, b))
  }

  "explain" should "report INL on the cos channel only when the amplitude changes along the travel (needs: INL per channel)" in {
    for ((bow, seed) <- Seq((4.0, 51L), (-3.0, 52L))) {
      val r = explain(f"cos bow $bow%.1f LSB, contrast 1 -> 0.7", bowed(bow, 0.7, seed))
      withClue(line(r)) {
        val inl = r.findings.filter(_.effect == "adc_nonlinearity")
        inl.map(_.channel) shouldBe Seq("cos")
        effects(r).filterNot(Set("adc_nonlinearity", "contrast_along_travel")) shouldBe empty
        // INL = bow (1 - u^2) = bow / 2 - bow / 2 T2(u)
        inl.head.params("inl2_lsb") shouldBe (-bow / 2 +- 0.2 * math.abs(bow) / 2)
      }
    }
  }

  it should "report a one-channel bow at constant amplitude on the cos channel only" in {
    val r = explain("cos bow 4 LSB, constant amplitude", bowed(4.0, 1.0, 53))
    withClue(line(r)) {
      r.findings should not be empty
      r.findings.map(_.channel).distinct shouldBe Seq("cos")
      effects(r).toSet should (be(Set("adc_nonlinearity")) or be(Set("harmonic")))
    }
  }

  it should "name the look-alike (INL or 2nd harmonic) at constant amplitude (needs: look-alikes)" in {
    val r = explain("cos bow 4 LSB, constant amplitude", bowed(4.0, 1.0, 53))
    withClue(line(r) + " | " + r.findings.map(_.summary).mkString("; ")) {
      r.findings should not be empty
      val f = r.findings.head
      if (f.effect == "harmonic") namesLookAlike(f, "adc_nonlinearity") shouldBe true
      else namesLookAlike(f, "harmonic") shouldBe true
    }
  }
}
