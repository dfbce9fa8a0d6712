package moire.protocol

/** One board register (u32). */
final case class Reg(addr: Int, name: String, writable: Boolean, doc: String)

/** The board's register table (stream format v1, docs/recording.md), the one place that names them;
  * the board's register file (moire.board.de2115.BoardCore) and `board-reg` both read it.
  */
object Registers {
  /** Samples per speed measurement for the speed trigger: speed = position change over this many samples. */
  val SpeedWindow: Int = 1024
  val Id: Reg = Reg(0x00, "id", false, "0x4D4F4952 \"MOIR\"")
  val Version: Reg = Reg(0x01, "version", false, "stream format version (2: v1 frames + burst and reference-count records)")
  val Status: Reg = Reg(0x02, "status", false, "sticky flags: bit0 overspeed, 1 over_range, 2 step_fault, 3 fifo_overflow, 4 otr_sin, 5 otr_cos; bit8 present (live)")
  val Control: Reg = Reg(0x03, "control", true, "bit0 stream enable (default 1), bit1 clear sticky status")
  val Decimation: Reg = Reg(0x04, "decimation", true, "D, one record every D ADC samples, 1..2^24")
  val DroppedTotal: Reg = Reg(0x05, "dropped_total", false, "records lost to FIFO overflow since reset")
  val CmdErrors: Reg = Reg(0x06, "cmd_errors", false, "commands ignored for a bad CRC")
  val Position: Reg = Reg(0x07, "position", false, "live datapath position, counts, two's complement")
  val AdcClockHz: Reg = Reg(0x08, "adc_clock_hz", false, "ADC sample clock in Hz")
  val FrameRecords: Reg = Reg(0x09, "frame_records", false, "n, records per record frame")
  val CountsPerPeriod: Reg = Reg(0x0A, "counts_per_period", false, "M, counts per grating period")
  val EncoderCount: Reg = Reg(0x0B, "encoder_count", false, "quadrature count of the encoder inputs A/B, two's complement")
  val EncoderZCount: Reg = Reg(0x0C, "encoder_z_count", false, "encoder_count latched at the last Z edge")
  val AdcFormat: Reg = Reg(0x0D, "adc_format", false, "0 offset binary, 1 two's complement")
  /** Register `id`: "MOIR". */
  val IdValue: Long = 0x4D4F4952L
  /** Bits of `status`: sticky flags and the live `present`. */
  object StatusBit {
    val Overspeed = 0; val OverRange = 1; val StepFault = 2; val FifoOverflow = 3; val OtrSin = 4; val OtrCos = 5
    val Present = 8
    val named: Seq[(Int, String)] = Seq(Overspeed -> "overspeed", OverRange -> "over_range", StepFault -> "step_fault",
      FifoOverflow -> "fifo_overflow", OtrSin -> "otr_sin", OtrCos -> "otr_cos", Present -> "present")
  }
  /** Bits of `control`: stream enable, clear the sticky status flags. */
  object ControlBit { val Enable = 0; val Clear = 1 }
  /** Largest decimation D (the smallest is 1). */
  val MaxDecimation: Long = 1L << 24
  /** Values of `adc_format`. */
  val AdcOffsetBinary: Int = 0
  val AdcTwosComplement: Int = 1
  val all: Seq[Reg] = Seq(Id, Version, Status, Control, Decimation, DroppedTotal, CmdErrors, Position, AdcClockHz,
    FrameRecords, CountsPerPeriod, EncoderCount, EncoderZCount, AdcFormat)

  /** Burst capture (moire.io.BurstCapture), above the harmonic slots in use. */
  val BurstControl: Reg = Reg(0xE0, "burst_control", true, "write bit0 arm (latches the burst registers), bit1 send the finished burst")
  val BurstTrigger: Reg = Reg(0xE1, "burst_trigger", true, "0 now, 1 |speed| rises to burst_threshold, 2 reference Z edge, 3 position crosses burst_target")
  val BurstLength: Reg = Reg(0xE2, "burst_length", true, "N, samples per burst, 1..burst depth")
  val BurstPre: Reg = Reg(0xE3, "burst_pre", true, "samples before the trigger sample, 0..N-1")
  val BurstThreshold: Reg = Reg(0xE4, "burst_threshold", true, s"speed threshold, counts per $SpeedWindow samples")
  val BurstTarget: Reg = Reg(0xE5, "burst_target", true, "trigger position, counts, two's complement")
  val BurstState: Reg = Reg(0xE6, "burst_state", false, "0 idle, 1 waiting for the trigger, 2 capturing, 3 done; bit2 sending")
  val BurstDepth: Reg = Reg(0xE7, "burst_depth", false, "largest burst length N the board holds")
  val burst: Seq[Reg] = Seq(BurstControl, BurstTrigger, BurstLength, BurstPre, BurstThreshold, BurstTarget, BurstState, BurstDepth)
  /** Bits of `burst_control`. */
  object BurstControlBit { val Arm = 0; val Send = 1 }
  /** Bit of `burst_state` set while the burst is being sent. */
  val BurstSendingBit: Int = 2

  /** The adaptive corrector's read-back, above the burst registers (design corrected). */
  val adapt: Seq[Reg] = AdaptRegisters.all

  private def known: Seq[Reg] = all ++ burst ++ adapt

  /** First address of the harmonic-coefficient window: 0x10 + slot*4 + {0 order, 1 c_k, 2 phi_k}. */
  val HarmonicBase: Int = 0x10
  val HarmonicFields: Seq[String] = Seq("order", "c", "phi")
  private val harmName = """h(\d+)_(order|c|phi)""".r

  /** Name of an address: a table name, `h<slot>_<order|c|phi>` in the harmonic window, else hex. */
  def name(addr: Int): String = known.find(_.addr == addr).map(_.name).getOrElse {
    val w = addr - HarmonicBase
    if (w >= 0 && (w & 3) < 3) s"h${w >> 2}_${HarmonicFields(w & 3)}" else f"0x$addr%02x"
  }

  def writable(addr: Int): Boolean = known.find(_.addr == addr).fold(addr >= HarmonicBase)(_.writable)

  /** A register named by table name, `h<slot>_<field>`, or an address (0x.. hex or decimal), 0..255. */
  def parse(s: String): Either[String, Int] = {
    val t = s.trim
    def inRange(v: Long) = if (v >= 0 && v <= 0xFF) Right(v.toInt) else Left(s"register address $t is outside 0x00..0xff")
    known.find(_.name == t).map(r => Right(r.addr)).getOrElse(t match {
      case harmName(slot, f) if slot.length <= 2 => inRange(HarmonicBase + slot.toLong * 4 + HarmonicFields.indexOf(f))
      case _ if t.startsWith("0x") || t.startsWith("0X") =>
        hex(t.drop(2)).map(inRange)
          .getOrElse(Left(s"register '$t' is not a hex address"))
      case _ => moire.numbers.Decimal.long(t).map(inRange).getOrElse(Left(
        s"register '$t' is unknown; names: ${known.map(_.name).mkString(", ")}, h<slot>_<order|c|phi>, or an address like 0x04"))
    })
  }

  /** Hex digits 0-9, a-f (without 0x), or None: Java's parseLong took other scripts' digits too (`--write decimation=٣`
    * wrote 3; `--read ٣` read address 3), which every other number of moire refuses.
    */
  def hex(s: String): Option[Long] =
    if (s.nonEmpty && s.forall(c => (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')))
      scala.util.Try(java.lang.Long.parseLong(s, 16)).toOption else None

  /** A u32 value given as decimal, 0x hex, or a negative decimal (two's complement). */
  def parseValue(s: String): Either[String, Long] = {
    val t = s.trim
    val v = if (t.startsWith("0x") || t.startsWith("0X")) hex(t.drop(2))
      else moire.numbers.Decimal.long(t).map(x => if (x < 0 && x >= Int.MinValue) x & StreamV1.MaxU32 else x)
    v.filter(x => x >= 0 && x <= StreamV1.MaxU32).toRight(s"value '$t' is not a u32 (decimal, negative decimal or 0x hex)")
  }
}
