package moire.stream

import moire.protocol.{Registers, StreamV1}

/** `board-reg --save FILE` / `--load FILE`: the registers a board keeps that a user sets (the decimation and the
  * turntable compensator's harmonic slots, `h<slot>_<order|c|phi>`) in one JSON file (docs/recording.md), with the
  * board's model (id, stream version, ADC clock and format, counts per period, records per frame) to check on load.
  * A harmonic register the file does not list is 0 (slot off): load writes every slot, so the board ends as saved.
  * A board with the adaptive corrector adds what it has learned ([[BoardRegLearned]]), restored on load.
  */
object BoardRegFile {
  val Format = "moire-board-registers v1"
  /** The registers that must read the same on the board a file is loaded into. */
  val Model: Seq[moire.protocol.Reg] = Seq(Registers.Id, Registers.Version, Registers.AdcClockHz, Registers.AdcFormat,
    Registers.CountsPerPeriod, Registers.FrameRecords)
  /** The settings saved, besides the harmonic window. */
  val Settings: Seq[moire.protocol.Reg] = Seq(Registers.Decimation)
  /** Harmonic addresses: slots of 4 words (order, c, phi, unused) from [[Registers.HarmonicBase]] up to the burst registers. */
  val Harmonic: Seq[Int] = (Registers.HarmonicBase until Registers.BurstControl.addr).filter(a => ((a - Registers.HarmonicBase) & 3) != 3)

  /** Writes the file; the number of settings, of non-zero harmonic registers, and the learned values (if any). */
  def save(c: BoardClient, file: os.Path, port: String, ask: (=> Long) => Long): (Int, Int, Option[BoardRegLearned]) = {
    val model = Model.map(r => r.name -> ask(c.read(r)))
    val settings = Settings.map(r => r.name -> ask(c.read(r)))
    val harm = Harmonic.map(a => a -> ask(c.read(a))).filter(_._2 != 0)
    val learned = BoardRegLearned.read(c, ask, port)
    val j = ujson.Obj("format" -> Format, "saved_utc" -> java.time.Instant.now().toString, "port" -> port,
      "model" -> ujson.Obj.from(model.map { case (k, v) => k -> ujson.Num(v.toDouble) }),
      "registers" -> ujson.Obj.from((settings ++ harm.map { case (a, v) => Registers.name(a) -> v }).map { case (k, v) => k -> ujson.Num(v.toDouble) }))
    learned.foreach(l => j(BoardRegLearned.Key) = l.json)
    moire.files.SafeWrite.madeText(file, ujson.write(j, indent = 2) + "\n")
    (settings.size, harm.size, learned)
  }

  /** What a file holds: the model, the register writes (every harmonic register, 0 where the file lists none) and the
    * corrector's learned values if it has them.
    */
  final case class Saved(model: Map[String, Long], writes: Seq[(Int, Long)], learned: Option[BoardRegLearned])

  def read(file: os.Path): Saved = {
    moire.files.PathKind.notAFile(file).foreach(m => throw new StreamError(m))
    val j = try moire.options.StrictJson.read(os.read(file)) catch { case e: Exception => throw new StreamError(s"$file: not valid JSON (${e.getMessage.linesIterator.next().take(80)})") }
    val o = j.objOpt.getOrElse(throw new StreamError(s"$file: expected a JSON object"))
    val fmt = o.get("format").flatMap(_.strOpt)
    if (!fmt.contains(Format)) throw new StreamError(s"$file: format is ${fmt.getOrElse("missing")}, expected '$Format' (written by board-reg --save)")
    def u32(where: String, v: ujson.Value): Long = v.numOpt.filter(x => x == math.rint(x) && x >= 0 && x <= StreamV1.MaxU32).map(_.toLong)
      .getOrElse(throw new StreamError(s"$file: $where must be an integer in 0..${StreamV1.MaxU32}, got ${ujson.write(v).take(30)}"))
    val model = o.get("model").flatMap(_.objOpt).getOrElse(throw new StreamError(s"$file: no 'model' object"))
    val m = Model.map(r => r.name -> u32(s"model.${r.name}", model.getOrElse(r.name, throw new StreamError(s"$file: model.${r.name} is missing")))).toMap
    val regs = o.get("registers").flatMap(_.objOpt).getOrElse(throw new StreamError(s"$file: no 'registers' object"))
    val inFile = regs.toSeq.map { case (k, v) =>
      val a = Registers.parse(k).toOption.filter(a => Settings.exists(_.addr == a) || Harmonic.contains(a))
        .getOrElse(throw new StreamError(s"$file: registers.$k is not a setting board-reg saves (${Settings.map(_.name).mkString(", ")}, h<slot>_<order|c|phi>)"))
      a -> u32(s"registers.$k", v)
    }.toMap
    Settings.foreach(r => if (!inFile.contains(r.addr)) throw new StreamError(s"$file: registers.${r.name} is missing"))
    // the values --write would refuse are refused here too, before the port is opened
    inFile.get(Registers.Decimation.addr).foreach(d => if (d < 1 || d > Registers.MaxDecimation)
      throw new StreamError(s"$file: registers.${Registers.Decimation.name} must be in 1..${Registers.MaxDecimation}, got $d"))
    val known = Set("format", "saved_utc", "port", "model", "registers", BoardRegLearned.Key)
    o.keys.find(k => !known.contains(k)).foreach(k => throw new StreamError(s"$file: '$k' is not a key board-reg saves (${known.mkString(", ")})"))
    Saved(m, Settings.map(r => r.addr -> inFile(r.addr)) ++ Harmonic.map(a => a -> inFile.getOrElse(a, 0L)),
      o.get(BoardRegLearned.Key).map(BoardRegLearned.parse(file, _)))
  }

  /** Checks the model (and the corrector's layout when the file has learned values), then writes and reads back each
    * register; the number of non-zero harmonic registers and a line on the learned values (None: neither side has any).
    */
  def load(c: BoardClient, file: os.Path, port: String, ask: (=> Long) => Long): (Int, Option[String]) = {
    val Saved(model, writes, learned) = read(file)
    val differ = Model.flatMap { r => val b = ask(c.read(r)); if (b != model(r.name)) Some(s"${r.name} ${model(r.name)} in the file, $b on the board") else None }
    val onBoard = BoardRegLearned.layout(c, ask, port)
    val layoutDiffers = learned.toSeq.flatMap { l => onBoard match {
      case None => Seq("the adaptive corrector's learned values in the file, no corrector read-back on the board (adapt_format 0)")
      case Some((bf, bs, _)) => Seq((moire.protocol.AdaptRegisters.Format, l.format, bf), (moire.protocol.AdaptRegisters.Size, l.size, bs)).collect {
        case (r, x, y) if x != y => f"${r.name} 0x$x%08x in the file, 0x$y%08x on the board" }
    } }
    if (differ.nonEmpty || layoutDiffers.nonEmpty)
      throw new StreamError(s"$file was saved from another kind of board: ${(differ ++ layoutDiffers).mkString("; ")}; nothing written")
    for ((a, v) <- writes) {
      val got = ask(c.write(a, v))
      if (got != v) throw new StreamError(f"$port: wrote 0x$v%08x to ${Registers.name(a)}, the board kept 0x$got%08x" +
        (if (a >= Registers.HarmonicBase) ": is the harmonic compensator in the design, with enough slots?" else ""))
    }
    val note = (learned, onBoard) match {
      case (Some(l), Some(_)) =>
        Some(BoardRegLearned.restore(c, ask, port, l))
      case (None, Some(_)) => Some("the file holds no learned values (saved from a board without the corrector's read-back)")
      case _ => None
    }
    (writes.count { case (a, v) => a >= Registers.HarmonicBase && v != 0 }, note)
  }
}
