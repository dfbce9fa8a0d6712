package moire.quadcomp

import chisel3._
import chiseltest._
import moire.cordic.{Rounding, SimSupport}
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import org.scalatest.flatspec.AnyFlatSpec

/** One configuration of the sweep: generator parameters and the signal it is fed. */
final case class RtlCase(p: QuadCompParams, sig: SignalParams, motion: Motion, gapPercent: Int)

/** RTL against the bit-accurate model, bit for bit, over a sweep of generator and signal parameters. */
class QuadCompRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** Samples per configuration; treadle (no Verilator) runs the first two configurations, fewer samples. */
  val samples: Int = if (SimSupport.hasVerilator) 3000 else 250

  val cases: Seq[RtlCase] = Seq(
    RtlCase(QuadCompParams(), SignalParams(phaseErrorDeg = 12, noiseRms = 0.5 / 2048, seed = 3), Motion.Constant(1e6), 0),
    RtlCase(QuadCompParams(iterations = 12, width = 16, peakTableSize = 16, averageLog2 = 0, rounding = Rounding.Truncate),
      SignalParams(amplitude = 0.6, phaseErrorDeg = -7, noiseRms = 0.5 / 2048, seed = 4), Motion.Constant(-1e6), 20),
    RtlCase(QuadCompParams(iterations = 20, width = 22, peakTableSize = 256, averageLog2 = 2, pipelineEvery = 2, fusePeaks = true),
      SignalParams(phaseErrorDeg = 3, noiseRms = 1.0 / 2048, seed = 5), Motion.Constant(2.5e6, 0.3), 10),
    RtlCase(QuadCompParams(inputBits = 10, iterations = 14, width = 18, peakTableSize = 0, averageLog2 = 1),
      SignalParams(amplitude = 0.8, phaseErrorDeg = 25, seed = 6), Motion.Oscillate(20, 30e3), 5),
    RtlCase(QuadCompParams(inputBits = 14, iterations = 16, width = 20, peakTableSize = 64, averageLog2 = 4, gainFrac = 15, fusePeaks = true),
      SignalParams(phaseErrorDeg = -12, noiseRms = 0.5 / 8192, seed = 7), Motion.Constant(400e3), 0)
  )

  "QuadComp RTL" should s"equal the model bit for bit over a sweep of configurations (${SimSupport.backendName})" in {
    val active = if (SimSupport.hasVerilator) cases else cases.take(2)
    val ps = active.map(_.p)
    val stim = active.map { c =>
      val adc = Adc(c.p.inputBits)
      val s = SignalSim.generate(c.sig, c.motion, adc, 50e6, samples)
      val model = QuadCompSim.modelFor(c.p, c.sig, adc)
      val ins = (0 until samples).map(i => (s.sinSigned(i).toLong, s.cosSigned(i).toLong))
      val outs = ins.map { case (a, b) => model.step(a, b) }
      val rnd = new scala.util.Random(c.p.hashCode)
      // Input schedule: sample index per cycle, or -1 for an idle cycle.
      val schedule = {
        val b = Seq.newBuilder[Int]; var k = 0
        while (k < samples) { if (rnd.nextInt(100) < c.gapPercent) b += -1 else { b += k; k += 1 } }
        b.result()
      }
      (model, ins, outs, schedule)
    }
    test(new QuadCompBank(ps)).withAnnotations(SimSupport.backend) { dut =>
      for (k <- ps.indices) {
        dut.io.gainSin(k).poke(stim(k)._1.gainSin.U)
        dut.io.gainCos(k).poke(stim(k)._1.gainCos.U)
      }
      val lat = dut.latencies
      val cycles = stim.map(_._4.size).max + lat.max + 2
      val got = Array.fill(ps.size)(0)
      val diffs = Array.fill(ps.size)(Vector.empty[Long])
      for (t <- 0 until cycles) {
        for (k <- ps.indices) {
          val sch = stim(k)._4
          val idx = if (t < sch.size) sch(t) else -1
          dut.io.in(k).valid.poke((idx >= 0).B)
          val (a, b) = if (idx >= 0) stim(k)._2(idx) else (0L, 0L)
          dut.io.in(k).bits.sin.poke(a.S)
          dut.io.in(k).bits.cos.poke(b.S)
          val src = t - lat(k)
          val expectValid = src >= 0 && src < sch.size && sch(src) >= 0
          dut.io.out(k).valid.expect(expectValid.B, s"${ps(k).moduleName} valid at cycle $t")
          if (expectValid) {
            val e = stim(k)._3(sch(src))
            val o = dut.io.out(k).bits
            val (s, c) = (o.sin.peekInt().toLong, o.cos.peekInt().toLong)
            assert(s == e.sin && c == e.cos,
              s"${ps(k).moduleName} sample ${sch(src)}: rtl ($s, $c), model (${e.sin}, ${e.cos})")
            got(k) += 1
          }
          if (dut.io.diff(k).valid.peekBoolean()) diffs(k) :+= dut.io.diff(k).bits.peekInt().toLong
        }
        dut.clock.step()
      }
      for (k <- ps.indices) {
        assert(got(k) == samples, s"${ps(k).moduleName}: ${got(k)} outputs for $samples inputs")
        val want = stim(k)._3.flatMap(_.diff)
        assert(want.size >= 3, s"${ps(k).moduleName}: the stimulus gives only ${want.size} measurements")
        assert(diffs(k) == want, s"${ps(k).moduleName}: measured differences rtl ${diffs(k)}, model $want")
      }
    }
  }
}
