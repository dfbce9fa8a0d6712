package moire.protocol

/** The adaptive corrector's read-back registers (board design `corrected` only; other designs read 0 there): what it
  * has learned, in its own fixed-point formats, which `adapt_format` and `adapt_size` describe, and the harmonic table
  * through an index register and a data register. Read-only except `adapt_table_index`, `adapt_control` and the presets (0xf5-0xfc, write-only), which restore learned values. Formats: docs/board-de2-115.md.
  */
object AdaptRegisters {
  val OffsetSin: Reg = Reg(0xE8, "adapt_offset_sin", false, "sin offset, ADC codes with adapt_format.offset_frac fractional bits, two's complement")
  val OffsetCos: Reg = Reg(0xE9, "adapt_offset_cos", false, "cos offset, the same format")
  val GainSin: Reg = Reg(0xEA, "adapt_gain_sin", false, "sin gain, output LSB per ADC code with adapt_format.gain_frac fractional bits")
  val GainCos: Reg = Reg(0xEB, "adapt_gain_cos", false, "cos gain, the same format")
  val Phase: Reg = Reg(0xEC, "adapt_phase", false, "tan of the cos channel's phase error, adapt_format.phase_frac fractional bits, two's complement")
  val Updates: Reg = Reg(0xED, "adapt_updates", false, "offset/gain/phase updates since reset (one per closed window), saturating")
  val Locked: Reg = Reg(0xEE, "adapt_locked", false, "1 while the PLL is locked (the table adapts only then, and above its minimum speed)")
  val TableSum: Reg = Reg(0xEF, "adapt_table_sum", false, "sum of the table entries (their mean is subtracted when the table is applied)")
  val TableIndex: Reg = Reg(0xF0, "adapt_table_index", true, "entry adapt_table_data shows, 0..entries-1 (higher bits ignored)")
  val TableData: Reg = Reg(0xF1, "adapt_table_data", false, "table entry at adapt_table_index, 2^-fine_bits signal period, two's complement")
  val Format: Reg = Reg(0xF2, "adapt_format", false, "bits 0-7 offset_frac, 8-15 gain_frac, 16-23 phase_frac, 24-31 fine_bits; 0: no corrector")
  val Size: Reg = Reg(0xF3, "adapt_size", false, "bits 0-7 ADC bits, 8-15 output bits, 16-31 table entries; 0: no corrector")
  val Control: Reg = Reg(0xF4, "adapt_control", true, "bit0 hold (estimates, statistics, PLL and table stand still; the correction goes on); with hold, write bit1 = load the presets into the corrector, bit2 = write the preset pair; reads bit0")
  val PresetOffsetSin: Reg = Reg(0xF5, "adapt_preset_offset_sin", true, "preset of adapt_offset_sin (its format), loaded by adapt_control bit1")
  val PresetOffsetCos: Reg = Reg(0xF6, "adapt_preset_offset_cos", true, "preset of adapt_offset_cos")
  val PresetGainSin: Reg = Reg(0xF7, "adapt_preset_gain_sin", true, "preset of adapt_gain_sin")
  val PresetGainCos: Reg = Reg(0xF8, "adapt_preset_gain_cos", true, "preset of adapt_gain_cos")
  val PresetPhase: Reg = Reg(0xF9, "adapt_preset_phase", true, "preset of adapt_phase")
  val PresetTableSum: Reg = Reg(0xFA, "adapt_preset_table_sum", true, "preset of adapt_table_sum")
  val PresetEven: Reg = Reg(0xFB, "adapt_preset_even", true, "table entry 2k, k = adapt_table_index / 2, written by adapt_control bit2")
  val PresetOdd: Reg = Reg(0xFC, "adapt_preset_odd", true, "table entry 2k + 1, written with adapt_preset_even")
  /** Bits of adapt_control. */
  object AdaptBit { val Hold = 0; val Load = 1; val TableWrite = 2 }
  /** The presets (write-only: they read 0, and a write answers 0; what they loaded reads back at 0xe8-0xf1). */
  val writeOnly: Set[Reg] = Set(PresetOffsetSin, PresetOffsetCos, PresetGainSin, PresetGainCos, PresetPhase, PresetTableSum, PresetEven, PresetOdd)
  /** The presets of the learned values, by the register each restores. */
  val presets: Seq[(Reg, Reg)] = Seq(OffsetSin -> PresetOffsetSin, OffsetCos -> PresetOffsetCos, GainSin -> PresetGainSin,
    GainCos -> PresetGainCos, Phase -> PresetPhase, TableSum -> PresetTableSum)
  /** The learned values besides the table (saved by `board-reg --save`). */
  val learned: Seq[Reg] = Seq(OffsetSin, OffsetCos, GainSin, GainCos, Phase, Updates, Locked, TableSum)
  val all: Seq[Reg] = learned ++ Seq(TableIndex, TableData, Format, Size, Control) ++ presets.map(_._2) ++ Seq(PresetEven, PresetOdd)

  def u32(v: Long): Long = v & StreamV1.MaxU32
  def signed(v: Long): Long = if (v >= (1L << 31)) v - (1L << 32) else v

  def formatWord(offsetFrac: Int, gainFrac: Int, phaseFrac: Int, fineBits: Int): Long =
    offsetFrac.toLong | (gainFrac.toLong << 8) | (phaseFrac.toLong << 16) | (fineBits.toLong << 24)
  def sizeWord(inputBits: Int, outputBits: Int, entries: Int): Long = inputBits.toLong | (outputBits.toLong << 8) | (entries.toLong << 16)

  /** adapt_format and adapt_size decoded. */
  final case class Layout(offsetFrac: Int, gainFrac: Int, phaseFrac: Int, fineBits: Int, inputBits: Int, outputBits: Int, entries: Int)
  object Layout {
    /** None when both read 0 (no corrector); Left for words no corrector makes. */
    def of(format: Long, size: Long): Either[String, Option[Layout]] =
      if (format == 0 && size == 0) Right(None) else {
        def b(w: Long, k: Int) = ((w >> (8 * k)) & 0xFF).toInt
        val l = Layout(b(format, 0), b(format, 1), b(format, 2), b(format, 3), b(size, 0), b(size, 1), (size >> 16).toInt)
        val e = l.entries
        if (l.inputBits < 8 || l.inputBits > 16 || l.outputBits < l.inputBits || l.outputBits > 18 || l.offsetFrac < 1 ||
          l.gainFrac < 1 || l.phaseFrac < 1 || l.fineBits < 12 || (e != 0 && (e & (e - 1)) != 0))
          Left(f"adapt_format 0x$format%08x / adapt_size 0x$size%08x do not describe a corrector")
        else Right(Some(l))
      }
  }

  /** The learned values in the units a bench engineer reads (from the registers' u32 words and the layout). */
  final case class Readout(offsetSinCodes: Double, offsetCosCodes: Double, amplitudeSinCodes: Double, amplitudeCosCodes: Double,
                           phaseErrorDeg: Double, tableDeg: Seq[Double]) {
    /** sin amplitude over cos amplitude. */
    def ratio: Double = amplitudeSinCodes / amplitudeCosCodes
  }
  /** `words` by register (every one of [[learned]]) and the table's u32 words, in entry order. */
  def readout(l: Layout, words: Map[Reg, Long], table: Seq[Long]): Readout = {
    def s(r: Reg) = signed(words(r)).toDouble
    val r = math.pow(2, l.outputBits - 1) / math.sqrt(2) // output amplitude the gains aim at
    def amp(g: Reg) = r / (s(g) / math.pow(2, l.gainFrac))
    val mean = if (table.isEmpty) 0.0 else s(TableSum) / table.size
    Readout(s(OffsetSin) / math.pow(2, l.offsetFrac), s(OffsetCos) / math.pow(2, l.offsetFrac), amp(GainSin), amp(GainCos),
      math.toDegrees(math.atan(s(Phase) / math.pow(2, l.phaseFrac))), table.map(w => (signed(w) - mean) * 360 / math.pow(2, l.fineBits)))
  }
}
