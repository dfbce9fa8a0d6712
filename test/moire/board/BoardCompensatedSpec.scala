package moire.board

import chiseltest._
import moire.cordic.SimSupport
import moire.harmonic.{HarmonicModel, HarmonicParams, HarmonicSlot}
import moire.protocol.Registers
import moire.signal.{AdcFormat, Motion, SignalParams}
import moire.subdiv.{SubdivModel, SubdivSample}
import org.scalatest.flatspec.AnyFlatSpec

/** The turntable compensator on the board (design compensated): coefficients written and read back through
  * the register interface as `board-reg --coefficients` does, records carrying theta - f(theta) exactly as the
  * subdivider and compensator models give it, and the A/B/Z outputs following it.
  */
class BoardCompensatedSpec extends AnyFlatSpec with ChiselScalatestTester {
  // 256 fringe periods per turn of 1024 counts: 2^18 counts, about 4.9 arcsec per count
  val p = BoardParams(design = BoardDesign.Compensated, adcClockHz = 12500000, baud = 6250000, frameRecords = 4, fifoDepth = 8,
    decimation = 512, clockSource = ClockSource.Logic, burstSamples = 256, harmonic = HarmonicParams(lines = 256))
  val hp: HarmonicParams = p.harmonicParams

  "The DE2-115 board with the turntable compensator" should "load coefficients by register and stream theta - f(theta)" in {
    test(new BoardHarness(p)).withAnnotations(SimSupport.backend) { c =>
      c.clock.setTimeout(0)
      val adc = Ad9226Model(AdcFormat.OffsetBinary, SignalParams(amplitude = 0.85), Motion.Constant(40e3, start = 0.3), p.adcClockHz)
      val b = new BoardBench(c, adc)
      val quad = new QuadDecoder
      b.onCycle = () => { val (a, bb, _) = b.encOut; quad.update(a, bb) }
      b.reset()
      // two harmonics: order 1, 100 arcsec at 30 degrees; order 2, -60 arcsec at 200 degrees
      val slots = Seq(HarmonicSlot.of(hp, 1, 100, 30), HarmonicSlot.of(hp, 2, -60, 200)) ++ Seq.fill(hp.harmonics - 2)(HarmonicSlot.off)
      for ((s, j) <- slots.take(2).zipWithIndex; (v, f) <- Seq(s.order.toLong, s.c & 0xFFFFFFFFL, s.phi).zipWithIndex) {
        val addr = Registers.HarmonicBase + j * hp.regsPerSlot + f
        val want = if (f == 1) java.lang.Long.valueOf(moire.cordic.Fixed.wrap(s.c, hp.coefWidth)).longValue & 0xFFFFFFFFL else v
        assert(b.write(addr, v) == want, s"${Registers.name(addr)} write 0x${v.toHexString} read back")
      }
      val from = b.recordFrames.size + 3 // records already in the FIFO may predate the writes
      b.runUntil(400000, "record frames after the writes")(b.recordFrames.size >= from + 6)
      val recs = b.recordFrames.drop(from).flatMap(_.records)
      val sub = new SubdivModel(p.subdiv)
      val harm = new HarmonicModel(hp)
      val n = recs.map(_.index.toInt).max + 1
      val raw = (0 until n).map { i =>
        val s = adc.sample(i)
        sub.process(SubdivSample(adc.adc.fromPins(s.sin), adc.adc.fromPins(s.cos), s.otrSin, s.otrCos)).position.toInt
      }
      var maxShift = 0L
      for (r <- recs) {
        val k = r.index.toInt
        val f = harm(raw(k).toLong & ((1L << hp.countBits) - 1), slots).f
        val fCounts = Math.floorDiv(f + (1L << (hp.outFrac - 1)), 1L << hp.outFrac)
        maxShift = math.max(maxShift, math.abs(fCounts))
        assert(r.position == (raw(k) - fCounts).toInt, s"record $k: position ${r.position}, model ${raw(k)} - $fCounts")
      }
      assert(maxShift > 10, s"the coefficients should move the position by more than 10 counts, moved $maxShift")
      // A/B/Z follow the compensated position: the decoded count moves with the records
      val moved = quad.count
      assert(quad.errors == 0 && moved > 0, s"A/B outputs: count $moved, ${quad.errors} skipped phases")
      info(s"${recs.size} records checked against the models, |f| up to $maxShift counts (${SimSupport.backendName})")
    }
  }
}
