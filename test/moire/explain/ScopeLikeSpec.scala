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
    for ((seed, wobble, noise) <- Seq((1L, 0.6, 0.4), (2L, 1.4, 0.3))) {
      val r = SignalExplain.run("scope", FringeGenerator.recording(scope(seed, wobble, noise)), Nil, Progress.none).report
      println(s"scope-like seed $seed wobble $wobble noise $noise LSB: findings [${describe(r)}]; unexplained [${r.unexplained.map(u => u.where + ": " + u.summary).mkString("; ")}] (${"%.1f".format(r.seconds)} s)")
      r.findings.map(_.effect) should contain noneOf ("jitter", "interference", "drift", "warmup")
    }
  }
}
