package moire.adapt

import chisel3._
import moire.protocol.AdaptRegisters

/** What the corrector has learned, in its own number formats ([[AdaptParams]]): offsets, gains, phase term, estimate
  * updates since reset (saturating at 2^32 - 1), the PLL's lock (the table adapts only while locked), the harmonic
  * table and its sum. [[AdaptModel.learned]] gives it; the board reads the same values by register (AdaptRegisters).
  */
final case class AdaptLearned(offsetSin: Long, offsetCos: Long, gainSin: Long, gainCos: Long, phase: Long, updates: Long,
                              locked: Boolean, tableSum: Long, table: Seq[Long]) {
  /** The read-only registers' u32 values, table excluded (it is read entry by entry through adapt_table_data). */
  def words: Seq[(moire.protocol.Reg, Long)] = {
    import AdaptRegisters._
    Seq(OffsetSin -> offsetSin, OffsetCos -> offsetCos, GainSin -> gainSin, GainCos -> gainCos, Phase -> phase,
      Updates -> updates, Locked -> (if (locked) 1L else 0L), TableSum -> tableSum).map { case (r, v) => r -> AdaptRegisters.u32(v) }
  }
  /** Table entries as adapt_table_data reads them. */
  def tableWords: Seq[Long] = table.map(AdaptRegisters.u32)
}

object AdaptLearned {
  val MaxUpdates: Long = 0xFFFFFFFFL
  /** adapt_format and adapt_size of a corrector. */
  def format(p: AdaptParams): Long = AdaptRegisters.formatWord(p.offsetFrac, p.gainFrac, p.phaseFrac, p.fineBits)
  def size(p: AdaptParams): Long = AdaptRegisters.sizeWord(p.inputBits, p.outputBits, p.harmonicEntries)
}

/** The corrector's read-back port (AdaptiveCorrector with `withReadBack`): the learned values, each a register, and
  * the harmonic table entry at `tableIndex` (three clocks after the index; 0 without a table).
  */
class AdaptReadBackIO(p: AdaptParams) extends Bundle {
  val learned = Output(new Bundle {
    val offsetSin = SInt(p.offsetWidth.W)
    val offsetCos = SInt(p.offsetWidth.W)
    val gainSin = SInt(p.gainBits.W)
    val gainCos = SInt(p.gainBits.W)
    val phase = SInt(p.phaseBits.W)
    val updates = UInt(32.W)
    val locked = Bool()
    val tableSum = SInt((p.tableBits + p.tableIndexBits).W)
    val tableData = SInt(p.tableBits.W)
  })
  val tableIndex = Input(UInt(math.max(p.tableIndexBits, 1).W))
}

/** The corrector's preset port (AdaptiveCorrector with `withReadBack`), every input from a register of the register file:
  * `hold` stops its loops (estimates, statistics, PLL, table: the correction goes on with the values held); with hold,
  * the strobe `load` puts the preset offsets, gains, phase term and table sum into the loops' registers, and the strobe
  * `tableWrite` writes entries 2 `pair` and 2 `pair` + 1 (`even`, `odd`) through the table's write port.
  */
class AdaptPresetIO(p: AdaptParams) extends Bundle {
  val hold = Input(Bool())
  val load = Input(Bool())
  val offsetSin = Input(SInt(p.offsetWidth.W))
  val offsetCos = Input(SInt(p.offsetWidth.W))
  val gainSin = Input(SInt(p.gainBits.W))
  val gainCos = Input(SInt(p.gainBits.W))
  val phase = Input(SInt(p.phaseBits.W))
  val tableSum = Input(SInt((p.tableBits + p.tableIndexBits).W))
  val tableWrite = Input(Bool())
  val pair = Input(UInt(math.max(p.tableIndexBits - 1, 1).W))
  val even = Input(SInt(p.tableBits.W))
  val odd = Input(SInt(p.tableBits.W))
}
