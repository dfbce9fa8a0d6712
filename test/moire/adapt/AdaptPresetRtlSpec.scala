package moire.adapt

import chisel3._
import chiseltest._
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec

/** The corrector's preset port (hold, load, table pair writes) against the model's `held`, `load` and `writePair`,
  * clock for clock and bit for bit, on a moving signal: the output every clock and the read-back at the end.
  */
class AdaptPresetRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  val rtl = new AdaptRtlSpec
  val p: AdaptParams = rtl.fast
  val cycles: Int = rtl.cycles
  val holdAt: Int = cycles / 3
  val pairsAt: Int = holdAt + 20
  val loadAt: Int = pairsAt + p.harmonicEntries + 6
  val releaseAt: Int = cycles / 2
  val preset: AdaptLearned = {
    val rnd = new scala.util.Random(5)
    val table = Seq.fill(p.harmonicEntries)((rnd.nextInt(1 << 13) - (1 << 12)).toLong)
    AdaptLearned(3 * 4096 + 17, -2 * 4096 - 5, p.startGain * 21 / 20, p.startGain * 19 / 20, -1234, 0, locked = false, table.sum, table)
  }

  "AdaptiveCorrector's preset port" should s"hold, load and write the table exactly as the model (${SimSupport.backendName})" in {
    val stim = rtl.stimulus(p, 0)
    val model = new AdaptModel(p)
    test(new AdaptiveCorrector(p, withReadBack = true)).withAnnotations(SimSupport.backend) { dut =>
      val pr = dut.preset.get
      var checked = 0
      for (t <- 0 until cycles) {
        val (in, otr) = stim(t)
        dut.io.in.valid.poke(in.isDefined.B)
        dut.io.in.bits.sin.poke(in.fold(0L)(_._1).S); dut.io.in.bits.cos.poke(in.fold(0L)(_._2).S)
        dut.io.in.bits.otrSin.poke(otr._1.B); dut.io.in.bits.otrCos.poke(otr._2.B)
        // inputs poked in clock t are registered by the corrector: they act in clock t + 1
        pr.hold.poke((t >= holdAt && t < releaseAt).B)
        pr.load.poke((t == loadAt).B)
        pr.offsetSin.poke(preset.offsetSin.S); pr.offsetCos.poke(preset.offsetCos.S); pr.gainSin.poke(preset.gainSin.S)
        pr.gainCos.poke(preset.gainCos.S); pr.phase.poke(preset.phase.S); pr.tableSum.poke(preset.tableSum.S)
        val k = (t - pairsAt) / 2
        val pairNow = t >= pairsAt && (t - pairsAt) % 2 == 0 && k < p.harmonicEntries / 2
        pr.tableWrite.poke(pairNow.B)
        val kk = math.max(k, 0) % (p.harmonicEntries / 2)
        pr.pair.poke(kk.U)
        pr.even.poke(preset.table(2 * kk).S); pr.odd.poke(preset.table(2 * kk + 1).S)
        dut.readBack.get.tableIndex.poke(0.U)
        model.held = t - 1 >= holdAt && t - 1 < releaseAt
        val e = model.step(in, otr)
        if (t - 1 == loadAt) model.load(preset)
        if (t - 1 >= pairsAt && (t - 1 - pairsAt) % 2 == 0 && (t - 1 - pairsAt) / 2 < p.harmonicEntries / 2) {
          val j = (t - 1 - pairsAt) / 2
          model.writePair(j, preset.table(2 * j), preset.table(2 * j + 1))
        }
        dut.io.out.valid.expect(e.isDefined.B, s"valid at cycle $t")
        e.foreach { w =>
          val o = dut.io.out.bits
          val got = AdaptOut(o.sin.peekInt().toLong, o.cos.peekInt().toLong, o.otrSin.peekBoolean(), o.otrCos.peekBoolean())
          assert(got == w, s"cycle $t: rtl $got, model $w")
          checked += 1
        }
        dut.clock.step()
        if (t == releaseAt - 1) {
          // held since holdAt, loaded: the estimates are the presets, the table the preset table
          assert((model.os, model.oc, model.ks, model.kc, model.t) == (preset.offsetSin, preset.offsetCos, preset.gainSin, preset.gainCos, preset.phase))
          assert(model.table.toSeq == preset.table && model.tableSum == preset.tableSum)
        }
      }
      // drained (no input), then the read-back (table entry 0) a few clocks later
      dut.io.in.valid.poke(false.B)
      for (_ <- 0 until 60) { model.step(None); dut.clock.step() }
      dut.clock.step(4)
      val l = dut.readBack.get.learned
      val want = model.learned
      assert((l.offsetSin.peekInt(), l.offsetCos.peekInt(), l.gainSin.peekInt(), l.gainCos.peekInt(), l.phase.peekInt(), l.tableSum.peekInt()) ==
        (BigInt(want.offsetSin), BigInt(want.offsetCos), BigInt(want.gainSin), BigInt(want.gainCos), BigInt(want.phase), BigInt(want.tableSum)))
      assert(l.tableData.peekInt() == want.table.head && l.updates.peekInt() == want.updates)
      if (SimSupport.hasVerilator) assert(want.offsetSin != preset.offsetSin && want.table != preset.table, "the corrector did not learn on after the release")
      assert(checked > cycles / 2)
    }
  }
}
