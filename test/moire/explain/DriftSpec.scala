package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Drift in time (linear and warm-up) and contrast along the travel, from the independent generator. */
class DriftSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.describe

  private def run(s: FringeGenerator.Spec): Report = {
    val r = SignalExplain.run("drift", FringeGenerator.recording(s), Nil, Progress.none).report
    println(s"${s.motion} warm-up ${s.warmGain}/${s.warmOffset} tau ${s.warmTauS} drift ${s.driftGainPerS}/${s.driftOffsetPerS} contrast ${s.contrastPerPeriod}: " +
      s"findings [${describe(r)}]; unexplained [${r.unexplained.map(_.where).mkString("; ")}]")
    r
  }

  // back and forth over 60 periods, 30 times in 0.1 s: time and position can be told apart
  private val back = FringeGenerator.Spec(n = 100000, fs = 1e6, motion = "reverse", travel = 30, rateHz = 30, noiseLsb = 2.0, bits = 12)

  "explain" should "find a concealed warm-up with its time constant" in {
    // 1.5 LSB of offset and 0.15 % of amplitude (1.2 LSB) settling with 20 ms, under 2 LSB of noise per sample
    val r = run(back.copy(warmOffset = 1.5 / 2048, warmGain = 0.0015, warmTauS = 0.02))
    r.findings.map(_.effect) shouldBe Seq("warmup")
    val f = r.findings.head
    val (tau, sd) = (f.params("time_constant_s"), f.unc("time_constant_s"))
    println(f"warm-up time constant $tau%.4f +- $sd%.4f s (true 0.0200), offset step ${f.params("offset_sin_step_fs") * 2048}%.2f LSB (true 1.50)")
    math.abs(tau - 0.02) should be < 3 * sd
    sd should be < 0.01
  }

  it should "still find a linear drift (and call it linear)" in {
    val r = run(back.copy(driftOffsetPerS = 20.0 / 2048, driftGainPerS = 0.02))
    r.findings.map(_.effect) shouldBe Seq("drift")
    val f = r.findings.head
    f.params("offset_sin_per_s") * 2048 shouldBe 20.0 +- 3 * f.unc("offset_sin_per_s") * 2048
  }

  it should "find a drift on a scan whose speed swells and falls, the contrast change along the travel refuted by its halves" in {
    // a one-way scan whose speed swells and falls: position and time correlate (r 0.99), and the linear contrast change
    // along the travel is the stronger candidate. Its halves agree with each other but not, together, with the whole
    // record (a change linear in time has other slopes along the position in each half): it is no finding, and the
    // drift is found alone. Before, the contrast change was accepted first and listed as negligible once the drift
    // found after it took its part (0.09972 then; now 0.09984 +- 0.000046, 0.16 % below the generator's 0.1:
    // the model's error, 3.4 of the statistical sd)
    val r = run(FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "swell", f0 = 5e3, f1 = 60e3, noiseLsb = 1.2, driftOffsetPerS = 0.1))
    r.findings.map(_.effect) shouldBe Seq("drift")
    val f = r.findings.head
    println(f"swell: drift ${f.params("offset_sin_per_s")}%.5f +- ${f.unc("offset_sin_per_s")}%.2g / ${f.params("offset_cos_per_s")}%.5f (true 0.1)")
    for (k <- Seq("offset_sin_per_s", "offset_cos_per_s")) f.params(k) shouldBe 0.1 +- 0.0003
  }

  it should "find a large drift on a ramp, where a contrast change along the travel does not replicate on the halves" in {
    // position goes with the square of time: a change linear in the position has other slopes in the two halves of
    // the record. Before, the drift stood back for that refuted alternative ("the record cannot tell it from a contrast
    // change") and the report had no finding
    val r = run(FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "chirp", f0 = 5e3, f1 = 60e3, noiseLsb = 1.2, driftOffsetPerS = 0.1))
    r.findings.map(_.effect) shouldBe Seq("drift")
    val f = r.findings.head
    println(f"drift on a ramp: ${f.params("offset_sin_per_s")}%.5f +- ${f.unc("offset_sin_per_s")}%.1e full scale per second (true 0.1)")
    f.params("offset_sin_per_s") shouldBe 0.1 +- 3 * f.unc("offset_sin_per_s")
    f.lookAlikes.exists(_.startsWith("contrast_along_travel")) shouldBe true
    // time and speed go together on the ramp, but an offset drift changes no amplitude: no low-pass is like it
    f.lookAlikes.exists(_.startsWith("bandwidth")) shouldBe false
  }

  it should "name a drift beside the crosstalk that a drift of the amplitudes on a chirp is taken for" in {
    // speed grows linearly in time: an amplitude growing linearly in time grows linearly with speed, as crosstalk's do
    // (sin from cos and cos from sin with opposite signs). The record cannot tell them apart; whichever is found must
    // name the other. Before, a crosstalk of -144 / +147 ns stood alone
    val r = run(FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "chirp", f0 = 5e3, f1 = 60e3, noiseLsb = 1.2, driftGainPerS = 0.5))
    val f = r.findings.find(f => f.effect == "crosstalk" || f.effect == "drift").getOrElse(fail(s"neither crosstalk nor drift: ${describe(r)}"))
    println(s"${f.effect} on a chirp: ${f.lookAlikes.mkString(" | ")}")
    f.lookAlikes.exists(_.startsWith(if (f.effect == "crosstalk") "drift predicts" else "crosstalk predicts")) shouldBe true
  }

  it should "find a gain drift on a slow ramp, whose means in time show nothing" in {
    // 2 % of amplitude over 0.4 s while the speed grows by a fifth: a change of the amplitudes leaves the residual's
    // means in time at zero, the test the drift claims. Before, that test's -6.3 sd (before) against -0.5 sd (after)
    // refused the drift; the change along the travel was fitted unnamed and its curvature came out as a warm-up of
    // 0.08 % with 38 ms (an outside generator's file)
    val r = run(FringeGenerator.Spec(n = 400000, fs = 1e6, motion = "chirp", f0 = 3e3, f1 = 3.64e3, noiseLsb = 1.2, driftGainPerS = 0.05))
    r.findings.map(_.effect) shouldBe Seq("drift")
    val f = r.findings.head
    // the generator's 5 % per second of the amplitude at the start is 0.05 / 1.01 of the one at the record's middle
    val truth = 0.05 / (1 + 0.05 * 0.2)
    println(f"gain drift on a slow ramp: ${f.params("gain_sin_per_s")}%.5f +- ${f.unc("gain_sin_per_s")}%.1e per second (true $truth%.5f)")
    for (k <- Seq("gain_sin_per_s", "gain_cos_per_s")) f.params(k) shouldBe truth +- math.max(3 * f.unc(k), 1e-4)
  }

  it should "fit a drift at one speed, unnamed, and assess the rest of the record" in {
    // at a constant speed time and position go together: a drift and a contrast change along the travel predict the
    // same signal. Neither is a finding; the change is fitted all the same (15 LSB, 10 x the noise), so that the model
    // follows the signal and the 2nd harmonic beside it is found. Before, neither was fitted, the model did not follow
    // over 75 % of the record and nothing was assessed (the helper sweep's e09; the bench's a 3rd harmonic missed)
    val r = run(FringeGenerator.Spec(n = 100000, fs = 2e6, f0 = 20e3, noiseLsb = 1.5, driftOffsetPerS = 0.3, h2 = 0.003))
    r.misfit shouldBe empty
    r.findings.map(_.effect) should contain("harmonic")
    r.findings.map(_.effect) should contain noneOf ("drift", "warmup", "contrast_along_travel")
    val u = r.unexplained.filter(_.summary.contains("fitted, unnamed"))
    // named by both, in one order whichever was tried
    u.map(_.where) should have size 1
    u.head.where should startWith("contrast_along_travel or drift (both): ")
    u.head.summary should include("cannot tell it from")
    r.finalRms should be < 1.2 * 1.5 / 2048
  }

  it should "call a contrast change along a one-way scan neither drift nor warm-up, and rank three sizes in order" in {
    val sizes = Seq(-1e-5, -3e-5, -1e-4)
    val est = sizes.map { c =>
      val s = FringeGenerator.Spec(n = 50000, fs = 2e6, motion = "uneven", f0 = 20e3, wobble = 0.6, bits = 12, noiseLsb = 1.0, contrastPerPeriod = c)
      val r = run(s)
      r.findings.map(_.effect) should contain noneOf ("drift", "warmup")
      r.findings.map(_.effect) should contain("contrast_along_travel")
      // the trajectory does not follow the vibrations at 137 and 311 Hz: its phase departures correlate over tens of
      // samples, which is no noise (before, phase noise of 0.2 mrad was found at -1e-5 and -1e-4)
      r.findings.map(_.effect) should contain noneOf ("phase_noise", "jitter")
      if (c == sizes.head) r.unexplained.filter(_.where.startsWith("phase_noise")).map(_.summary).mkString should include("motion the trajectory does not follow")
      val f = r.findings.find(_.effect == "contrast_along_travel").get
      // the fit's amplitudes are those at the mean position: the gain per period relative to them is c / (1 + c (xm - x0))
      val xm = (0 until s.n).map(i => FringeGenerator.periods(s, i / s.fs)).sum / s.n
      val truth = c / (1 + c * xm)
      val (g, sd) = (f.params("gain_sin_per_period"), f.unc("gain_sin_per_period"))
      println(f"contrast $c%.1e per period: estimate $g%.4e +- $sd%.1e (truth $truth%.4e)")
      math.abs(g - truth) should be < 3 * sd
      g
    }
    est shouldBe est.sorted.reverse
  }
}

/** A drift too small to matter on a scan where time and position go together: negligible, whatever the record cannot
  * tell it from (it was "unexplained: the record cannot tell it from a contrast change along the travel").
  */
class SmallDriftSpec extends AnyFlatSpec with Matchers {
  "explain" should "list a drift of a tenth of an LSB on a chirp as negligible, not as unexplained" in {
    val s = FringeGenerator.Spec(n = 200000, fs = 5e6, motion = "chirp", f0 = 20e3, f1 = 150e3, driftOffsetPerS = 0.001, seed = 43)
    val r = SignalExplain.run("small drift", FringeGenerator.recording(s), Nil, Progress.none).report
    info(s"negligible [${r.negligible.map(_.effect).mkString(", ")}]; unexplained [${r.unexplained.map(_.where).mkString("; ")}]")
    r.findings shouldBe empty
    r.negligible.map(_.effect) should contain("drift")
    r.unexplained.map(_.where).filter(w => w.startsWith("drift") || w.startsWith("contrast_along_travel")) shouldBe empty
  }
}
