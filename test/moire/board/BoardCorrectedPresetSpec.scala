package moire.board

import chiseltest._
import moire.adapt.AdaptLearned
import moire.chain.{AdcPinCodes, CorrectedSubdivModel}
import moire.cordic.SimSupport
import moire.protocol.{AdaptRegisters, Registers}
import moire.signal.{Adc, SignalSim}
import org.scalatest.flatspec.AnyFlatSpec

/** The adaptive corrector's learned values restored by register on the whole DE2-115 top (design corrected): the board
  * learns on an imperfect signal, its values are read (saved), the board is reset (it has learned nothing), the values
  * are written back (hold, presets, table pairs, load) and read again, bit for bit the saved ones; then the hold is
  * released, the encoder moves again, and the board goes on exactly as the clock-accurate model that was given the same
  * presets: the learned values after the motion and the streamed positions bit for bit. The restore happens while the
  * encoder stands still, so the model needs the restore's clock only roughly (every loop is at rest then).
  */
class BoardCorrectedPresetSpec extends AnyFlatSpec with ChiselScalatestTester {
  val spec = new BoardCorrectedReadBackSpec
  val p: BoardParams = spec.p
  val ap = p.correctedParams.adapt
  /** Samples of motion before the save (640 periods) and after the restore (400 periods). */
  val before = 40000
  val after = 25000
  def periods(i: Int): Double = spec.fringeHz * i / p.adcClockHz

  "The corrected DE2-115 top" should "restore its learned values by register after a reset and go on as its model" in {
    test(new BoardHarness(p)).withAnnotations(SimSupport.backend) { c =>
      c.clock.setTimeout(0)
      val still = periods(before) + 0.125 // 45 degrees: away from every quadrant edge
      var moveFrom = Int.MaxValue // ADC sample where the second motion starts (set after the restore)
      val adc = new Ad9226Model(Adc(12, p.adcFormat), i => {
        val ph = if (i < before) periods(i) else if (i >= moveFrom && i < moveFrom + after) still + periods(i - moveFrom) else still
        val (s, co) = SignalSim.analog(spec.signal, ph)
        AnalogSample(s, co, ph)
      })
      val b = new BoardBench(c, adc)
      import AdaptRegisters._
      def readAll(): (Map[moire.protocol.Reg, Long], Seq[Long]) =
        (learned.map(r => r -> b.read(r.addr)).toMap, (0 until ap.harmonicEntries).map { i => b.write(TableIndex.addr, i); b.read(TableData.addr) })
      b.reset()
      b.runUntil(p.adcDivide * (before + 20000L), "the first motion to stop and settle")(adc.edges >= before + 12000)
      val (saved, savedTable) = readAll()
      assert(saved(Updates) > 20 && saved(Locked) == 1 && savedTable.count(_ != 0) > ap.harmonicEntries / 2, s"learned too little: $saved")

      // reset: the board has learned nothing
      b.reset()
      val first = adc.edges // the board's sample 0 after the reset
      val cycle0 = b.cycle
      b.runUntil(p.adcDivide * 6000L, "the board to settle after the reset")(adc.edges >= first + 3000)
      val (fresh, freshTable) = readAll()
      assert(fresh(Updates) == 0 && fresh(OffsetSin) == 0 && freshTable.forall(_ == 0), s"after the reset: $fresh")

      // restore: hold, presets, the table pair by pair, load; read back while held
      def sampleNow: Int = ((b.cycle - cycle0) / p.adcDivide).toInt
      assert(b.write(Control.addr, 1 << AdaptBit.Hold) == 1)
      val heldAt = sampleNow
      for ((r, pr) <- presets) assert(b.write(pr.addr, saved(r)) == 0, s"${pr.name} is write-only")
      for (k <- 0 until ap.harmonicEntries / 2) {
        b.write(TableIndex.addr, 2 * k); b.write(PresetEven.addr, savedTable(2 * k)); b.write(PresetOdd.addr, savedTable(2 * k + 1))
        b.write(Control.addr, (1 << AdaptBit.Hold) | (1 << AdaptBit.TableWrite))
      }
      assert(b.write(Control.addr, (1 << AdaptBit.Hold) | (1 << AdaptBit.Load)) == 1)
      val loadedAt = sampleNow
      val (restored, restoredTable) = readAll()
      for ((r, _) <- presets) assert(restored(r) == saved(r), s"${r.name}: restored 0x${restored(r).toHexString}, saved 0x${saved(r).toHexString}")
      for (((got, v), i) <- restoredTable.zip(savedTable).zipWithIndex) assert(got == v, s"table entry $i: restored 0x${got.toHexString}, saved 0x${v.toHexString}")
      assert(restored(Updates) == 0, "a load is not an update")
      b.write(Registers.Decimation.addr, 64)
      b.write(Registers.Control.addr, 1 << Registers.ControlBit.Enable)
      assert(b.write(Control.addr, 0) == 0)
      val releasedAt = sampleNow
      moveFrom = adc.edges + 3000

      b.runUntil(p.adcDivide * (after + 30000L), "the second motion to stop and settle")(adc.edges >= moveFrom + after + 12000)
      val (end, endTable) = readAll()
      val recs = b.recordFrames.flatMap(_.records).filter(_.index >= releasedAt + 1000)

      // the model from the reset: the same samples, hold, presets and release at about the board's samples
      val model = new CorrectedSubdivModel(p.correctedParams)
      val n = adc.edges - first
      val pos = scala.collection.mutable.ArrayBuffer.empty[Int]
      val preset = AdaptLearned(AdaptRegisters.signed(saved(OffsetSin)), AdaptRegisters.signed(saved(OffsetCos)), saved(GainSin),
        saved(GainCos), AdaptRegisters.signed(saved(Phase)), 0, locked = false, AdaptRegisters.signed(saved(TableSum)), Nil)
      for (j <- 0 until n) {
        if (j == heldAt) model.adapt.held = true
        if (j == releasedAt) model.adapt.held = false
        val s = adc.sample(first + j)
        val cyc = model.clock(valid = true, AdcPinCodes(s.sin, s.cos, s.otrSin, s.otrCos))
        if (cyc.valid) pos += cyc.out.position.toInt
        for (_ <- 1 until p.adcDivide) { val q = model.clock(valid = false, AdcPinCodes(0, 0)); if (q.valid) pos += q.out.position.toInt }
        if (j == loadedAt) {
          model.adapt.load(preset)
          for (k <- 0 until ap.harmonicEntries / 2)
            model.adapt.writePair(k, AdaptRegisters.signed(savedTable(2 * k)), AdaptRegisters.signed(savedTable(2 * k + 1)))
        }
      }
      val want = model.adapt.learned
      for ((r, v) <- want.words) assert(end(r) == v, s"${r.name}: board 0x${end(r).toHexString}, model 0x${v.toHexString}")
      for (((got, v), i) <- endTable.zip(want.tableWords).zipWithIndex) assert(got == v, s"table entry $i: board 0x${got.toHexString}, model 0x${v.toHexString}")
      assert(want.updates > 10 && want.words.toMap.apply(OffsetSin) != saved(OffsetSin) || want.table != savedTable.map(AdaptRegisters.signed),
        "the corrector learned nothing after the restore")
      // the streamed positions after the release: the board's sample k is the ADC's sample first + k
      assert(recs.size > 300, s"${recs.size} records")
      for (r <- recs) {
        val k = r.index.toInt; val s = adc.sample(first + k)
        assert(r.sin == s.sin && r.cos == s.cos, s"record $k codes")
        assert(r.position == pos(k), s"record $k position ${r.position}, model ${pos(k)}")
      }
      info(s"restored ${presets.size} values and ${ap.harmonicEntries} table entries; then ${want.updates} updates, " +
        s"${recs.size} records compared; ${b.cycle} clocks (${SimSupport.backendName})")
    }
  }
}
