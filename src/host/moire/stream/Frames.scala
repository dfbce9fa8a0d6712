package moire.stream

import moire.protocol.{Field, StreamV1}
import moire.protocol.StreamV1.{WordLayout => W}

/** One record: the ADC sample index (u32), the flag/code word (u32), the datapath position (s32) and, in
  * frames of type 0x05, the reference encoder's count (s32).
  */
final case class Record(index: Long, word: Long, position: Int, ref: Option[Int] = None) {
  require(index >= 0 && index <= StreamV1.MaxU32, s"record index must be a u32, got $index")
  require(word >= 0 && word <= StreamV1.MaxU32, s"record word must be a u32, got $word")
  private def bit(f: Field): Boolean = f.get(word) != 0
  /** sin code as on the ADC pins. */
  def sin: Int = W.Sin.get(word).toInt
  /** cos code as on the ADC pins. */
  def cos: Int = W.Cos.get(word).toInt
  def otrSin: Boolean = bit(W.OtrSin)
  def otrCos: Boolean = bit(W.OtrCos)
  def present: Boolean = bit(W.Present)
  def overRange: Boolean = bit(W.OverRange)
  def stepFault: Boolean = bit(W.StepFault)
  /** true = counting up. */
  def direction: Boolean = bit(W.Direction)
}

object Record {
  /** A record from its fields; codes are 12-bit pin patterns. */
  def of(index: Long, sin: Int, cos: Int, position: Int, otrSin: Boolean = false, otrCos: Boolean = false,
         present: Boolean = true, overRange: Boolean = false, stepFault: Boolean = false, direction: Boolean = true): Record = {
    def code(f: Field, v: Int) = {
      require(v >= 0 && v <= f.maxValue, s"${f.name} code must be in 0..${f.maxValue}, got $v")
      f.put(v)
    }
    def b(flag: Boolean, f: Field) = if (flag) f.put(1) else 0L
    Record(index, code(W.Sin, sin) | code(W.Cos, cos) | b(otrSin, W.OtrSin) | b(otrCos, W.OtrCos) | b(present, W.Present) |
      b(overRange, W.OverRange) | b(stepFault, W.StepFault) | b(direction, W.Direction), position)
  }
}

/** A board -> host frame. `seq` is the u16 frame counter (+1 per frame of any type). */
sealed trait Frame { def seq: Int }

/** Type 0x01 (records without) or 0x05 (records with the reference count): 1..255 records and the count of
  * records lost to FIFO overflow since the previous record frame.
  */
final case class RecordFrame(seq: Int, dropped: Int, records: IndexedSeq[Record]) extends Frame {
  require(records.forall(_.ref.isDefined) || records.forall(_.ref.isEmpty), "records of one frame all carry the reference count or none does")
  /** The frame type these records go in. */
  def frameType: Int = if (records.headOption.exists(_.ref.isDefined)) StreamV1.TypeRefRecords else StreamV1.TypeRecords
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(dropped >= 0 && dropped <= 0xFFFF, s"dropped must be a u16, got $dropped")
  require(records.nonEmpty && records.size <= StreamV1.MaxFrameRecords, s"a record frame holds 1..${StreamV1.MaxFrameRecords} records, got ${records.size}")
}

/** Type 0x02: the answer to a command, the register's value after it. */
final case class RegisterReply(seq: Int, addr: Int, value: Long) extends Frame {
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(addr >= 0 && addr <= 0xFF, s"addr must be a byte, got $addr")
  require(value >= 0 && value <= StreamV1.MaxU32, s"value must be a u32, got $value")
}

/** Type 0x03: a finished burst's length, pre-trigger count and anchors (trigger sample = burst sample `pre`). */
final case class BurstInfo(seq: Int, length: Long, pre: Long, trigger: moire.io.Anchor, last: moire.io.Anchor) extends Frame {
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(length >= 1 && length <= StreamV1.MaxU32 && pre >= 0 && pre < length, s"burst length $length, pre $pre: need 0 <= pre < length <= u32")
}

/** Type 0x04: 1..255 burst sample words ([[moire.protocol.BurstLayout]]) from sample `offset` of the burst on. */
final case class BurstSamples(seq: Int, offset: Long, words: IndexedSeq[Long]) extends Frame {
  require(seq >= 0 && seq <= 0xFFFF, s"seq must be a u16, got $seq")
  require(offset >= 0 && offset <= StreamV1.MaxU32, s"burst offset must be a u32, got $offset")
  require(words.nonEmpty && words.size <= StreamV1.MaxBurstWords, s"a burst frame holds 1..${StreamV1.MaxBurstWords} words, got ${words.size}")
}

/** A host -> board command: read (value ignored, sent as 0) or write one register. */
final case class Command(write: Boolean, addr: Int, value: Long = 0) {
  require(addr >= 0 && addr <= 0xFF, s"addr must be a byte, got $addr")
  require(value >= 0 && value <= StreamV1.MaxU32, s"value must be a u32, got $value")
}
object Command {
  def read(addr: Int): Command = Command(write = false, addr, 0)
  def write(addr: Int, value: Long): Command = Command(write = true, addr, value)
}
