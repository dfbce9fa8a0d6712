package moire.subdiv

import moire.cordic.{CordicBound, Fixed}
import moire.paper.AccuracyRow
import moire.signal._

/** Error model of the subdivider, in radians of phase (see docs/subdivision.md). */
object SubdivBound {
  private def lsb(p: SubdivParams): Double = math.pow(2, -(p.inputBits - 1))
  /** Largest |sel| / A the arcsine sees for a signal of amplitude r: the smaller channel is at most r / sqrt 2. */
  def asinArg(p: SubdivParams, r: Double): Double = math.min(1.0, (r + lsb(p)) / (p.asinAmplitude * math.sqrt(2)))
  /** Error of scaling the arcsine argument: rounding to the CORDIC word plus the rounded 1/A. */
  def asinScale(p: SubdivParams): Double =
    CordicBound.roundingLsb(p.rounding) * math.pow(2, -p.cordic.dataFrac) +
      math.abs(p.kConst * math.pow(2, -p.kFrac) - 1 / p.asinAmplitude)

  /** Datapath error against the double-precision method on the same ADC samples, for amplitude r. */
  def datapath(p: SubdivParams, r: Double): Double =
    if (!p.isAsin) CordicBound.atan2(p.cordic, r - lsb(p)).total
    else {
      val a = asinArg(p, r)
      CordicBound.asinDouble(p.cordic, math.min(1.0, a + asinScale(p))).total + CordicBound.asinBand(a, asinScale(p))
    }

  /** ADC quantization (half an LSB on each channel) seen in the phase, for amplitude r. */
  def quantization(p: SubdivParams, r: Double): Double =
    if (!p.isAsin) math.asin(math.min(1.0, math.sqrt(2) * 0.5 * lsb(p) / (r - lsb(p))))
    else CordicBound.asinBand(asinArg(p, r), 0.5 * lsb(p) / p.asinAmplitude)

  /** Bound on |position - exact phase * M| in counts for a clean signal of amplitude r
    * (for asin-double: r equal to asinAmplitude): (datapath + quantization) * M / 2 pi, plus one
    * count for m = floor(phase * M).
    */
  def counts(p: SubdivParams, r: Double): Double = (datapath(p, r) + quantization(p, r)) * p.counts / (2 * math.Pi) + 1
}

/** The phase in double precision by the same method as the hardware (radians, [0, 2 pi)). */
object SubdivReference {
  /** sin, cos in full scale (1.0 = 2^(inputBits-1) codes). */
  def phase(p: SubdivParams, sin: Double, cos: Double): Double = {
    val t = if (!p.isAsin) math.atan2(sin, cos)
    else {
      def asin(v: Double) = math.asin(math.max(-1.0, math.min(1.0, v / p.asinAmplitude)))
      if (math.abs(sin) <= math.abs(cos)) { if (cos < 0) math.Pi - asin(sin) else asin(sin) }
      else { if (sin < 0) asin(cos) - math.Pi / 2 else math.Pi / 2 - asin(cos) }
    }
    if (t < 0) t + 2 * math.Pi else t
  }
}

/** Figures of one run of the model over simulated signals.
  * @param maxCounts    largest |position - exact phase * M|, counts (period offset of the start removed)
  * @param maxRefRad    largest |model phase - double-precision method on the same samples|, radians
  * @param finalCounts  position - exact phase * M at the last sample
  * @param stepFaults   samples flagged stepFault
  * @param absent       samples flagged not present
  * @param maxFineCounts largest |(periods + phase) * M - exact phase * M|, counts: the error before the floor of eq. 1
  */
final case class SubdivRun(maxCounts: Double, maxRefRad: Double, finalCounts: Double, stepFaults: Int, absent: Int,
                           maxFineCounts: Double) {
  /** A period was lost or gained somewhere (the error passed half a period). */
  def lostPeriod(m: Int): Boolean = maxCounts >= m / 2.0
}

object SubdivAccuracy {
  val fs = 50e6
  /** The imperfect signal of the accuracy rows: 2 % offset, 3 % gain, 5 degree phase, 2 % + 1 % harmonics, 0.5 LSB noise. */
  val imperfect: SignalParams = SignalParams(amplitude = 0.8, offsetSin = 0.02, offsetCos = -0.01, gainCos = 1.03,
    phaseErrorDeg = 5, harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01)), noiseRms = 0.5 / 2048, seed = 7)

  def run(p: SubdivParams, s: Samples): SubdivRun = {
    val model = new SubdivModel(p)
    val mm = p.counts
    val lsb = math.pow(2, -(p.inputBits - 1))
    var offset = 0.0
    var pos = 0L; var prevRaw = 0L
    var maxC = 0.0; var maxR = 0.0; var last = 0.0; var faults = 0; var absent = 0; var maxF = 0.0
    for (i <- 0 until s.length) {
      val sn = s.sinSigned(i); val cs = s.cosSigned(i)
      val r = model.process(SubdivSample(sn, cs, s.otrSin(i), s.otrCos(i)))
      pos = if (i == 0) r.position else pos + Fixed.wrap(r.position - prevRaw, p.positionWidth)
      prevRaw = r.position
      val exact = s.truePeriods(i) * mm
      if (i == 0) offset = math.rint((pos - exact) / mm) * mm
      val e = pos - exact - offset
      if (r.present) {
        maxC = math.max(maxC, math.abs(e))
        val fine = Math.floorDiv(pos, mm.toLong) * mm + r.phase.toDouble / math.pow(2, p.angleBits) * mm
        maxF = math.max(maxF, math.abs(fine - exact - offset))
        val ref = SubdivReference.phase(p, sn * lsb, cs * lsb)
        maxR = math.max(maxR, math.abs(Fixed.angleDiff(Fixed.angleToRad(r.phase, p.angleBits), ref)))
      } else absent += 1
      if (r.stepFault) faults += 1
      last = e
    }
    SubdivRun(maxC, maxR, last, faults, absent, maxF)
  }

  /** A run with `n` samples at 50 MS/s. */
  def run(p: SubdivParams, sig: SignalParams, motion: Motion, n: Int): SubdivRun =
    run(p, SignalSim.generate(sig, motion, Adc(p.inputBits), fs, n))

  /** A fringe frequency (fraction of fs) that does not repeat the same phases every few samples. */
  def oddRate(f: Double): Double = f * fs * (1 + 1e-3 * math.sqrt(2))

  def rows(): Seq[AccuracyRow] = {
    val out = Seq.newBuilder[AccuracyRow]
    val n = 20000
    for (method <- PhaseMethod.all; mm <- Seq(256, 512, 1024, 2048, 4096)) {
      val p = SubdivParams(method = method, counts = mm, asinAmplitude = 0.9)
      val clean = run(p, SignalParams(amplitude = 0.9), Motion.Constant(oddRate(0.0013)), n)
      val bound = SubdivBound.counts(p, 0.9)
      out += AccuracyRow("subdiv", s"max |position - exact phase * M|, M=$mm clean, ${method.name}", "-", clean.maxCounts,
        "counts", clean.maxCounts <= bound, f"12-bit ADC, amplitude 0.9; bound $bound%.3f counts (CORDIC + ADC quantization " +
          f"+ 1 count for m = int(phi M), seed 002 eq. 1); before that floor ${clean.maxFineCounts}%.3f counts")
      val pi = p.copy(asinAmplitude = 0.8)
      val imp = run(pi, imperfect, Motion.Constant(oddRate(0.0013)), n)
      val refBound = SubdivBound.datapath(pi, 0.8 * 0.97)
      out += AccuracyRow("subdiv", s"max |position - exact phase * M|, M=$mm imperfect, ${method.name}", "-", imp.maxCounts, "counts",
        imp.maxRefRad <= refBound && !imp.lostPeriod(mm),
        f"offset/gain/phase/harmonics as seed 002 sec. 5.2 warns; holds when the datapath stays within ${refBound}%.2e rad " +
          f"of the double-precision method (measured ${imp.maxRefRad}%.2e) and no period is lost")
    }
    val p = SubdivParams(counts = 4096)
    val cleanOsc = run(p, SignalParams(amplitude = 0.9), Motion.Oscillate(3.3, fs / 2000), 100000)
    val bound = SubdivBound.counts(p, 0.9)
    out += AccuracyRow("subdiv", "max error across 100 reversals, M=4096, clean", "-", cleanOsc.maxCounts, "counts",
      cleanOsc.maxCounts <= bound, f"Oscillate 3.3 periods at 25 kHz (up to 0.52 MHz fringe); bound $bound%.3f counts")
    val osc = run(p, imperfect, Motion.Oscillate(3.3, fs / 2000), 100000)
    out += AccuracyRow("subdiv", "lost periods across 100 reversals, M=4096, imperfect", 0, if (osc.lostPeriod(4096)) 1 else 0,
      "periods", !osc.lostPeriod(4096),
      f"max error ${osc.maxCounts}%.1f counts (the signal's own phase error), final ${osc.finalCounts}%.1f counts")
    for (f <- Seq(0.45, -0.45)) {
      val fast = run(p, SignalParams(amplitude = 0.9), Motion.Constant(oddRate(f)), 20000)
      out += AccuracyRow("subdiv", f"max error at ${f}%.2f fs (Nyquist-safe), M=4096, clean", "-", fast.maxCounts, "counts",
        fast.maxCounts <= SubdivBound.counts(p, 0.9) && fast.stepFaults == 0, s"${fast.stepFaults} step faults")
    }
    val alias = run(p, SignalParams(amplitude = 0.9), Motion.Constant(0.49 * fs), 2000)
    out += AccuracyRow("subdiv", "0.49 fs (beyond the safe step) is flagged", "flagged", if (alias.stepFaults > 0) "flagged" else "silent",
      "", alias.stepFaults >= 1990, s"${alias.stepFaults} of 1999 steps flagged")
    out.result()
  }
}
