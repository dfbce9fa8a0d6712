package moire.stream

/** Frames and commands to bytes, exactly as stream format v1 puts them on the wire.
  * This is the bit-accurate model the board's framing RTL is checked against.
  */
object Encoder {
  private final class Out(n: Int) {
    val a = new Array[Byte](n); var at = 0
    def u8(v: Int): Unit = { a(at) = v.toByte; at += 1 }
    def u16(v: Int): Unit = { u8(v); u8(v >> 8) }
    def u32(v: Long): Unit = { u16((v & 0xFFFF).toInt); u16(((v >> 16) & 0xFFFF).toInt) }
    /** Appends the CRC of everything after the sync bytes. */
    def crc(): Array[Byte] = { u16(Crc16.of(a, 2, at - 2)); require(at == a.length); a }
  }

  def frame(f: Frame): Array[Byte] = f match {
    case r: RecordFrame =>
      val o = new Out(Wire.recordFrameBytes(r.records.size))
      o.u8(Wire.Sync0); o.u8(Wire.Sync1); o.u8(Wire.TypeRecords); o.u16(r.seq); o.u8(r.records.size); o.u16(r.dropped)
      r.records.foreach { x => o.u32(x.index); o.u32(x.word); o.u32(x.position.toLong & Wire.MaxU32) }
      o.crc()
    case r: RegisterReply =>
      val o = new Out(Wire.ReplyBytes)
      o.u8(Wire.Sync0); o.u8(Wire.Sync1); o.u8(Wire.TypeReply); o.u16(r.seq); o.u8(r.addr); o.u32(r.value)
      o.crc()
  }

  def frames(fs: Iterable[Frame]): Array[Byte] = fs.iterator.flatMap(frame(_).iterator).toArray

  def command(c: Command): Array[Byte] = {
    val o = new Out(Wire.CommandBytes)
    o.u8(Wire.Sync0); o.u8(Wire.Sync1); o.u8(if (c.write) Wire.OpWrite else Wire.OpRead); o.u8(c.addr); o.u32(c.value)
    o.crc()
  }
}
