package moire.board

import chiseltest._
import moire.chain.{AdcPinCodes, CorrectedSubdivModel}
import moire.cordic.SimSupport
import moire.protocol.Registers
import moire.signal.{AdcFormat, Motion, SignalParams}
import org.scalatest.flatspec.AnyFlatSpec

/** The other strap and datapath: two's complement AD9226 codes, the corrected chain
  * (moire.chain.CorrectedSubdivider), a 12.5 MHz ADC clock (divider 4).
  */
class BoardVariantSpec extends AnyFlatSpec with ChiselScalatestTester {
  val p = BoardParams(design = BoardDesign.Corrected, adcFormat = AdcFormat.TwosComplement, adcClockHz = 12500000,
    baud = 6250000, frameRecords = 4, fifoDepth = 8, decimation = 512, clockSource = ClockSource.Logic)

  "The DE2-115 board with the corrected chain and two's complement ADCs" should "stream the model's positions" in {
    test(new BoardHarness(p)).withAnnotations(SimSupport.backend) { c =>
      c.clock.setTimeout(0)
      val M = p.correctedParams.subdiv.counts
      val adc = Ad9226Model(AdcFormat.TwosComplement, SignalParams(amplitude = 0.85), Motion.Constant(-30e3, start = 0.6), p.adcClockHz)
      val b = new BoardBench(c, adc)
      b.reset()
      assert(b.read(Registers.AdcFormat.addr) == 1)
      assert(b.read(Registers.AdcClockHz.addr) == p.adcClockHz)
      b.runUntil(200000, "5 record frames")(b.recordFrames.size >= 5)
      val recs = b.recordFrames.flatMap(_.records)
      assert(b.decoder.stats.crcErrors == 0 && recs.map(_.index).sliding(2).forall { case Seq(x, y) => y - x == p.decimation })
      // the clock-accurate chain model, fed the same samples back to back (the datapath only moves on valid samples)
      val model = new CorrectedSubdivModel(p.correctedParams)
      val n = recs.map(_.index.toInt).max + 1
      val pos = scala.collection.mutable.ArrayBuffer.empty[Int]
      var i = 0
      while (pos.size < n) {
        val s = if (i < n) adc.sample(i) else adc.sample(0)
        val cyc = model.clock(i < n, AdcPinCodes(s.sin, s.cos, s.otrSin, s.otrCos))
        if (cyc.valid) pos += cyc.out.position.toInt
        i += 1
      }
      for (r <- recs) {
        val k = r.index.toInt; val s = adc.sample(k)
        assert(r.sin == s.sin && r.cos == s.cos, s"record $k codes")
        assert(r.position == pos(k), s"record $k position ${r.position}, model ${pos(k)}")
        val truth = math.floor(s.truePeriods * M).toLong
        assert(math.abs(r.position - truth) <= 1, s"record $k position ${r.position}, true motion $truth")
        if (k > 0) assert(!r.direction, s"record $k: moving down")
      }
      info(s"${recs.size} records, ${b.cycle} clocks (${SimSupport.backendName})")
    }
  }
}
