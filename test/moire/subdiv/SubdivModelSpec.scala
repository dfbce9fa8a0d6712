package moire.subdiv

import moire.signal._
import org.scalatest.flatspec.AnyFlatSpec

/** The model against double precision and the exact phase, within the stated error bound. */
class SubdivModelSpec extends AnyFlatSpec {
  import SubdivAccuracy.{fs, oddRate}
  def run(p: SubdivParams, s: SignalParams, m: Motion, n: Int): SubdivRun = SubdivAccuracy.run(p, s, m, n)
  val clean = SignalParams(amplitude = 0.9)

  "Subdivision error on clean signals" should "stay within the bound (CORDIC + ADC quantization + 1 count) for M = 256..4096" in {
    for (method <- PhaseMethod.all; bits <- Seq(10, 12, 14); mm <- Seq(256, 1024, 4096)) {
      val p = SubdivParams(bits, method, counts = mm)
      val r = run(p, clean, Motion.Constant(oddRate(0.0021), 0.37), 12000)
      val bound = SubdivBound.counts(p, 0.9)
      assert(r.maxCounts <= bound, s"${p.moduleName}: ${r.maxCounts} counts > bound $bound")
      // The floor of eq. 1 alone costs up to one count: a run that never reaches it would test nothing.
      assert(r.maxCounts > 0.9, s"${p.moduleName}: ${r.maxCounts}")
      // Before the floor: within the datapath + ADC part of the bound.
      assert(r.maxFineCounts <= bound - 1, s"${p.moduleName}: ${r.maxFineCounts} counts before the floor > ${bound - 1}")
      assert(r.maxRefRad <= SubdivBound.datapath(p, 0.9), s"${p.moduleName}: ${r.maxRefRad} rad from double precision")
      assert(r.stepFaults == 0 && r.absent == 0)
    }
  }

  "The bound" should "be tight enough to notice a wrong amplitude setting of the arcsine" in {
    val p = SubdivParams(12, PhaseMethod.AsinDouble, counts = 4096, asinAmplitude = 0.8)
    val r = run(p, clean, Motion.Constant(oddRate(0.0021)), 12000)
    assert(r.maxCounts > SubdivBound.counts(p.copy(asinAmplitude = 0.9), 0.9))
    assert(r.maxRefRad <= SubdivBound.datapath(p, 0.9)) // still right against its own double-precision method
  }

  "Imperfect signals" should "keep the datapath within its bound of double precision and lose no period" in {
    for (method <- PhaseMethod.all; mm <- Seq(256, 1024, 4096)) {
      val p = SubdivParams(method = method, counts = mm, asinAmplitude = 0.8)
      val r = run(p, SubdivAccuracy.imperfect, Motion.Oscillate(2.2, fs / 3000), 12000)
      assert(r.maxRefRad <= SubdivBound.datapath(p, 0.8 * 0.97), s"${p.moduleName}: ${r.maxRefRad}")
      assert(!r.lostPeriod(mm))
      // The signal's own phase error (several degrees) shows up, as it must.
      assert(r.maxCounts > 2.0 / 360 * mm)
    }
  }

  "Direction reversals" should "never lose a count: error within the bound over 60 reversals, clean and with noise" in {
    for (method <- PhaseMethod.all) {
      val p = SubdivParams(method = method, counts = 4096)
      val bound = SubdivBound.counts(p, 0.9)
      val r = run(p, clean, Motion.Oscillate(4.6, fs / 1000, start = 0.123), 30000)
      assert(r.maxCounts <= bound, s"${method.name} clean: ${r.maxCounts} > $bound")
      val noisy = run(p, clean.copy(noiseRms = 2.0 / 2048, seed = 5), Motion.Oscillate(4.6, fs / 1000, start = 0.123), 30000)
      assert(!noisy.lostPeriod(4096) && math.abs(noisy.finalCounts) <= bound + 3, s"${method.name} noisy: $noisy")
    }
  }

  "Speeds up to 0.45 fs" should "be counted exactly in both directions, without a step fault" in {
    for (method <- PhaseMethod.all; f <- Seq(0.02, 0.2, 0.37, 0.45, -0.1, -0.31, -0.45)) {
      val p = SubdivParams(method = method, counts = 2048)
      val r = run(p, clean, Motion.Constant(oddRate(f), 0.4), 8000)
      assert(r.maxCounts <= SubdivBound.counts(p, 0.9), s"${method.name} at $f fs: ${r.maxCounts}")
      assert(r.stepFaults == 0)
    }
  }

  "Speeds beyond the safe step" should "be flagged on every sample where the phase step exceeds maxStepTurns" in {
    for (f <- Seq(0.48, 0.52, -0.49)) {
      val p = SubdivParams(counts = 1024)
      val r = run(p, clean, Motion.Constant(f * fs), 3000)
      assert(r.stepFaults == 2999, s"$f fs: ${r.stepFaults}")
    }
  }

  "Low amplitude and over-range" should "be flagged, and the position holds while the signal is absent" in {
    val p = SubdivParams(counts = 256, presentThreshold = 0.2)
    val m = new SubdivModel(p)
    val a = m.process(SubdivSample(1000, 1000))
    val held = m.process(SubdivSample(-300, 20)) // |v| = 0.147 < 0.2
    assert(!held.present && held.position == a.position && held.m == a.m)
    val back = m.process(SubdivSample(-200, 1500)) // 45 -> -7.6 degrees: backwards across the period boundary
    val expectM = math.floor((1 + math.atan2(-200, 1500) / (2 * math.Pi)) * 256).toLong
    assert(back.present && back.periods == -1 && back.m == expectM && back.position == -256 + expectM)
    assert(m.process(SubdivSample(2047, 10, otrSin = true)).overRange)
    assert(!m.process(SubdivSample(2047, 10)).overRange)
    // Threshold exactly at the code: sqrt(409^2 + 0) < 0.2 * 2048 = 409.6 <= sqrt(410^2)
    assert(!m.process(SubdivSample(409, 0)).present && m.process(SubdivSample(410, 0)).present)
  }
}
