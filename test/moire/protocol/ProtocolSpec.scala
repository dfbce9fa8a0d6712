package moire.protocol

import chisel3._
import chisel3.experimental.BundleLiterals._
import chiseltest._
import moire.stream.{Encoder, Record, RecordFrame}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers
import StreamV1.{RecordLayout, WordLayout}

/** The record Bundles sit where StreamV1's layout says, the hardware CRC is the Scala one, and the
  * host encoder puts every field at its StreamV1 offset.
  */
class ProtocolSpec extends AnyFlatSpec with ChiselScalatestTester with Matchers {
  /** Bundle element name of a layout field: camelCase, and `direction` is `up` (Data.direction is taken). */
  private def element(f: Field): String =
    if (f.name == "direction") "up" else f.name.split('_').toSeq match { case h +: t => h + t.map(_.capitalize).mkString }

  private def at(d: Data, path: Seq[String]): Data = path.foldLeft(d)((x, n) => x.asInstanceOf[chisel3.Record].elements(n))

  /** A literal of `gen` with the leaf at `path` all ones and every other leaf zero, as a number. */
  private def onesAt[T <: Bundle](gen: => T, leaves: Seq[Seq[String]], path: Seq[String]): BigInt = {
    val t = gen
    val lits = leaves.map { p => (b: T) =>
      val e = at(b, p)
      val w = e.getWidth
      val v = if (p == path) (BigInt(1) << w) - 1 else BigInt(0)
      e -> (e match {
        case _: Bool => (v != 0).B
        case _: SInt => (if (v == 0) BigInt(0) else BigInt(-1)).S(w.W)
        case _ => v.U(w.W)
      })
    }
    t.Lit(lits: _*).litValue
  }

  private val wordLeaves = WordLayout.fields.map(f => Seq(element(f)))
  private val recordLeaves = Seq(Seq("index"), Seq("position"), Seq("refCount")) ++ wordLeaves.map("word" +: _)

  "RecordWord" should "have one element per StreamV1.WordLayout field, in its place" in {
    (new RecordWord).elements.keySet shouldBe wordLeaves.map(_.head).toSet
    (new RecordWord).getWidth shouldBe RecordLayout.Word.width
    for (f <- WordLayout.fields) withClue(f.name) {
      onesAt(new RecordWord, wordLeaves, Seq(element(f))) shouldBe f.mask
    }
  }

  "StreamRecord" should "put index, word, position and reference count where StreamV1.RecordLayout says" in {
    (new StreamRecord).getWidth shouldBe RecordLayout.refWidth
    for ((f, e) <- Seq(RecordLayout.Index -> "index", RecordLayout.Position -> "position", RecordLayout.RefCount -> "refCount")) withClue(f.name) {
      onesAt(new StreamRecord, recordLeaves, Seq(e)) shouldBe f.mask
    }
    for (f <- WordLayout.fields) withClue(f.name) {
      onesAt(new StreamRecord, recordLeaves, Seq("word", element(f))) shouldBe (f.mask << RecordLayout.Word.lsb)
    }
  }

  "the record layout" should "be what the encoder sends: index, word, position little-endian" in {
    val r = Record(0x04030201L, 0x08070605L, 0x0C0B0A09)
    val b = Encoder.frame(RecordFrame(0, 0, IndexedSeq(r)))
    b.slice(StreamV1.AtRecords, StreamV1.AtRecords + RecordLayout.bytes).toSeq shouldBe (1 to 12).map(_.toByte)
    b.length shouldBe StreamV1.recordFrameBytes(1)
    b(StreamV1.AtType) shouldBe StreamV1.TypeRecords.toByte
    // with the reference count: type 0x05, 16 bytes per record
    val rb = Encoder.frame(RecordFrame(0, 0, IndexedSeq(r.copy(ref = Some(0x100F0E0D)))))
    rb(StreamV1.AtType) shouldBe StreamV1.TypeRefRecords.toByte
    rb.slice(StreamV1.AtRecords, StreamV1.AtRecords + RecordLayout.refBytes).toSeq shouldBe (1 to 16).map(_.toByte)
    rb.length shouldBe StreamV1.refRecordFrameBytes(1)
    new moire.stream.Decoder(1).feed(rb) shouldBe Vector(RecordFrame(0, 0, IndexedSeq(r.copy(ref = Some(0x100F0E0D)))))
    // the word's fields as the host reads them
    val w = Record.of(0, sin = 0xABC, cos = 0x123, position = 0, otrSin = true, present = false, direction = false)
    WordLayout.Sin.get(w.word) shouldBe 0xABC
    WordLayout.Cos.get(w.word) shouldBe 0x123
    (w.otrSin, w.otrCos, w.present, w.direction) shouldBe ((true, false, false, false))
    w.word shouldBe (0xABCL | (0x123L << 12) | (1L << 24))
  }

  private class CrcStep extends Module {
    val io = IO(new Bundle {
      val crc = Input(UInt(16.W)); val byte = Input(UInt(8.W)); val out = Output(UInt(16.W))
    })
    io.out := Crc16.next(io.crc, io.byte)
  }

  "Crc16.next" should "be Crc16.step in hardware, for every byte" in {
    test(new CrcStep) { c =>
      val rnd = new scala.util.Random(11)
      for (crc <- Seq(Crc16.Init, 0, 0x8000, 0x1021) ++ Seq.fill(4)(rnd.nextInt(1 << 16)); b <- 0 until 256) {
        c.io.crc.poke(crc.U); c.io.byte.poke(b.U)
        c.io.out.expect(Crc16.step(crc, b).U, f"crc 0x$crc%04x byte 0x$b%02x")
      }
    }
  }
}
