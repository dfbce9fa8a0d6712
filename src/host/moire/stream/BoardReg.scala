package moire.stream

import moire.calibration.CoefficientFile
import moire.protocol.{AdaptRegisters, Registers, StreamV1}

/** `moire board-reg`: read and write the board's registers by name, load harmonic coefficients. */
object BoardReg {
  final case class Options(port: String, baud: Int = 115200, reads: Seq[String] = Nil, writes: Seq[String] = Nil,
                           coefficients: Option[String] = None, timeoutMs: Int = 500, save: Option[String] = None,
                           load: Option[String] = None)

  private def parseWrite(s: String): (Int, Long) = s.split("=", 2) match {
    case Array(n, v) =>
      val a = Registers.parse(n).fold(e => throw new StreamError(s"--write $s: $e"), identity)
      if (!Registers.writable(a)) throw new StreamError(
        s"--write $s: ${Registers.name(a)} is read-only; writable: ${Registers.all.filter(_.writable).map(_.name).mkString(", ")}, h<slot>_<order|c|phi>")
      val x = Registers.parseValue(v).fold(e => throw new StreamError(s"--write $s: $e"), identity)
      // the decimation as record, board and monitor take it (0 or 2^32 - 1 would stop or starve the stream)
      if (a == Registers.Decimation.addr && (x < 1 || x > Registers.MaxDecimation))
        throw new StreamError(s"--write $s: decimation must be in 1..${Registers.MaxDecimation}, got ${if (v.trim.startsWith("-")) v.trim else x}")
      a -> x
    case _ => throw new StreamError(s"--write '$s' must be NAME=VALUE, like decimation=100")
  }

  /** Load first (model check, then every saved register), then writes (in the order given), then coefficients,
    * then reads, then save; with none of them, reads the whole table.
    */
  def run(o: Options, say: String => Unit): Unit = {
    val loadFile = o.load.map(os.Path(_, os.pwd))
    loadFile.foreach(BoardRegFile.read) // a bad file fails before the port is opened
    val saveFile = o.save.map(os.Path(_, os.pwd))
    saveFile.foreach(moire.files.SafeWrite.checkMade)
    val writes = o.writes.map(parseWrite)
    // the same register written twice in one command: the first value would be lost at once
    writes.groupBy(_._1).collectFirst { case (a, ws) if ws.size > 1 =>
      throw new StreamError(s"--write ${Registers.name(a)} is given ${ws.size} times (${o.writes.filter(w => parseWrite(w)._1 == a).map("'" + _ + "'").mkString(", ")}); write each register once") }
    val reads = o.reads.map(r => Registers.parse(r).fold(e => throw new StreamError(s"--read: $e"), identity))
    val coefs = o.coefficients.map(f => loadCoefficients(os.Path(f, os.pwd)))
    if (o.baud < 300 || o.baud > 12000000) throw new StreamError(s"--baud must be in 300..12000000, got ${o.baud}")
    if (o.timeoutMs < 10 || o.timeoutMs > 60000) throw new StreamError(s"--timeout-ms must be in 10..60000, got ${o.timeoutMs}")
    val link = SerialLink.open(o.port, o.baud)
    try {
      val c = new BoardClient(link, o.timeoutMs)
      BoardClient.check(c, o.baud, "")
      def ask[T](f: => T): T = try f catch { case e: NoAnswer => throw new StreamError(e.getMessage) }
      for (f <- loadFile) {
        val (h, learned) = BoardRegFile.load(c, f, o.port, ask(_))
        say(s"loaded $f: ${BoardRegFile.Settings.map(_.name).mkString(", ")} and ${BoardRegFile.Harmonic.size} harmonic registers ($h not zero), each read back")
        learned.foreach(say)
      }
      for ((a, v) <- writes) {
        val got = ask(c.write(a, v))
        say(s"wrote ${line(a, got)}")
        if (got != v && !AdaptRegisters.writeOnly.exists(_.addr == a))
          throw new StreamError(f"${o.port}: wrote 0x$v%08x to ${Registers.name(a)}, the board kept 0x$got%08x")
      }
      for ((ws, file) <- coefs.zip(o.coefficients)) {
        for ((a, v) <- ws) {
          val got = ask(c.write(a, v))
          if (got != v) throw new StreamError(f"${o.port}: wrote 0x$v%08x to ${Registers.name(a)} (0x$a%02x), the board kept 0x$got%08x: " +
            "is the harmonic compensator in the design, with enough slots?")
        }
        say(s"loaded ${ws.size} harmonic registers (0x${"%02x".format(ws.map(_._1).min)}..0x${"%02x".format(ws.map(_._1).max)}) from $file, each read back")
      }
      val whole = reads.isEmpty && writes.isEmpty && coefs.isEmpty && loadFile.isEmpty && saveFile.isEmpty
      val toRead = if (whole) Registers.all.map(_.addr) else reads
      toRead.foreach(a => say(line(a, ask(c.read(a)))))
      // the whole table of a board with the corrector: its learned values too, and what they mean
      if (whole) BoardRegLearned.layout(c, ask(_), o.port).foreach { case (_, _, l) =>
        val words = AdaptRegisters.learned.map(r => r -> ask(c.read(r))).toMap
        AdaptRegisters.learned.foreach(r => say(line(r.addr, words(r))))
        val ro = AdaptRegisters.readout(l, words, Nil)
        say(f"corrector: offsets ${ro.offsetSinCodes}%.2f / ${ro.offsetCosCodes}%.2f codes, amplitudes ${ro.amplitudeSinCodes}%.1f / " +
          f"${ro.amplitudeCosCodes}%.1f codes (sin/cos ${ro.ratio}%.4f), phase error ${ro.phaseErrorDeg}%.3f deg; table: --save")
      }
      for (f <- saveFile) {
        val (s, h, learned) = BoardRegFile.save(c, f, o.port, ask(_))
        say(s"saved $f: $s setting(s), $h non-zero harmonic register(s) of ${BoardRegFile.Harmonic.size}, " +
          learned.fold("and the board's model")(l => s"the corrector's learned values (${l.table.size} table entries) and the board's model"))
      }
    } finally link.close()
  }

  /** One register as a line: address, name, decimal, hex and what it means. */
  def line(addr: Int, v: Long): String = {
    val signed = if (v >= (1L << 31)) v - (1L << 32) else v
    val note = addr match {
      case Registers.Id.addr => new String(Array(24, 16, 8, 0).map(s => ((v >> s) & 0xFF).toByte), "ISO-8859-1").filter(ch => ch >= ' ' && ch < 127)
      case Registers.Status.addr => Registers.StatusBit.named.collect { case (b, n) if ((v >> b) & 1) != 0 => n }.mkString(" ")
      case Registers.Control.addr => if (((v >> Registers.ControlBit.Enable) & 1) != 0) "stream on" else "stream off"
      case Registers.Position.addr | Registers.EncoderCount.addr | Registers.EncoderZCount.addr |
           AdaptRegisters.OffsetSin.addr | AdaptRegisters.OffsetCos.addr | AdaptRegisters.Phase.addr |
           AdaptRegisters.TableSum.addr | AdaptRegisters.TableData.addr => s"signed $signed"
      case Registers.AdcFormat.addr => v match {
        case Registers.AdcOffsetBinary => "offset-binary"; case Registers.AdcTwosComplement => "twos-complement"; case _ => "unknown"
      }
      case _ => ""
    }
    f"0x$addr%02x ${Registers.name(addr)}%-18s $v%10d  0x$v%08x  $note".trim
  }

  /** Register writes of a coefficient file from `calibrate`: `.coefficients.json` or the `addr data` hex listing.
    * Addresses in the file are within the harmonic window; the board's are [[Registers.HarmonicBase]] + them.
    */
  def loadCoefficients(path: os.Path): Seq[(Int, Long)] = {
    moire.files.PathKind.notAFile(path).foreach(m => throw new StreamError(m))
    // a binary file's bytes were told back raw in the error about its first line
    moire.files.Shown.binaryKind(path).foreach(k => throw new StreamError(
      s"$path: is $k; a coefficient file from calibrate is JSON (.coefficients.json) or text (.registers.txt); it starts with '${moire.files.Shown.head(path, 16)}'"))
    // (a byte-order mark, as editors on Windows write, passed over: it was "'\ufeff0x10' is not a hex number")
    val text = try os.read(path).stripPrefix("\uFEFF") catch { case e: java.io.IOException => throw new StreamError(s"$path: cannot read (${e.getMessage})") }
    def place(where: String, a: Long, d: Long): (Int, Long) = {
      // the window ends where the burst registers start (0xe0): above it, burst_control and the corrector's presets
      val top = Registers.BurstControl.addr - Registers.HarmonicBase - 1
      if (a < 0 || a > top) throw new StreamError(s"$where: window address $a is outside 0..$top (the harmonic window, 0x${"%02x".format(Registers.HarmonicBase)}..0x${"%02x".format(Registers.BurstControl.addr - 1)} on the board)")
      if (d < 0 || d > StreamV1.MaxU32) throw new StreamError(s"$where: data $d is not a u32")
      (Registers.HarmonicBase + a.toInt) -> d
    }
    def hex(where: String, s: String): Long = Registers.hex(s.trim.stripPrefix("0x").stripPrefix("0X"))
      .getOrElse(throw new StreamError(s"$where: '${moire.files.Shown.text(s)}' is not a hex number"))
    val ws = if (text.trim.startsWith("{")) {
      val j = try moire.options.StrictJson.read(text) catch { case e: Exception => throw new StreamError(s"$path: not valid JSON (${e.getMessage.linesIterator.next()})") }
      val fmt = j.obj.get("format").flatMap(_.strOpt)
      if (!fmt.contains(CoefficientFile.format)) throw new StreamError(s"$path: format is ${fmt.fold("missing")(f => s"'${moire.files.Shown.text(f)}'")}, expected '${CoefficientFile.format}'")
      val regs = j.obj.get("registers").flatMap(_.arrOpt).getOrElse(throw new StreamError(s"$path: no 'registers' list"))
      regs.zipWithIndex.map { case (r, i) =>
        val where = s"$path: registers[$i]"
        val o = r.objOpt.getOrElse(throw new StreamError(s"$where: expected an object {\"addr\": N, \"data\": \"0x...\"}, got ${ujson.write(r).take(40)}"))
        val a = o.get("addr").flatMap(_.numOpt).filter(v => v == math.rint(v)).getOrElse(throw new StreamError(s"$where: 'addr' missing or not an integer"))
        val d = o.get("data").flatMap(_.strOpt).getOrElse(throw new StreamError(s"$where: 'data' missing"))
        place(where, a.toLong, hex(where, d))
      }.toSeq
    } else text.linesIterator.zipWithIndex.flatMap { case (l, i) =>
      val body = l.takeWhile(_ != '#').trim
      if (body.isEmpty) None
      else body.split("\\s+") match {
        case Array(a, d) => val w = s"$path:${i + 1}"; Some(place(w, hex(w, a), hex(w, d)))
        case _ => throw new StreamError(s"$path:${i + 1}: expected 'addr data' in hex, got '${moire.files.Shown.text(l, 40)}'")
      }
    }.toSeq
    if (ws.isEmpty) throw new StreamError(s"$path: no register writes in the file")
    ws.groupBy(_._1).collectFirst { case (a, xs) if xs.size > 1 => a }.foreach(a =>
      throw new StreamError(s"$path: window address ${a - Registers.HarmonicBase} is written twice (which value is meant?)"))
    ws
  }
}
