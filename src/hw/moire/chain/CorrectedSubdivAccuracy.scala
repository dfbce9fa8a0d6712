package moire.chain

import moire.signal._
import moire.subdiv.{SubdivModel, SubdivParams, SubdivSample}

/** Position error of the corrected chain against the exact phase, next to the plain subdivider's. */
object CorrectedSubdivAccuracy {
  /** Max |position - M * true phase| in counts over the last `evalFraction` of the run, after removing the
    * mean (the start count and the corrector's constant phase are arbitrary); `bound` = the 0.02 degree
    * goal of issue 3 plus the floor of m = int(phi M).
    */
  final case class Result(corrected: Double, plain: Double, bound: Double)

  def run(p: CorrectedSubdivParams, sig: SignalParams, hz: Double, samples: Int, evalFraction: Double = 0.25): Result = {
    val fs = 50e6
    val adc = Adc(p.adapt.inputBits, p.format)
    val s = SignalSim.generate(sig, Motion.Constant(hz, 0.1), adc, fs, samples)
    val from = (samples * (1 - evalFraction)).toInt
    val m = p.subdiv.counts
    def spread(errs: Seq[Double]): Double = { val mean = errs.sum / errs.size; errs.map(e => math.abs(e - mean)).max }

    val model = new CorrectedSubdivModel(p)
    val errs = Seq.newBuilder[Double]
    for (t <- 0 until samples + p.latency) {
      val i = math.min(t, samples - 1)
      val c = model.clock(t < samples, AdcPinCodes(s.sin(i), s.cos(i), s.otrSin(i), s.otrCos(i)))
      val j = t - p.latency
      if (c.valid && j >= from) errs += c.out.position - m * s.truePeriods(j)
    }
    val plainP = SubdivParams(inputBits = p.adapt.inputBits, counts = m, method = p.subdiv.method)
    val plain = new SubdivModel(plainP)
    val perrs = (0 until samples).map { i =>
      plain.process(SubdivSample(s.sinSigned(i), s.cosSigned(i))).position - m * s.truePeriods(i)
    }.drop(from)
    Result(spread(errs.result()), spread(perrs), 0.02 / 360 * m + 1.0)
  }
}

/** The chain's row in `accuracy`: position error at M = 4096 with and without the corrector. */
object CorrectedSubdivRows {
  import moire.paper.AccuracyRow
  val imperfect: SignalParams = SignalParams(amplitude = 0.85, offsetSin = 0.02, offsetCos = -0.02, gainCos = 0.97,
    phaseErrorDeg = 5, harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01)), noiseRms = 0.5 / 2048)

  def rows(progress: String => Unit = _ => ()): Seq[AccuracyRow] = Seq(500e3, 1e6).map { hz =>
    progress(f"corrected subdivision ${hz / 1e3}%.0f kHz")
    val r = CorrectedSubdivAccuracy.run(CorrectedSubdivParams(), imperfect, hz, samples = 300000)
    AccuracyRow("issue3", f"corrector + subdivider, M = 4096, ${hz / 1e3}%.0f kHz, all imperfections: max position error",
      ujson.Num(r.bound), r.corrected, "counts", r.corrected <= r.bound,
      f"paper column = 0.02 deg goal + 1 count floor; plain subdivider ${r.plain}%.2f counts; last 1.5 ms of 6 ms, 0.5 LSB noise")
  }
}
