package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A pickup line's frequency within its stated uncertainty on records long enough that the line is searched on a
  * subsample (the independent fringe generator: mains hum common to both channels, 14 bit, a scan whose speed swells
  * from 0.5 to 6 kHz and falls back).
  */
class LineFrequencySpec extends AnyFlatSpec with Matchers {
  "explain" should "state a pickup line's frequency within its uncertainty, on the record's samples, not the subsample's" in {
    val z = Seq(1L, 2L, 3L, 4L).map { seed =>
      val s = FringeGenerator.Spec(n = 400000, fs = 200e3, motion = "swell", f0 = 500, f1 = 6e3, bits = 14, noiseLsb = 2.0,
        humFs = 3e-4, humHz = 60.0, seed = seed)
      val r = SignalExplain.run("hum", FringeGenerator.recording(s), Nil, Progress.none).report
      val f = r.findings.find(_.effect == "interference").getOrElse(fail(s"no pickup found: ${ExplainSupport.describe(r)}"))
      val (hz, sd) = (f.params("frequency_hz"), f.unc("frequency_hz"))
      println(f"seed $seed: pickup at $hz%.6f +- $sd%.6f Hz (true 60): ${(hz - 60) / sd}%+.2f sd")
      (hz - 60) / sd
    }
    z.foreach(x => math.abs(x) should be < 4.0)
    math.sqrt(z.map(x => x * x).sum / z.size) should be < 2.5
  }
}
