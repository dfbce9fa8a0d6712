package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The oscilloscope capture of issue 12, rebuilt by the independent generator: 8 bit, 2 MS/s, 0.1 s, uneven motion
  * with reversals, contrast and offset changing along the travel, no effect in time: explain must tell no story
  * of jitter, pickup or drift.
  */
class ScopeLikeSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.describe

  private def scope(seed: Long, wobble: Double, noise: Double) = FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "uneven", f0 = 20e3,
    wobble = wobble, bits = 8, noiseLsb = noise, amp = 0.85, contrastPerPeriod = -1e-4, offsetPerPeriod = 3e-6, seed = seed)

  "explain on a scope-like 8-bit capture" should "report no jitter, no pickup and no drift" in {
    for ((seed, wobble, noise) <- Seq((1L, 0.6, 0.4))) {
      val r = SignalExplain.run("scope", FringeGenerator.recording(scope(seed, wobble, noise)), Nil, Progress.none).report
      println(s"scope-like seed $seed wobble $wobble noise $noise LSB: findings [${describe(r)}]; unexplained [${r.unexplained.map(u => u.where + ": " + u.summary).mkString("; ")}] (${"%.1f".format(r.seconds)} s)")
      r.findings.map(_.effect) should contain noneOf ("jitter", "interference", "drift", "warmup")
    }
  }

  it should "report 8-bit codes in a 12-bit format as coarse quantization, not as four stuck data lines" in {
    val s = scope(3, 1.4, 0.3).copy(n = 20000, formatBits = 12)
    val r = SignalExplain.run("scope12", FringeGenerator.recording(s), Nil, Progress.none).report
    println(s"8-bit codes in 12-bit words: findings [${describe(r)}]; unexplained [${r.unexplained.map(_.where).mkString("; ")}]")
    r.findings.map(_.effect) should contain("coarse_quantization")
    r.findings.map(_.effect) should not contain "adc_bit_fault"
    r.findings.find(_.effect == "coarse_quantization").get.params("effective_bits") shouldBe 8.0
    r.unexplained.map(_.where).filter(_.startsWith("code histogram")) shouldBe empty
  }
}
