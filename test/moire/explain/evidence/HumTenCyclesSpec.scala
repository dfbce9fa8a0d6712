package moire.explain.evidence

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Prove it 7: mains hum that completes exactly 10 cycles in the record is reported (10.0 +- 0.01 cycles
  * is not "fewer than 10"), with its frequency and size.
  */
class HumTenCyclesSpec extends AnyFlatSpec with Matchers {
  import Evidence._

  "explain" should "report mains hum completing exactly 10 cycles in the record" in {
    for ((hz, fs, hum, seed) <- Seq((50.0, 100e3, 4.0, 71L), (50.0, 50e3, 6.0, 72L), (60.0, 60e3, 4.0, 73L))) {
      val n = (10 * fs / hz).round.toInt
      val r = explain(f"hum $hz%.0f Hz $hum%.0f LSB, $n samples = 10 cycles", Interferometer.text(Motions.chirp(n, fs, 2e3, 5e3), fs,
        Bench(lines = Seq(hz -> hum), noiseLsb = 1.0, seed = seed)))
      withClue(line(r) + " | " + r.unexplained.map(_.summary).mkString("; ")) {
        effects(r) shouldBe Seq("interference")
        val p = r.findings.head.params
        p("frequency_hz") shouldBe hz +- 0.5
        p("amplitude_fs") shouldBe hum / 2048 +- 0.15 * hum / 2048
      }
    }
  }
}
