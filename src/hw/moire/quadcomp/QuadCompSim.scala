package moire.quadcomp

import moire.cordic.Fixed
import moire.signal.{Adc, Motion, SignalParams, SignalSim, Samples}

/** Statistics of a signed error series, degrees: mean, the value of largest magnitude, standard deviation. */
final case class ErrorStats(mean: Double, max: Double, std: Double, count: Int)
object ErrorStats {
  def of(e: Seq[Double]): ErrorStats = {
    val m = e.sum / e.size
    ErrorStats(m, e.maxBy(math.abs), math.sqrt(e.map(v => (v - m) * (v - m)).sum / e.size), e.size)
  }
}

/** One simulated run of the bit-accurate model on SignalSim samples. */
final case class QuadCompRun(p: QuadCompParams, samples: Samples, outs: IndexedSeq[QuadCompSample]) {
  private def deg(angle: Long) = math.toDegrees(Fixed.angleToRad(angle, p.angleBits))
  /** Raw per-period measurements, degrees, in order. */
  def diffsDeg: Seq[Double] = outs.flatMap(_.diff).map(deg)
  /** The correction in use at the last sample, degrees. */
  def finalCorrectionDeg: Double = deg(outs.last.correction)
  /** Index of the first sample `k` periods (either direction) from the start. */
  def periodStart(k: Double): Int = {
    val t0 = samples.truePeriods(0)
    val i = samples.truePeriods.indexWhere(v => math.abs(v - t0) >= k)
    if (i < 0) samples.length else i
  }

  /** After-compensation error of sample i, degrees: the phase of the output pair (sin out, rebuilt
    * cos) minus the true fringe phase, wrapped to (-180, 180].
    */
  def pairError(i: Int): Double = {
    val o = outs(i)
    val ph = math.atan2(o.sin.toDouble, o.cos.toDouble)
    math.toDegrees(Fixed.angleDiff(ph, 2 * math.Pi * samples.truePeriods(i)))
  }
  /** The corrected cos angle psi (the rebuild CORDIC's input) minus the true phase, degrees. Large
    * near the cos channel's peaks, where the arccosine turns noise into angle.
    */
  def cosAngleError(i: Int): Double =
    math.toDegrees(Fixed.angleDiff(Fixed.angleToRad(outs(i).psi, p.angleBits), 2 * math.Pi * samples.truePeriods(i)))
  /** The same error for the uncompensated pair (normalised sin, normalised cos channel). */
  def rawPairError(i: Int, model: QuadCompModel): Double = {
    val s = model.normalise(samples.sinSigned(i), model.gainSin)
    val c = model.normalise(samples.cosSigned(i), model.gainCos)
    math.toDegrees(Fixed.angleDiff(math.atan2(s.toDouble, c.toDouble), 2 * math.Pi * samples.truePeriods(i)))
  }
}

/** Runs the model on the paper's setup: 12-bit AD9226 at 50 MS/s, constant fringe frequency. */
object QuadCompSim {
  val sampleRate = 50e6
  /** Added noise, LSB rms: with the 0.29 LSB rms of quantisation about 0.5 LSB in all, i.e. the
    * AD9226's typical SNR of about 69.5 dB for a full-scale sine.
    */
  val noiseLsb = 0.4
  val amplitude = 0.9

  def signal(phaseErrorDeg: Double, noiseLsb: Double = noiseLsb, seed: Long = 1, adc: Adc = Adc(12)): SignalParams =
    SignalParams(amplitude = amplitude, phaseErrorDeg = phaseErrorDeg, noiseRms = noiseLsb * adc.lsb, seed = seed)

  /** Runs `periods` fringe periods at `hz`; gains set from the nominal amplitude, as for a signal generator. */
  def run(p: QuadCompParams, sig: SignalParams, hz: Double, periods: Double, start: Double = 0.1): QuadCompRun = {
    val adc = Adc(p.inputBits)
    val n = math.ceil(periods / math.abs(hz) * sampleRate).toInt
    val s = SignalSim.generate(sig, Motion.Constant(hz, start), adc, sampleRate, n)
    val model = modelFor(p, sig, adc)
    val outs = (0 until n).map(i => model.step(s.sinSigned(i), s.cosSigned(i)))
    QuadCompRun(p, s, outs)
  }

  def modelFor(p: QuadCompParams, sig: SignalParams, adc: Adc): QuadCompModel = {
    val g = p.gainFor(sig.amplitude * adc.half)
    new QuadCompModel(p, g, g)
  }
}
