package moire.stream

import moire.protocol.{AdaptRegisters, Reg, StreamV1}
import moire.protocol.AdaptRegisters.{Layout, Readout}

/** The adaptive corrector's learned values in a `board-reg --save` file (section `learned`, docs/recording.md): the
  * u32 words of its read-back registers, the harmonic table entry by entry, and a `readout` in codes and degrees for
  * the reader (derived from the words; not read back). `--load` checks that the board has the same corrector
  * (adapt_format, adapt_size), then restores them through the preset registers ([[BoardRegLearned.restore]]).
  */
final case class BoardRegLearned(format: Long, size: Long, layout: Layout, words: Map[Reg, Long], table: Seq[Long]) {
  def readout: Readout = AdaptRegisters.readout(layout, words, table)

  def json: ujson.Obj = {
    val r = readout
    ujson.Obj.from(Seq(AdaptRegisters.Format.name -> ujson.Num(format.toDouble), AdaptRegisters.Size.name -> ujson.Num(size.toDouble)) ++
      AdaptRegisters.learned.map(g => g.name -> ujson.Num(words(g).toDouble)) ++ Seq(
      BoardRegLearned.TableKey -> ujson.Arr.from(table.map(v => ujson.Num(v.toDouble))),
      BoardRegLearned.ReadoutKey -> ujson.Obj("offset_sin_codes" -> r.offsetSinCodes, "offset_cos_codes" -> r.offsetCosCodes,
        "amplitude_sin_codes" -> r.amplitudeSinCodes, "amplitude_cos_codes" -> r.amplitudeCosCodes, "amplitude_ratio_sin_cos" -> r.ratio,
        "phase_error_deg" -> r.phaseErrorDeg, "table_deg" -> ujson.Arr.from(r.tableDeg.map(ujson.Num(_))))))
  }

  /** One line per value that differs between `this` (the file) and `board`, in codes and degrees; Nil when all agree. */
  def differences(board: BoardRegLearned): Seq[String] = {
    val (f, b) = (readout, board.readout)
    val scalars = Seq(("offset_sin", f.offsetSinCodes, b.offsetSinCodes, "codes"), ("offset_cos", f.offsetCosCodes, b.offsetCosCodes, "codes"),
      ("amplitude_sin", f.amplitudeSinCodes, b.amplitudeSinCodes, "codes"), ("amplitude_cos", f.amplitudeCosCodes, b.amplitudeCosCodes, "codes"),
      ("phase_error", f.phaseErrorDeg, b.phaseErrorDeg, "deg")).zip(Seq(AdaptRegisters.OffsetSin, AdaptRegisters.OffsetCos,
      AdaptRegisters.GainSin, AdaptRegisters.GainCos, AdaptRegisters.Phase)).collect {
      case ((n, x, y, u), g) if words(g) != board.words(g) => f"$n $x%.4f $u in the file, $y%.4f $u on the board"
    }
    val entries = table.indices.filter(i => table(i) != board.table(i))
    val worst = entries.map(i => math.abs(f.tableDeg(i) - b.tableDeg(i))).maxOption
    scalars ++ worst.map(w => f"table: ${entries.size} of ${table.size} entries differ, by up to $w%.5f deg")
  }
}

object BoardRegLearned {
  val Key = "learned"
  val TableKey = "adapt_table"
  val ReadoutKey = "readout"

  /** The board's layout: None without a corrector (both words 0). */
  def layout(c: BoardClient, ask: (=> Long) => Long, port: String): Option[(Long, Long, Layout)] = {
    val (f, s) = (ask(c.read(AdaptRegisters.Format)), ask(c.read(AdaptRegisters.Size)))
    Layout.of(f, s).fold(e => throw new StreamError(s"$port: $e"), _.map(l => (f, s, l)))
  }

  /** Reads every learned value and table entry (the index register is put back as it was). The corrector keeps
    * learning meanwhile: a snapshot taken register by register.
    */
  def read(c: BoardClient, ask: (=> Long) => Long, port: String): Option[BoardRegLearned] = layout(c, ask, port).map { case (f, s, l) =>
    val words = AdaptRegisters.learned.map(r => r -> ask(c.read(r))).toMap
    val index = ask(c.read(AdaptRegisters.TableIndex))
    val table = (0 until l.entries).map { i =>
      val got = ask(c.write(AdaptRegisters.TableIndex.addr, i))
      if (got != i) throw new StreamError(s"$port: wrote $i to ${AdaptRegisters.TableIndex.name}, the board kept $got")
      ask(c.read(AdaptRegisters.TableData))
    }
    if (l.entries > 0) ask(c.write(AdaptRegisters.TableIndex.addr, index))
    BoardRegLearned(f, s, l, words, table)
  }

  /** Writes `l` back: holds the corrector (adapt_control bit 0), writes the presets and the table pair by pair, loads
    * them, reads everything back and compares, then puts adapt_control back as it was (learning goes on unless it was
    * held). The update count and the lock are the board's own (not restored). A line on what was done.
    */
  def restore(c: BoardClient, ask: (=> Long) => Long, port: String, l: BoardRegLearned): String = {
    import AdaptRegisters._
    // adapt_control answers with its hold bit only, the presets (write-only) with 0
    def put(r: Reg, v: Long): Unit = {
      val got = ask(c.write(r.addr, v))
      if (got != (if (r == Control) v & 1 else if (writeOnly(r)) 0 else v)) throw new StreamError(f"$port: wrote 0x$v%08x to ${r.name}, the board kept 0x$got%08x: " +
        "a bitstream without adapt_control and the preset registers (0xf4-0xfc)?")
    }
    val before = ask(c.read(Control))
    val index = ask(c.read(TableIndex))
    val hold = 1L << AdaptBit.Hold
    put(Control, hold)
    var done = false
    try {
      for ((r, pr) <- presets) put(pr, l.words(r))
      for (k <- 0 until l.table.size / 2) {
        put(TableIndex, 2L * k); put(PresetEven, l.table(2 * k)); put(PresetOdd, l.table(2 * k + 1))
        put(Control, hold | (1L << AdaptBit.TableWrite))
      }
      put(Control, hold | (1L << AdaptBit.Load))
      if (l.table.nonEmpty) put(TableIndex, index)
      val back = read(c, ask, port).getOrElse(throw new StreamError(s"$port: the corrector's read-back vanished during the load"))
      val sum = if (back.words(TableSum) != l.words(TableSum)) Seq(s"adapt_table_sum ${signed(l.words(TableSum))} in the file, " +
        s"${signed(back.words(TableSum))} on the board") else Nil
      val d = l.differences(back) ++ sum
      if (d.nonEmpty) throw new StreamError(s"$port: the learned values read back differ from the file's after the load: ${d.mkString("; ")}")
      done = true
    } finally {
      // adapt_control as it was; after a failure, the failure is what is reported
      if (done) put(Control, before & hold) else try put(Control, before & hold) catch { case _: Exception => }
    }
    s"restored the corrector's learned values (offsets, gains, phase, ${l.table.size} table entries and their sum), each read back; " +
      (if ((before & hold) != 0) "the corrector stays held, as it was" else "learning goes on from them")
  }

  /** The `learned` section of a file, every word checked. */
  def parse(file: os.Path, v: ujson.Value): BoardRegLearned = {
    val o = v.objOpt.getOrElse(throw new StreamError(s"$file: '$Key' must be an object"))
    def u32(where: String, x: ujson.Value): Long = x.numOpt.filter(y => y == math.rint(y) && y >= 0 && y <= StreamV1.MaxU32).map(_.toLong)
      .getOrElse(throw new StreamError(s"$file: $where must be an integer in 0..${StreamV1.MaxU32}, got ${ujson.write(x).take(30)}"))
    def get(k: String): ujson.Value = o.getOrElse(k, throw new StreamError(s"$file: $Key.$k is missing"))
    val known = Set(AdaptRegisters.Format.name, AdaptRegisters.Size.name, TableKey, ReadoutKey) ++ AdaptRegisters.learned.map(_.name)
    o.keys.find(k => !known.contains(k)).foreach(k => throw new StreamError(
      s"$file: $Key.$k is not a value board-reg saves (${(AdaptRegisters.learned.map(_.name) :+ TableKey).mkString(", ")})"))
    val (f, s) = (u32(s"$Key.${AdaptRegisters.Format.name}", get(AdaptRegisters.Format.name)), u32(s"$Key.${AdaptRegisters.Size.name}", get(AdaptRegisters.Size.name)))
    val l = Layout.of(f, s).fold(e => throw new StreamError(s"$file: $Key: $e"), identity)
      .getOrElse(throw new StreamError(s"$file: $Key: adapt_format and adapt_size are 0 (no corrector)"))
    val words = AdaptRegisters.learned.map(r => r -> u32(s"$Key.${r.name}", get(r.name))).toMap
    val arr = get(TableKey).arrOpt.getOrElse(throw new StreamError(s"$file: $Key.$TableKey must be a list of ${l.entries} entries"))
    if (arr.size != l.entries) throw new StreamError(s"$file: $Key.$TableKey has ${arr.size} entries, adapt_size says ${l.entries}")
    BoardRegLearned(f, s, l, words, arr.zipWithIndex.map { case (x, i) => u32(s"$Key.$TableKey[$i]", x) }.toSeq)
  }
}
