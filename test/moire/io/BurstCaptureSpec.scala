package moire.io

import chisel3._
import chiseltest._
import moire.protocol.BurstLayout
import moire.protocol.BurstLayout.Trigger
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** One burst test case: RAM depth, settings, arm clock, input stream and how often `in` and `out` stall. */
final case class BurstCase(samples: Int, cfg: BurstCfg, armAt: Int, inputs: IndexedSeq[BurstIn], validPct: Int, readyPct: Int, seed: Int)

/** BurstCapture against BurstModel clock by clock, and the model against the burst's definition
  * (the `length` input samples around the first trigger sample once `pre` samples are held).
  */
class BurstCaptureSpec extends AnyFlatSpec with ChiselScalatestTester with Matchers {
  /** A slow motion with a speed ramp, Z once per 37 samples, random codes and flags. */
  private def stream(n: Int, rnd: scala.util.Random): IndexedSeq[BurstIn] = IndexedSeq.tabulate(n) { i =>
    val z = if (i % 37 == 5) 1 else 0
    val word = (rnd.nextInt(1 << BurstLayout.RefZ.lsb)) | (z << BurstLayout.RefZ.lsb)
    BurstIn(word, i * 3 - 100, i / 2 - 7, (if (i % 2 == 0) 1 else -1) * i * 5, 1000L + i)
  }

  private def cases: Seq[BurstCase] = {
    val rnd = new scala.util.Random(15)
    for {
      (samples, length, pre) <- Seq((16, 16L, 0L), (16, 10L, 3L), (32, 32L, 31L), (17, 0L, 0L), (8, 99L, 99L), (64, 40L, 20L))
      mode <- Trigger.named.map(_._1)
    } yield {
      val threshold = if (mode != Trigger.Speed) 0L else if (samples == 64) 405L else 400L // 405: a negative speed equal to it
      BurstCase(samples, BurstCfg(mode, length, pre, threshold, target = 50), armAt = 3 + rnd.nextInt(5),
        stream(260, rnd), validPct = 60 + rnd.nextInt(41), readyPct = 30 + rnd.nextInt(71), seed = rnd.nextInt())
    }
  }

  /** Which input samples `in` accepts at which clock (drawn once, shared by RTL and model). */
  private def schedule(c: BurstCase): IndexedSeq[Option[BurstIn]] = {
    val rnd = new scala.util.Random(c.seed)
    var next = 0
    IndexedSeq.fill(c.inputs.length * 2) {
      if (next < c.inputs.length && rnd.nextInt(100) < c.validPct) { next += 1; Some(c.inputs(next - 1)) } else None
    }
  }

  /** The definition: from the samples seen after arm, the burst words and the two anchors. */
  private def definition(c: BurstCase, seen: IndexedSeq[BurstIn]): (IndexedSeq[Int], Anchor, Anchor) = {
    val p = BurstParams(c.samples)
    val len = p.length(c.cfg.length); val pre = p.pre(c.cfg.pre, len)
    def edge(i: Int, f: BurstIn => Boolean) = i >= 1 && f(seen(i)) && !f(seen(i - 1))
    def hit(i: Int) = c.cfg.mode match {
      case Trigger.Speed => edge(i, s => math.abs(s.speed.toLong) >= c.cfg.threshold)
      case Trigger.RefZ => edge(i, s => ((s.word >> BurstLayout.RefZ.lsb) & 1) == 1)
      case Trigger.Position => i >= 1 && (seen(i).position < c.cfg.target) != (seen(i - 1).position < c.cfg.target)
      case _ => true
    }
    val t = seen.indices.find(i => i >= pre && hit(i)).get
    val burst = seen.slice(t - pre, t - pre + len)
    def a(s: BurstIn) = Anchor(s.index, s.position, s.ref)
    (burst.map(_.word), a(seen(t)), a(burst.last))
  }

  "BurstModel" should "capture the samples around the first trigger, as defined, in every mode" in {
    for (c <- cases) withClue(s"samples ${c.samples}, ${c.cfg}, arm at ${c.armAt}, seed ${c.seed}: ") {
      val m = new BurstModel(BurstParams(c.samples))
      val sched = schedule(c)
      for ((in, t) <- sched.zipWithIndex) m.step(in, if (t == c.armAt) Some(c.cfg) else None)
      m.state shouldBe BurstState.Done
      // the sample at `in` in the arm clock is dropped, the one in the stage register at arm is lost too
      val seen = sched.drop(c.armAt).flatten
      val (words, trig, last) = definition(c, seen)
      m.words shouldBe words
      m.trigger shouldBe trig
      m.last shouldBe last
    }
  }

  "BurstCapture" should "match BurstModel clock by clock and send the burst oldest first under back-pressure" in {
    for ((samples, group) <- cases.groupBy(_.samples).toSeq.sortBy(_._1)) {
      // 32 and 64 samples in banks of 8 words (4 and 8 banks), the others in one; words in groups of 8 bits
      // (4 groups), 5 bits (6, the last of 4) or one group of 29
      val banked = BurstParams(samples, bankWords = if (samples >= 32) 8 else 16384,
        groupBits = samples match { case 16 => BurstLayout.width; case 17 => 5; case _ => 8 })
      test(new BurstCapture(banked)).withAnnotations(moire.cordic.SimSupport.backend) { dut =>
        for (c <- group) withClue(s"samples ${c.samples}, ${c.cfg}, arm at ${c.armAt}, seed ${c.seed}: ") {
          val m = new BurstModel(BurstParams(samples))
          val sched = schedule(c)
          def poke(in: Option[BurstIn], arm: Boolean): Unit = {
            dut.io.in.valid.poke(in.isDefined.B)
            in.foreach { s =>
              dut.io.in.bits.word.poke(s.word.U); dut.io.in.bits.position.poke(s.position.S)
              dut.io.in.bits.refCount.poke(s.ref.S); dut.io.in.bits.speed.poke(s.speed.S); dut.io.in.bits.index.poke(s.index.U)
            }
            dut.io.arm.poke(arm.B)
          }
          dut.io.config.mode.poke(c.cfg.mode.U); dut.io.config.length.poke(c.cfg.length.U)
          dut.io.config.pre.poke(c.cfg.pre.U); dut.io.config.threshold.poke(c.cfg.threshold.U)
          dut.io.config.target.poke(c.cfg.target.S)
          dut.io.read.poke(false.B); dut.io.out.ready.poke(false.B)
          for ((in, t) <- sched.zipWithIndex) {
            poke(in, t == c.armAt)
            m.step(in, if (t == c.armAt) Some(c.cfg) else None)
            dut.clock.step()
            if (t >= c.armAt) dut.io.state.peekInt() shouldBe m.state // the DUT still holds the last case's burst before
          }
          poke(None, arm = false)
          m.state shouldBe BurstState.Done
          dut.io.length.peekInt() shouldBe m.length
          dut.io.pre.peekInt() shouldBe m.pre
          for ((a, b) <- Seq(dut.io.trigger -> m.trigger, dut.io.last -> m.last)) {
            a.index.peekInt() shouldBe b.index; a.position.peekInt() shouldBe b.position; a.refCount.peekInt() shouldBe b.ref
          }
          // read twice: the burst stays until the next arm
          for (_ <- 0 until 2) {
            dut.io.read.poke(true.B); dut.clock.step(); dut.io.read.poke(false.B)
            dut.io.sending.peekBoolean() shouldBe true
            val rnd = new scala.util.Random(c.seed)
            val got = scala.collection.mutable.ArrayBuffer.empty[Int]
            var clocks = 0
            while (dut.io.sending.peekBoolean() && clocks < 10 * samples + 50) {
              val ready = rnd.nextInt(100) < c.readyPct
              dut.io.out.ready.poke(ready.B)
              if (ready && dut.io.out.valid.peekBoolean()) got += dut.io.out.bits.peekInt().toInt
              dut.clock.step(); clocks += 1
            }
            dut.io.out.ready.poke(false.B)
            dut.io.out.valid.peekBoolean() shouldBe false
            got.toSeq shouldBe m.words
          }
        }
      }
    }
  }

  "BurstParams" should "refuse a depth outside 2..2^20 and clamp length and pre-trigger" in {
    an[IllegalArgumentException] should be thrownBy BurstParams(1)
    val p = BurstParams(16)
    (p.length(0), p.length(5), p.length(1L << 31)) shouldBe ((1, 5, 16))
    (p.pre(9, 5), p.pre(3, 5)) shouldBe ((4, 3))
    BurstParams().addrBits shouldBe 16
  }
}
