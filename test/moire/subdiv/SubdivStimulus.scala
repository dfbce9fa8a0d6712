package moire.subdiv

import moire.signal._

/** One clock of stimulus: pin codes (None = in.valid low) and clearStatus. */
final case class PinCycle(in: Option[AdcSample2], clear: Boolean)
final case class AdcSample2(sin: Int, cos: Int, otrSin: Boolean, otrCos: Boolean)

/** Test stimulus from the one signal simulator: reversals, imperfect and noisy signals, over-range,
  * low amplitude, motion beyond the safe step, a slow tail; random valid gaps and clear pulses.
  */
object SubdivStimulus {
  val fs = 50e6
  def segments(adc: Adc, scale: Int, seed: Long): Seq[Samples] = {
    def g(sp: SignalParams, m: Motion, n: Int) = SignalSim.generate(sp.copy(seed = seed), m, adc, fs, n * scale)
    val clean = SignalParams(amplitude = 0.9)
    Seq(
      g(clean, Motion.Oscillate(1.7, fs / (240 * scale), start = 0.3), 240),
      g(SubdivAccuracy.imperfect.copy(noiseRms = 3.0 / (1 << adc.bits)), Motion.Constant(0.21 * fs), 100),
      g(SignalParams(amplitude = 1.25), Motion.Constant(-0.013 * fs, 0.1), 80),
      g(SignalParams(amplitude = 0.05, noiseRms = 0.01), Motion.Constant(0.05 * fs), 60),
      g(clean, Motion.Constant(0.48 * fs, 0.7), 50),
      g(clean, Motion.Constant(-0.3 * fs, 0.2), 60),
      g(clean, Motion.Ramp(0.0, 0.002 * fs, 1e-6), 120))
  }

  def cycles(adc: Adc, scale: Int, seed: Long): Seq[PinCycle] = {
    val rnd = new scala.util.Random(seed)
    val samples = segments(adc, scale, seed).flatMap(s => (0 until s.length).map(i =>
      AdcSample2(s.sin(i), s.cos(i), s.otrSin(i), s.otrCos(i))))
    val out = Seq.newBuilder[PinCycle]
    for (s <- samples) {
      if (rnd.nextDouble() < 0.08) out += PinCycle(None, rnd.nextDouble() < 0.1)
      out += PinCycle(Some(s), rnd.nextDouble() < 0.01)
    }
    out.result()
  }
}
