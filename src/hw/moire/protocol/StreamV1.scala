package moire.protocol

/** Stream format v1 (docs/recording.md): the one definition of frames, commands and records that the
  * board RTL (moire.io.FrameTx, moire.io.CommandRx, the DE2-115 core) and the host codec
  * (moire.stream.Encoder, Decoder) share. All multi-byte numbers are little-endian.
  */
object StreamV1 {
  /** Register `version`: 2 = the v1 frames plus burst frames (0x03, 0x04) and records with the reference count
    * (0x05). Hosts read boards of versions 1 and 2; the frame layout of v1 is unchanged.
    */
  val Version: Int = 2
  val ReadableVersions: Seq[Int] = Seq(1, 2)
  val Sync0: Int = 0xA5
  val Sync1: Int = 0x5A
  val TypeRecords: Int = 0x01
  val TypeReply: Int = 0x02
  /** Burst info: length, pre-trigger and the two anchors of a finished burst; then its samples. */
  val TypeBurstInfo: Int = 0x03
  val TypeBurstSamples: Int = 0x04
  /** Record frame whose records also carry the reference encoder's count (boards of version 2 send only these). */
  val TypeRefRecords: Int = 0x05
  val OpRead: Int = 0x52  // 'R'
  val OpWrite: Int = 0x57 // 'W'
  val MaxU32: Long = 0xFFFFFFFFL

  /** The CRC (u16) covers every byte after the sync bytes up to the CRC itself. */
  val CrcFrom: Int = 2
  val CrcBytes: Int = 2

  // ---- board -> host frames: sync, type, seq (u16), then by type ----
  val AtType: Int = 2
  val AtSeq: Int = 3
  /** Header bytes common to both frame types. */
  val HeaderBytes: Int = AtSeq + 2
  /** Record frame: n (u8), dropped (u16), n records. */
  val AtCount: Int = HeaderBytes
  val AtDropped: Int = AtCount + 1
  val AtRecords: Int = AtDropped + 2
  val MaxFrameRecords: Int = 255
  val MaxDropped: Int = 0xFFFF
  /** Register reply: addr (u8), value (u32). */
  val AtReplyAddr: Int = HeaderBytes
  val AtReplyValue: Int = AtReplyAddr + 1
  val ReplyBytes: Int = AtReplyValue + 4 + CrcBytes

  /** Burst info: length (u32), pre (u32), anchors of the trigger and the last sample: index (u32),
    * position (s32), reference count (s32) each.
    */
  val AtBurstLength: Int = HeaderBytes
  val AtBurstPre: Int = AtBurstLength + 4
  val AtBurstTrigger: Int = AtBurstPre + 4
  val AtBurstLast: Int = AtBurstTrigger + 12
  val BurstInfoBytes: Int = AtBurstLast + 12 + CrcBytes
  /** Burst samples: offset of the first within the burst (u32), n (u8), n words (u32, [[BurstLayout]]). */
  val AtBurstOffset: Int = HeaderBytes
  val AtBurstCount: Int = AtBurstOffset + 4
  val AtBurstWords: Int = AtBurstCount + 1
  val MaxBurstWords: Int = 255
  /** Words per burst sample frame the boards send (the last frame of a burst may hold fewer). */
  val BurstFrameWords: Int = 128
  def burstFrameBytes(n: Int): Int = AtBurstWords + 4 * n + CrcBytes

  // ---- host -> board commands: sync, op, addr (u8), value (u32), CRC ----
  val AtOp: Int = 2
  val AtCmdAddr: Int = AtOp + 1
  val AtCmdValue: Int = AtCmdAddr + 1
  val CommandBytes: Int = AtCmdValue + 4 + CrcBytes

  /** One record (byte 0 = bits 7..0): sample index (u32), word (u32), position (s32): 96 bits in frames of
    * type 0x01; in frames of type 0x05 also the reference encoder's count (s32): 128 bits.
    */
  object RecordLayout {
    val Index: Field = Field("index", 0, 32)
    val Word: Field = Index.next("word", 32)
    val Position: Field = Word.next("position", 32)
    val RefCount: Field = Position.next("ref_count", 32)
    val fields: Seq[Field] = Seq(Index, Word, Position)
    val refFields: Seq[Field] = fields :+ RefCount
    val width: Int = Position.msb + 1
    val bytes: Int = width / 8
    val refWidth: Int = RefCount.msb + 1
    val refBytes: Int = refWidth / 8
    /** Bytes of one record in a frame of type `t` (0x01 or 0x05). */
    def bytesOf(t: Int): Int = if (t == TypeRefRecords) refBytes else bytes
    /** Byte offset of a field within the record. */
    def at(f: Field): Int = f.lsb / 8
  }

  /** The record word: ADC codes as on the pins, then the flags, from bit 0 up. */
  object WordLayout {
    val Sin: Field = Field("sin", 0, 12)
    val Cos: Field = Sin.next("cos", 12)
    val OtrSin: Field = Cos.next("otr_sin", 1)
    val OtrCos: Field = OtrSin.next("otr_cos", 1)
    val Present: Field = OtrCos.next("present", 1)
    val OverRange: Field = Present.next("over_range", 1)
    val StepFault: Field = OverRange.next("step_fault", 1)
    /** 1 = counting up. */
    val Direction: Field = StepFault.next("direction", 1)
    /** Sent as zero. */
    val Reserved: Field = Direction.next("reserved", 2)
    val fields: Seq[Field] = Seq(Sin, Cos, OtrSin, OtrCos, Present, OverRange, StepFault, Direction, Reserved)
    require(Reserved.msb + 1 == RecordLayout.Word.width, "the record word must fill its 32 bits")
  }

  /** Bytes of a record frame with n records. */
  def recordFrameBytes(n: Int): Int = AtRecords + RecordLayout.bytes * n + CrcBytes
  /** Bytes of a record frame of type 0x05 with n records. */
  def refRecordFrameBytes(n: Int): Int = AtRecords + RecordLayout.refBytes * n + CrcBytes
}
