package moire.monitor

import moire.explain.{EffectSpec, PhysicsModel}
import moire.recording.Recording
import moire.signal.{Adc, Motion, SignalParams}

/** `monitor --simulate`: a board made by the physics model (explain's forward model): a read head moving at a steady
  * 5,000 fringe periods per second, sampled at 1 MS/s by a 12-bit ADC, with the offsets, gains and phase error of an
  * untrimmed head, and the effects given (by default a 3rd harmonic of 0.3 % on sin, for explain to name).
  * 2^20 samples (about a second), played in a loop.
  */
object SimBoard {
  val DefaultEffects: Seq[String] = Seq("harmonic:order=3,amplitude_rel=0.003,channel=sin")
  val SampleRateHz = 1e6
  val Samples: Int = 1 << 20
  val CountsPerPeriod = 4096
  val PeriodUm = 20.0

  def recording(effects: Seq[String]): Recording = {
    val specs = try effects.map(EffectSpec.parse) catch { case e: moire.MoireError => throw new MonitorError(e.getMessage) }
    val m = PhysicsModel(SignalParams(amplitude = 0.8, offsetSin = 0.012, offsetCos = -0.006, gainSin = 1.0, gainCos = 0.96,
      phaseErrorDeg = 1.5, noiseRms = 0.0007, seed = 5), Motion.Constant(5000), SampleRateHz, Samples, Adc(12), None, specs)
    val (rec, truth) = try m.generate() catch { case e: IllegalArgumentException => throw new MonitorError(e.getMessage.stripPrefix("requirement failed: ")) }
    rec.copy(meta = rec.meta ++ Map("source" -> "simulated board", "counts_per_period" -> CountsPerPeriod.toString, "period_um" -> PeriodUm.toString),
      extra = rec.extra ++ Map("position" -> truth.map(p => math.floor(p * CountsPerPeriod))))
  }
}
