package moire.io

import chisel3._
import chisel3.util._
import chiseltest._
import moire.protocol.{BurstLayout, RegReply, StreamRecord, StreamV1}
import moire.protocol.StreamV1.RecordLayout
import moire.stream.{BurstInfo, BurstSamples, Command, CommandDecoder, Encoder, Record, RecordFrame, RegisterReply}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** FrameTx fed with packed records as the board's FIFO holds them (asTypeOf at the port, as BoardCore does). */
class FrameTxPacked(n: Int) extends Module {
  val io = IO(new Bundle {
    val records = Flipped(Decoupled(UInt(RecordLayout.refWidth.W)))
    val recordCount = Input(UInt(8.W))
    val dropped = Input(Bool())
    val reply = Flipped(Decoupled(new RegReply))
    val burstInfo = Flipped(Decoupled(new BurstInfoBits))
    val burstWords = Flipped(Decoupled(UInt(BurstLayout.width.W)))
    val out = Decoupled(UInt(8.W))
  })
  private val tx = Module(new FrameTx(n, 8))
  tx.io.burstInfo <> io.burstInfo
  tx.io.burstWords <> io.burstWords
  tx.io.records.valid := io.records.valid
  tx.io.records.bits := io.records.bits.asTypeOf(new StreamRecord)
  io.records.ready := tx.io.records.ready
  tx.io.recordCount := io.recordCount
  tx.io.dropped := io.dropped
  tx.io.reply <> io.reply
  io.out <> tx.io.out
}

/** The framing RTL against the host codec, byte for byte: FrameTx's output is Encoder's, and
  * CommandRx takes what Encoder.command sends as CommandDecoder does.
  */
class FramingSpec extends AnyFlatSpec with ChiselScalatestTester with Matchers {
  private def packed(r: Record): BigInt =
    (BigInt(r.index) << RecordLayout.Index.lsb) | (BigInt(r.word) << RecordLayout.Word.lsb) |
      (BigInt(r.position.toLong & 0xFFFFFFFFL) << RecordLayout.Position.lsb) |
      (BigInt(r.ref.get.toLong & 0xFFFFFFFFL) << RecordLayout.RefCount.lsb)

  private def idle(c: FrameTxPacked): Unit = {
    c.io.recordCount.poke(0.U); c.io.records.valid.poke(false.B); c.io.reply.valid.poke(false.B)
    c.io.burstInfo.valid.poke(false.B); c.io.burstWords.valid.poke(false.B)
  }

  "FrameTx" should "send exactly Encoder's bytes: a reply, then record frames with the dropped count" in {
    for (n <- Seq(1, 3)) withClue(s"n = $n: ") {
      val rnd = new scala.util.Random(n)
      val recs = IndexedSeq.fill(3 * n)(Record(rnd.nextInt() & 0xFFFFFFFFL, rnd.nextInt() & 0xFFFFFFFFL, rnd.nextInt(), Some(rnd.nextInt())))
      val reply = RegisterReply(0, 0x0A, 0xDEADBEEFL)
      val expected = Encoder.frames(reply +: recs.grouped(n).zipWithIndex.map { case (rs, k) =>
        RecordFrame(k + 1, if (k == 0) 5 else 0, rs) }.toSeq).toSeq
      test(new FrameTxPacked(n)) { c =>
        val got = scala.collection.mutable.ArrayBuffer.empty[Byte]
        def clock(): Unit = {
          if (c.io.out.valid.peekBoolean() && c.io.out.ready.peekBoolean()) got += c.io.out.bits.peekInt().toByte
          c.clock.step()
        }
        idle(c)
        c.io.dropped.poke(true.B)
        for (_ <- 0 until 5) clock() // five records lost before the first record frame
        c.io.dropped.poke(false.B)
        c.io.reply.valid.poke(true.B); c.io.reply.bits.addr.poke(reply.addr.U); c.io.reply.bits.value.poke(reply.value.U)
        while (!c.io.reply.ready.peekBoolean()) clock()
        clock()
        c.io.reply.valid.poke(false.B)
        var next = 0
        var cycles = 0
        while (got.size < expected.size && cycles < 20000) {
          c.io.out.ready.poke((rnd.nextInt(4) != 0).B) // the UART is not always ready
          c.io.recordCount.poke((recs.size - next).U)
          c.io.records.valid.poke((next < recs.size).B)
          if (next < recs.size) c.io.records.bits.poke(packed(recs(next)).U(RecordLayout.refWidth.W))
          val take = next < recs.size && c.io.records.ready.peekBoolean()
          clock(); cycles += 1
          if (take) next += 1
        }
        got.toSeq shouldBe expected
      }
    }
  }

  it should "send a burst as Encoder does: the info frame, then sample frames of 128 words, records paused meanwhile" in {
    val rnd = new scala.util.Random(7)
    val len = 300 // frames of 128, 128, 44 words
    val words = IndexedSeq.fill(len)(rnd.nextInt(1 << BurstLayout.width).toLong)
    val info = BurstInfo(0, len, 17, Anchor(1000, -5, 77), Anchor(1299, 40, -3))
    val rec = Record(5, 6, 7, Some(-8))
    val frames = Seq(info) ++ words.grouped(StreamV1.BurstFrameWords).zipWithIndex.map { case (ws, k) =>
      BurstSamples(k + 1, k.toLong * StreamV1.BurstFrameWords, ws) } :+ RecordFrame(4, 0, IndexedSeq(rec))
    val expected = Encoder.frames(frames).toSeq
    test(new FrameTxPacked(1)) { c =>
      val got = scala.collection.mutable.ArrayBuffer.empty[Byte]
      idle(c); c.io.dropped.poke(false.B)
      c.io.burstInfo.valid.poke(true.B)
      c.io.burstInfo.bits.length.poke(len.U); c.io.burstInfo.bits.pre.poke(17.U)
      for ((a, p) <- Seq(info.trigger -> c.io.burstInfo.bits.trigger, info.last -> c.io.burstInfo.bits.last)) {
        p.index.poke(a.index.U); p.position.poke(a.position.S); p.refCount.poke(a.ref.S)
      }
      var next = 0; var cycles = 0; var infoTaken = false
      while (got.size < expected.size && cycles < 40000) {
        c.io.out.ready.poke((rnd.nextInt(3) != 0).B)
        // a record waits from the start: it must come after the whole burst
        c.io.recordCount.poke(1.U); c.io.records.valid.poke(true.B); c.io.records.bits.poke(packed(rec).U(RecordLayout.refWidth.W))
        val wordValid = next < len && rnd.nextInt(4) != 0 // the burst RAM is not always ready
        c.io.burstWords.valid.poke(wordValid.B)
        if (next < len) c.io.burstWords.bits.poke(words(next).U)
        if (c.io.burstInfo.ready.peekBoolean()) infoTaken = true
        val take = wordValid && c.io.burstWords.ready.peekBoolean()
        if (c.io.out.valid.peekBoolean() && c.io.out.ready.peekBoolean()) got += c.io.out.bits.peekInt().toByte
        c.clock.step(); cycles += 1
        if (infoTaken) c.io.burstInfo.valid.poke(false.B)
        if (take) next += 1
      }
      got.toSeq shouldBe expected
    }
  }

  "CommandRx" should "take Encoder's commands as CommandDecoder does, and flag a bad CRC" in {
    val cmds = Seq(Command.read(0x04), Command.write(0x03, 3), Command.write(0x10, 0x89ABCDEFL))
    val bad = Encoder.command(Command.read(0x00)); bad(5) = (bad(5) ^ 0x40).toByte
    val bytes = Array[Byte](0x5A, 0xA5.toByte, 0x00) ++ Encoder.command(cmds(0)) ++ bad ++ cmds.tail.flatMap(Encoder.command)
    val host = new CommandDecoder
    host.feed(bytes) shouldBe cmds
    host.errors shouldBe 1
    test(new CommandRx) { c =>
      val seen = scala.collection.mutable.ArrayBuffer.empty[Command]
      var errors = 0
      def clock(): Unit = {
        if (c.io.cmd.valid.peekBoolean())
          seen += Command(c.io.cmd.bits.write.peekBoolean(), c.io.cmd.bits.addr.peekInt().toInt, c.io.cmd.bits.value.peekInt().toLong)
        if (c.io.error.peekBoolean()) errors += 1
        c.clock.step()
      }
      for (b <- bytes) {
        c.io.in.valid.poke(true.B); c.io.in.bits.poke((b & 0xFF).U); clock()
        c.io.in.valid.poke(false.B); clock(); clock()
      }
      seen.toSeq shouldBe cmds
      errors shouldBe 1
    }
  }
}
