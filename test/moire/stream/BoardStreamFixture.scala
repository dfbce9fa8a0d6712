package moire.stream

import moire.protocol.StreamV1
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import moire.subdiv.{SubdivModel, SubdivParams, SubdivSample}

/** Realistic records: the one signal simulator (codes, OTR) through the subdivider model (position, flags),
  * one record every `decimation` ADC samples, sample index from `first`.
  */
object BoardStreamFixture {
  def records(n: Int, decimation: Long, adcClockHz: Double, first: Long = 0, adc: Adc = Adc(12),
              motion: Motion = Motion.Oscillate(3.0, 2.0, 0.1), p: SignalParams = SignalParams(noiseRms = 0.002)): IndexedSeq[Record] = {
    val s = SignalSim.generate(p, motion, adc, adcClockHz / decimation, n)
    val model = new SubdivModel(SubdivParams(counts = 1024))
    var last = 0L; var up = true
    IndexedSeq.tabulate(n) { i =>
      val r = model.process(SubdivSample(s.sinSigned(i), s.cosSigned(i), s.otrSin(i), s.otrCos(i)))
      if (i > 0 && r.position != last) up = r.position > last
      last = r.position
      Record.of((first + i * decimation) & StreamV1.MaxU32, s.sin(i), s.cos(i), r.position.toInt, s.otrSin(i), s.otrCos(i),
        r.present, r.overRange, r.stepFault, up)
    }
  }
}
