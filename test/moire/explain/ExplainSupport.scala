package moire.explain

import moire.recording.Recording
import moire.signal.{Adc, Motion, SignalParams}

/** Builds concealed-effect recordings with `simulate`'s model and explains them. */
object ExplainSupport {
  val lsb12: Double = 1.0 / 2048

  def sim(effects: Seq[EffectSpec], motion: Motion = Motion.Ramp(20e3, 200e3, 0.01), n: Int = 100000, fs: Double = 10e6,
          noiseLsb: Double = 1.5, phaseErrorDeg: Double = 1.0, seed: Long = 3, linesPerRev: Option[Double] = None,
          amplitude: Double = 0.85): Recording = {
    val base = SignalParams(amplitude = amplitude, offsetSin = 0.004, offsetCos = -0.003, gainSin = 1.0, gainCos = 1.015,
      phaseErrorDeg = phaseErrorDeg, noiseRms = noiseLsb * lsb12, seed = seed)
    PhysicsModel(base, motion, fs, n, Adc(12), linesPerRev, effects).generate()._1
  }

  def explain(r: Recording): Report = SignalExplain.run("test", r, Nil, Progress.none).report

  def within(actual: Double, expected: Double, rel: Double = 0.2): Boolean = math.abs(actual - expected) <= rel * math.abs(expected)

  def describe(r: Report): String = r.findings.map(f => s"${f.effect}(${f.channel}) ${f.params} dBIC=${f.deltaBic}").mkString("; ")

  /** The independent generator's record of `spec`, explained on all its samples. */
  def explainAll(name: String, spec: FringeGenerator.Spec): Report =
    SignalExplain.run(name, FringeGenerator.recording(spec), Nil, Progress.none, searchSamples = Int.MaxValue).report

  /** What a report found, left unexplained and did not follow: for a clue. */
  def clue(r: Report): String = s"${describe(r)}; unexplained ${r.unexplained.map(_.summary)}; misfit ${r.misfit.map(_.summary)}"
}
