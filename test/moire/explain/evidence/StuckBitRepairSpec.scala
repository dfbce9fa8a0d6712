package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A stuck low bit whose two preimages lie less than two noise sd apart: the small effect fitted beside it comes out
  * unbiased. Undoing the fault with the preimage closest to the prediction pulled the data toward the prediction and
  * the fit to a fixed point short of the truth (this line on cos came out 1.8 % low, 4.3 of its sd); the repair now
  * weighs the preimages by their likelihood (an EM step of the mixture), and the sd counts the information lost.
  */
class StuckBitRepairSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  "explain" should "fit a 0.6 LSB pickup line beside a stuck bit 1 without pulling it toward the prediction" in {
    val fs = 10e6; val lineLsb = 0.6
    val b = Bench(stuck = Some(("cos", 1, 0)), lines = Seq(50e3 -> lineLsb), noiseLsb = 1.2, seed = 11)
    val r = explain("cos bit 1 stuck at 0 + 0.6 LSB at 50 kHz", Interferometer.text(Motions.chirp(400000, fs, 20e3, 250e3), fs, b))
    withClue(line(r)) {
      effects(r).toSet shouldBe Set("adc_bit_fault", "interference")
      val f = r.findings.find(_.effect == "interference").get
      val truth = lineLsb / 2048
      for (ch <- Seq("cos", "sin")) {
        val (a, sd) = (f.params(s"amplitude_${ch}_fs"), f.unc(s"amplitude_${ch}_fs"))
        sd should be < 0.008 * truth // fine enough to tell the old repair's bias
        a shouldBe truth +- 3 * sd
      }
      // the repaired channel's estimate is less certain than the other's: the fault took part of its information
      f.unc("amplitude_cos_fs") should be > 1.2 * f.unc("amplitude_sin_fs")
    }
  }
}
