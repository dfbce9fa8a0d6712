package moire.stream

import moire.io.Anchor
import moire.protocol.{Registers, StreamV1}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Burst frames (types 0x03, 0x04) through Encoder and Decoder, mixed with v1 record frames and replies. */
class BurstFramesSpec extends AnyFlatSpec with Matchers {
  private def burst(seq0: Int, length: Int, pre: Int, perFrame: Int, rnd: scala.util.Random): Vector[Frame] = {
    val words = IndexedSeq.fill(length)(rnd.nextInt(1 << 29).toLong)
    val info = BurstInfo(seq0, length, pre, Anchor(0xFFFFFFF0L, -5, Int.MinValue), Anchor(7, Int.MaxValue, -1))
    info +: words.grouped(perFrame).zipWithIndex.map { case (ws, k) => BurstSamples(seq0 + 1 + k, k.toLong * perFrame, ws) }.toVector
  }

  private def decode(a: Array[Byte], chunk: Int): (Vector[Frame], StreamStats) = {
    val d = new Decoder(1)
    val out = a.grouped(chunk).flatMap(c => d.feed(c)).toVector ++ d.finish()
    (out, d.stats)
  }

  "Decoder" should "give back burst frames between record frames and replies, in any chunking, and count them" in {
    val rnd = new scala.util.Random(15)
    for ((length, perFrame) <- Seq((1, 1), (300, 255), (1000, 64)); chunk <- Seq(1, 7, 4096)) withClue(s"length $length, $perFrame per frame, chunks of $chunk: ") {
      val recs = RecordFrame(0, 0, IndexedSeq(Record(10, 0x123, -3), Record(11, 0x456, -2)))
      val b = burst(1, length, length / 3, perFrame, rnd)
      val after = RegisterReply(1 + b.size, Registers.BurstState.addr, 3)
      val fs = recs +: b :+ after
      val (out, st) = decode(Encoder.frames(fs), chunk)
      out shouldBe fs
      st.burstInfos shouldBe 1; st.burstFrames shouldBe b.size - 1; st.burstSamples shouldBe length
      st.burstGaps shouldBe 0; st.lost shouldBe false; st.crcErrors shouldBe 0; st.badHeaders shouldBe 0
      st.records shouldBe 2; st.dropped shouldBe 0
    }
  }

  it should "count a lost burst frame as a gap with its samples missing" in {
    val b = burst(0, 100, 0, 10, new scala.util.Random(1))
    val fs = b.patch(4, Nil, 1) // frame with offset 30 lost
    val (out, st) = decode(Encoder.frames(fs), 13)
    out shouldBe fs
    st.burstGaps shouldBe 1; st.burstMissing shouldBe 10; st.seqGaps shouldBe 1; st.lost shouldBe true
  }

  it should "lay a burst frame out as StreamV1 says, byte for byte" in {
    val a = Encoder.frame(BurstSamples(0x0102, 0x0A0B0C0DL, IndexedSeq(0x1FFFFFFFL)))
    a.length shouldBe StreamV1.burstFrameBytes(1)
    a.take(12).map(_ & 0xFF).toSeq shouldBe Seq(0xA5, 0x5A, 0x04, 0x02, 0x01, 0x0D, 0x0C, 0x0B, 0x0A, 1, 0xFF, 0xFF)
    Encoder.frame(BurstInfo(0, 5, 1, Anchor(1, 2, 3), Anchor(4, 5, 6))).length shouldBe StreamV1.BurstInfoBytes
  }

  "Registers" should "name the burst registers, apart from the v1 table and the harmonic window" in {
    Registers.parse("burst_length") shouldBe Right(0xE2)
    Registers.name(0xE6) shouldBe "burst_state"
    Registers.writable(Registers.BurstControl.addr) shouldBe true
    Registers.writable(Registers.BurstState.addr) shouldBe false
    (Registers.all ++ Registers.burst).map(_.addr).distinct.size shouldBe Registers.all.size + Registers.burst.size
  }
}
