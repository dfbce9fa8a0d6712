package moire.stream

/** The UART stream format v1 (docs/recording.md): constants shared by the encoder, the decoders and the board. */
object Wire {
  val Sync0: Int = 0xA5
  val Sync1: Int = 0x5A
  val TypeRecords: Int = 0x01
  val TypeReply: Int = 0x02
  val OpRead: Int = 0x52
  val OpWrite: Int = 0x57
  /** Bytes of one record. */
  val RecordBytes: Int = 12
  /** Bytes of a record frame with n records: sync, type, seq, n, dropped, records, CRC. */
  def recordFrameBytes(n: Int): Int = 8 + RecordBytes * n + 2
  val ReplyBytes: Int = 12
  val CommandBytes: Int = 10
  val MaxU32: Long = 0xFFFFFFFFL
}

/** One record: the ADC sample index (u32), the flag/code word (u32) and the datapath position (s32). */
final case class Record(index: Long, word: Long, position: Int) {
  require(index >= 0 && index <= Wire.MaxU32, s"record index must be a u32, got $index")
  require(word >= 0 && word <= Wire.MaxU32, s"record word must be a u32, got $word")
  private def bit(i: Int): Boolean = ((word >> i) & 1) != 0
  /** sin code as on the ADC pins (bits 0-11). */
  def sin: Int = (word & 0xFFF).toInt
  /** cos code as on the ADC pins (bits 12-23). */
  def cos: Int = ((word >> 12) & 0xFFF).toInt
  def otrSin: Boolean = bit(24)
  def otrCos: Boolean = bit(25)
  def present: Boolean = bit(26)
  def overRange: Boolean = bit(27)
  def stepFault: Boolean = bit(28)
  /** true = counting up. */
  def direction: Boolean = bit(29)
}

object Record {
  /** A record from its fields; codes are 12-bit pin patterns. */
  def of(index: Long, sin: Int, cos: Int, position: Int, otrSin: Boolean = false, otrCos: Boolean = false,
         present: Boolean = true, overRange: Boolean = false, stepFault: Boolean = false, direction: Boolean = true): Record = {
    require(sin >= 0 && sin < 4096, s"sin code must be in 0..4095, got $sin")
    require(cos >= 0 && cos < 4096, s"cos code must be in 0..4095, got $cos")
    def b(f: Boolean, i: Int) = if (f) 1L << i else 0L
    Record(index, sin.toLong | (cos.toLong << 12) | b(otrSin, 24) | b(otrCos, 25) | b(present, 26) |
      b(overRange, 27) | b(stepFault, 28) | b(direction, 29), position)
  }
}

/** A board -> host frame. `seq` is the u16 frame counter (+1 per frame of any type). */
sealed trait Frame { def seq: Int }

/** Type 0x01: 1..255 records and the count of records lost to FIFO overflow since the previous record frame. */
final case class RecordFrame(seq: Int, dropped: Int, records: IndexedSeq[Record]) extends Frame {
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(dropped >= 0 && dropped <= 0xFFFF, s"dropped must be a u16, got $dropped")
  require(records.nonEmpty && records.size <= 255, s"a record frame holds 1..255 records, got ${records.size}")
}

/** Type 0x02: the answer to a command, the register's value after it. */
final case class RegisterReply(seq: Int, addr: Int, value: Long) extends Frame {
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(addr >= 0 && addr <= 0xFF, s"addr must be a byte, got $addr")
  require(value >= 0 && value <= Wire.MaxU32, s"value must be a u32, got $value")
}

/** A host -> board command: read (value ignored, sent as 0) or write one register. */
final case class Command(write: Boolean, addr: Int, value: Long = 0) {
  require(addr >= 0 && addr <= 0xFF, s"addr must be a byte, got $addr")
  require(value >= 0 && value <= Wire.MaxU32, s"value must be a u32, got $value")
}
object Command {
  def read(addr: Int): Command = Command(write = false, addr, 0)
  def write(addr: Int, value: Long): Command = Command(write = true, addr, value)
}
