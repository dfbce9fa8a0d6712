package moire.stream

import moire.protocol.Crc16
import moire.protocol.StreamV1._

/** Frames and commands to bytes, exactly as stream format v1 (moire.protocol.StreamV1) puts them on the wire.
  * This is the bit-accurate model the board's framing RTL is checked against.
  */
object Encoder {
  /** A message of `n` bytes: sync bytes first, fields at their offsets, the CRC last. */
  private final class Out(n: Int) {
    val a = new Array[Byte](n)
    u8(0, Sync0); u8(1, Sync1)
    def u8(at: Int, v: Int): Unit = a(at) = v.toByte
    def u16(at: Int, v: Int): Unit = { u8(at, v); u8(at + 1, v >> 8) }
    def u32(at: Int, v: Long): Unit = { u16(at, (v & 0xFFFF).toInt); u16(at + 2, ((v >> 16) & 0xFFFF).toInt) }
    /** Writes the CRC of everything after the sync bytes. */
    def crc(): Array[Byte] = { u16(n - CrcBytes, Crc16.of(a, CrcFrom, n - CrcBytes - CrcFrom)); a }
  }

  def frame(f: Frame): Array[Byte] = f match {
    case r: RecordFrame =>
      val t = r.frameType
      val size = RecordLayout.bytesOf(t)
      val o = new Out(AtRecords + size * r.records.size + CrcBytes)
      o.u8(AtType, t); o.u16(AtSeq, r.seq); o.u8(AtCount, r.records.size); o.u16(AtDropped, r.dropped)
      for ((x, k) <- r.records.zipWithIndex) {
        val at = AtRecords + size * k
        o.u32(at + RecordLayout.at(RecordLayout.Index), x.index)
        o.u32(at + RecordLayout.at(RecordLayout.Word), x.word)
        o.u32(at + RecordLayout.at(RecordLayout.Position), x.position.toLong & MaxU32)
        x.ref.foreach(v => o.u32(at + RecordLayout.at(RecordLayout.RefCount), v.toLong & MaxU32))
      }
      o.crc()
    case b: BurstInfo =>
      val o = new Out(BurstInfoBytes)
      o.u8(AtType, TypeBurstInfo); o.u16(AtSeq, b.seq); o.u32(AtBurstLength, b.length); o.u32(AtBurstPre, b.pre)
      for ((a, at) <- Seq(b.trigger -> AtBurstTrigger, b.last -> AtBurstLast)) {
        o.u32(at, a.index); o.u32(at + 4, a.position.toLong & MaxU32); o.u32(at + 8, a.ref.toLong & MaxU32)
      }
      o.crc()
    case b: BurstSamples =>
      val o = new Out(burstFrameBytes(b.words.size))
      o.u8(AtType, TypeBurstSamples); o.u16(AtSeq, b.seq); o.u32(AtBurstOffset, b.offset); o.u8(AtBurstCount, b.words.size)
      for ((w, k) <- b.words.zipWithIndex) o.u32(AtBurstWords + 4 * k, w)
      o.crc()
    case r: RegisterReply =>
      val o = new Out(ReplyBytes)
      o.u8(AtType, TypeReply); o.u16(AtSeq, r.seq); o.u8(AtReplyAddr, r.addr); o.u32(AtReplyValue, r.value)
      o.crc()
  }

  def frames(fs: Iterable[Frame]): Array[Byte] = fs.iterator.flatMap(frame(_).iterator).toArray

  def command(c: Command): Array[Byte] = {
    val o = new Out(CommandBytes)
    o.u8(AtOp, if (c.write) OpWrite else OpRead); o.u8(AtCmdAddr, c.addr); o.u32(AtCmdValue, c.value)
    o.crc()
  }
}
