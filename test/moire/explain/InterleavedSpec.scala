package moire.explain

import moire.recording.Recording
import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A long record searched on every d-th sample and fitted again on the other interleaved subsamples (`Interleaved`)
  * gives the report of all samples searched: the same findings, each parameter within its stated uncertainty. Where the
  * subsamples disagree (a line above their Nyquist frequency, seen at its alias) all samples are searched. Records of
  * 400,000 samples searched on 100,000 stand in for 20 M searched on 2 M.
  */
class InterleavedSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private def run(rec: Recording, searchSamples: Int) = SignalExplain.run("interleaved", rec, Nil, Progress.none, searchSamples = searchSamples).report
  private def interleavedNote(r: Report) = r.notes.find(_.startsWith("searched on every"))

  "the interleaved search" should "give all samples' findings and parameters on the bench's five effects" in {
    val rec = sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 20e-9)), EffectSpec("bandwidth", Map("cutoff_hz" -> 600e3), "both"),
      EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 1e-3), "sin"), EffectSpec("adc_bit_fault", Map("bit" -> 2, "stuck_at" -> 0), "cos"),
      EffectSpec("interference", Map("frequency_hz" -> 50e3, "amplitude_fs" -> 3e-4))),
      motion = Motion.Ramp(20e3, 250e3, 0.04), n = 400000)
    Interleaved.factor(rec, 100000) shouldBe 4
    val fast = run(rec, 100000); val all = run(rec, Int.MaxValue)
    withClue(s"interleaved: ${describe(fast)}\nall samples: ${describe(all)}\n") {
      interleavedNote(fast) shouldBe defined
      interleavedNote(all) shouldBe empty
      fast.samples shouldBe 400000
      fast.findings.map(f => (f.effect, f.channel)).sorted shouldBe all.findings.map(f => (f.effect, f.channel)).sorted
      fast.findings should have size 5
      for (f <- fast.findings; r = all.findings.find(g => g.effect == f.effect && g.channel == f.channel).get; (k, v) <- r.params) {
        val u = math.max(f.unc.getOrElse(k, 0.0), r.unc.getOrElse(k, 0.0))
        withClue(s"${f.effect} $k: interleaved ${f.params(k)} +- ${f.unc.get(k)}, all samples $v +- ${r.unc.get(k)}: ") {
          math.abs(f.params(k) - v) should be <= 2 * u + 1e-9 * math.abs(v)
        }
      }
      fast.finalRms shouldBe all.finalRms +- 0.01 * all.finalRms
    }
  }

  it should "search all samples when a line above the subsamples' Nyquist frequency shows at its alias" in {
    // 2 MHz at 10 MS/s; every 4th sample is 2.5 MS/s, where it shows at 500 kHz
    val rec = sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 2e6, "amplitude_fs" -> 1e-3))),
      motion = Motion.Ramp(20e3, 50e3, 0.04), n = 400000)
    Interleaved.factor(rec, 100000) shouldBe 4
    val r = run(rec, 100000)
    withClue(s"${describe(r)}; notes ${r.notes}") {
      r.notes.exists(n => n.startsWith("explained on all 400000 samples") && n.contains("alias")) shouldBe true
      r.findings.map(_.effect) shouldBe Seq("interference")
      r.findings.head.params("frequency_hz") shouldBe 2e6 +- 1.0
    }
  }

  it should "name glitches by the whole record's rows, found on every subsample" in {
    val rec = sim(Nil, n = 400000)
    val rows = Seq(12346, 150003, 277780, 390001) // data rows from 1: indices 12345, 150002, ... (each subsample's own)
    rows.foreach(r => rec.sin(r - 1) = 0)
    val r = run(rec, 100000)
    withClue(s"${describe(r)}; notes ${r.notes}") {
      r.findings shouldBe empty
      interleavedNote(r) shouldBe defined
      r.notes.find(_.contains("isolated sample")).getOrElse(fail("no glitch note")) should startWith(s"4 isolated samples (data rows ${rows.mkString(", ")}) ")
    }
  }

  it should "search all samples when the motion takes the subsample's shortest trajectory segments" in {
    // VibrationSpec's shake at 2 kHz, 1 MS/s: on every 2nd sample the 64-sample segments last 128 us and left twice the
    // noise floor in the residual
    val rec = FringeGenerator.recording(FringeGenerator.Spec(n = 300000, fs = 1e6, motion = "vibration", travel = 1.5, rateHz = 2000,
      noiseLsb = 1.7, seed = 8))
    Interleaved.factor(rec, 150000) shouldBe 2
    val r = run(rec, 150000)
    withClue(s"${describe(r)}; notes ${r.notes}") {
      r.notes.exists(n => n.startsWith("explained on all 300000 samples") && n.contains("shortest trajectory segments")) shouldBe true
      r.findings shouldBe empty
      r.finalRms should be < 2.0 * lsb12
    }
  }

  it should "search all samples when the model does not follow another subsample" in {
    // every other sample of a stretch 60 LSB high on sin (two converters interleaved, one off): subsample 0 is clean
    val rec = sim(Nil, motion = Motion.Ramp(20e3, 50e3, 0.04), n = 400000)
    for (i <- 100001 until 160000 by 2) rec.sin(i) += 60
    val r = run(rec, 200000)
    withClue(s"${describe(r)}; notes ${r.notes}") {
      r.notes.find(_.startsWith("explained on all 400000 samples")).getOrElse(fail("searched on a subsample")) should
        include("does not follow subsample 1 in")
    }
  }

  it should "not go back to all samples for a parameter that describes each subsample (a contrast change's travel)" in {
    // travel_periods is each subsample's own travel, a sample apart: 10999.929, .947, .965, .983 sent 1 M records back
    val rec = sim(Seq(EffectSpec("contrast_along_travel", Map("gain_sin_per_period" -> 2e-6, "gain_cos_per_period" -> 2e-6))),
      motion = Motion.Ramp(20e3, 50e3, 0.04), n = 400000)
    val r = run(rec, 100000)
    withClue(s"${describe(r)}; notes ${r.notes}") {
      r.findings.map(_.effect) should contain("contrast_along_travel")
      interleavedNote(r) shouldBe defined
    }
  }

  "the subsampling factor" should "keep 4 samples per period of the fastest fringe, and leave a short record whole" in {
    val fast = sim(Nil, motion = Motion.Constant(1e6), n = 300000)
    // (the angle is read about the mid-ranges, without the fit's gains and phase error: a few % high at most)
    Interleaved.fastestFringeHz(fast) should (be >= 1e6 and be <= 1.05e6)
    Interleaved.factor(fast, 10000) shouldBe 2
    Interleaved.factor(sim(Nil, motion = Motion.Constant(100e3), n = 300000), 10000) should (be >= 23 and be <= 25)
    Interleaved.factor(sim(Nil, n = 100000), 100000) shouldBe 1
    val sub = Interleaved.pick(fast, 3, 2)
    sub.length shouldBe 100000
    sub.sampleRateHz shouldBe fast.sampleRateHz / 3
    sub.sin(10) shouldBe fast.sin(32)
  }

  // Another generator's 60 Hz hum on moves with dwells: on every 4th sample the hum was found beside five unexplained
  // items (a fit that did not follow the moves at a quarter of the rate), on all samples the hum alone. Structure the
  // subsample's model leaves unexplained sends a record this long back to all samples.
  it should "search all samples where the subsample's model leaves structure unexplained" in {
    // moves with a trapezoid speed (the acceleration steps) to 40 kHz and back, a 2 LSB hum; 2 seeds
    for (seed <- Seq(2, 4)) {
      val spec = FringeGenerator.Spec(n = 400000, fs = 2e6, motion = "trap", f0 = 40e3, amp = 0.85, humFs = 1e-3, humHz = 60, seed = seed)
      val r = SignalExplain.run("interleaved", FringeGenerator.recording(spec), Nil, Progress.none, searchSamples = 100000).report
      withClue(s"seed $seed: ${clue(r)}; notes ${r.notes}") {
        r.notes.exists(_.startsWith("explained on all 400000 samples: the model found on every 4th sample leaves")) shouldBe true
        r.findings.map(_.effect) shouldBe Seq("interference")
        r.findings.head.params("frequency_hz") shouldBe 60.0 +- 0.01
        r.unexplained shouldBe empty
      }
    }
  }
}
