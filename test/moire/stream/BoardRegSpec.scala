package moire.stream

import moire.MoireError
import moire.cli.CliProcess
import moire.harmonic.HarmonicParams
import moire.calibration.{CoefficientFile, Harmonic, HarmonicFitResult}
import moire.protocol.Registers
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class BoardRegSpec extends AnyFlatSpec with Matchers {
  private def run(pty: PtyPair, o: BoardReg.Options => BoardReg.Options): Vector[String] = {
    val lines = Vector.newBuilder[String]
    BoardReg.run(o(BoardReg.Options(pty.host.toString, timeoutMs = 2000)), lines += _)
    lines.result()
  }

  "board-reg" should "read the whole table by default, decoding ids, flags and formats" in PtyPair { pty =>
    val board = new FakeBoard(pty, FakeBoard.registers() + (Registers.Status.addr -> 0x109L))
    val out = try run(pty, o => o) finally board.close()
    out.map(_.split("\\s+")(1)) shouldBe Registers.all.map(_.name)
    out.head shouldBe "0x00 id                 1297041746  0x4d4f4952  MOIR"
    out.find(_.contains("status")).get should endWith("overspeed fifo_overflow present")
    out.find(_.contains(" position ")).get should endWith("signed -16")
    out.find(_.contains("adc_format")).get should endWith("offset-binary")
  }

  it should "write by name, then read back, and refuse read-only registers before sending anything" in PtyPair { pty =>
    val board = new FakeBoard(pty, FakeBoard.registers())
    val out = try run(pty, _.copy(writes = Seq("decimation=0x64", "control=3"), reads = Seq("decimation", "0x03", "h0_c")))
      finally board.close()
    board.registers(Registers.Decimation.addr) shouldBe 100
    out(0) should startWith("wrote 0x04 decimation                100  0x00000064")
    out.drop(2).map(_.split("\\s+").take(3).mkString(" ")) shouldBe Seq("0x04 decimation 100", "0x03 control 3", "0x11 h0_c 0")
    val e = intercept[MoireError](run(pty, _.copy(writes = Seq("status=1"))))
    e.getMessage should include("status is read-only")
    intercept[MoireError](run(pty, _.copy(reads = Seq("speed")))).getMessage should include("register 'speed' is unknown")
    board.commands.count(_.write) shouldBe 2
  }

  private val hp = HarmonicParams(harmonics = 3)
  private val fit = HarmonicFitResult(0.5, Seq(Harmonic(1, 12.5, 30.0), Harmonic(4, 2.25, -100.0)), Seq(0.1, -0.1))

  it should "load a coefficient file from calibrate (JSON or listing) into the harmonic window and check it" in PtyPair { pty =>
    val dir = pty.dir / "cal"
    os.write(dir / "t.coefficients.json", ujson.write(CoefficientFile.json(hp, "t.csv", fit, Nil)), createFolders = true)
    os.write(dir / "t.registers.txt", CoefficientFile.listing(hp, fit))
    val expected = CoefficientFile.writes(hp, CoefficientFile.slots(hp, fit)).map { case (a, v) => (0x10 + a) -> v }
    expected.size shouldBe 9
    for (f <- Seq("t.coefficients.json", "t.registers.txt")) {
      val board = new FakeBoard(pty, FakeBoard.registers(), harmonicSlots = 3)
      val out = try run(pty, _.copy(coefficients = Some((dir / f).toString))) finally board.close()
      out.last shouldBe s"loaded 9 harmonic registers (0x10..0x1a) from ${dir / f}, each read back"
      expected.foreach { case (a, v) => board.registers(a) shouldBe v }
      BoardReg.loadCoefficients(dir / f) shouldBe expected
    }
    // a board with one slot keeps 0 in slot 1: an error naming the register
    val small = new FakeBoard(pty, FakeBoard.registers(), harmonicSlots = 1)
    val e = try intercept[MoireError](run(pty, _.copy(coefficients = Some((dir / "t.registers.txt").toString)))) finally small.close()
    e.getMessage should include("h1_order (0x14), the board kept 0x00000000")
  }

  it should "name the file and line of a bad coefficient file" in {
    val f = os.temp("# moire harmonic registers\n00 00000001\n01 zz\n")
    intercept[MoireError](BoardReg.loadCoefficients(f)).getMessage shouldBe s"$f:3: 'zz' is not a hex number"
    val j = os.temp("""{"format": "other"}""")
    intercept[MoireError](BoardReg.loadCoefficients(j)).getMessage should include("expected 'moire-harmonic-coefficients v1'")
  }

  "moire board-reg (command line)" should "read a register by name" in PtyPair { pty =>
    val board = new FakeBoard(pty, FakeBoard.registers())
    val (code, out, err) = try CliProcess.run("board-reg", "--port", pty.host.toString, "--read", "adc_clock_hz", "--read", "0x0a")
      finally board.close()
    withClue(err) { code shouldBe 0 }
    out.linesIterator.map(_.split("\\s+").take(3).mkString(" ")).toSeq shouldBe Seq("0x08 adc_clock_hz 40000000", "0x0a counts_per_period 1024")
  }

  "board-reg --save / --load" should "keep and restore the decimation and the harmonic slots, and refuse another kind of board" in PtyPair { pty =>
    val dir = os.temp.dir(prefix = "moire-board-reg")
    val file = dir / "board.json"
    val h0 = Registers.HarmonicBase
    try {
      val saved = FakeBoard.registers(decimation = 250) ++ Seq(h0 -> 3L, (h0 + 1) -> 0x1234L, (h0 + 2) -> 77L, (h0 + 5) -> 0xFFFFFF00L)
      val a = new FakeBoard(pty, saved, harmonicSlots = 2)
      val out = try run(pty, _.copy(save = Some(file.toString))) finally a.close()
      out.last should include("1 setting(s), 4 non-zero harmonic register(s)")
      val j = ujson.read(os.read(file))
      j("format").str shouldBe BoardRegFile.Format
      j("model")("counts_per_period").num shouldBe 1024
      j("registers").obj.keys.toSeq shouldBe Seq("decimation", "h0_order", "h0_c", "h0_phi", "h1_c")
      // a board of the same model in another state ends as saved: listed registers written, the other slots cleared
      val b = new FakeBoard(pty, FakeBoard.registers(decimation = 9) ++ Seq((h0 + 4) -> 5L), harmonicSlots = 2)
      val loaded = try run(pty, _.copy(load = Some(file.toString))) finally b.close()
      loaded.head should include(s"loaded $file")
      b.registers(Registers.Decimation.addr) shouldBe 250
      Seq(0, 1, 2, 4, 5).map(k => b.registers.getOrElse(h0 + k, 0L)) shouldBe Seq(3L, 0x1234L, 77L, 0L, 0xFFFFFF00L)
      // another model: nothing written
      val c = new FakeBoard(pty, FakeBoard.registers(countsPerPeriod = 4096), harmonicSlots = 2)
      val e = try intercept[MoireError](run(pty, _.copy(load = Some(file.toString)))) finally c.close()
      e.getMessage should include("saved from another kind of board: counts_per_period 1024 in the file, 4096 on the board")
      c.commands.count(_.write) shouldBe 0
      // a board without the compensator cannot keep the slots: the read-back says so
      val d = new FakeBoard(pty, FakeBoard.registers(), harmonicSlots = 0)
      try intercept[MoireError](run(pty, _.copy(load = Some(file.toString)))).getMessage should include("is the harmonic compensator in the design")
      finally d.close()
      // bad files fail before the port is opened
      os.write.over(dir / "bad.json", """{"format": "moire-board-registers v1", "model": {}, "registers": {}}""")
      intercept[MoireError](BoardReg.run(BoardReg.Options("/dev/nonexistent", load = Some((dir / "bad.json").toString)), _ => ()))
        .getMessage should include("model.id is missing")
      os.write.over(dir / "bad2.json", os.read(file).replace("\"h1_c\"", "\"status\""))
      intercept[MoireError](BoardReg.run(BoardReg.Options("/dev/nonexistent", load = Some((dir / "bad2.json").toString)), _ => ()))
        .getMessage should include("registers.status is not a setting board-reg saves")
    } finally os.remove.all(dir)
  }

  "board-reg --save / --load with the adaptive corrector" should "keep its learned values and restore them on load, read back" in PtyPair { pty =>
    import moire.protocol.AdaptRegisters
    val ap = moire.adapt.AdaptParams(harmonicEntries = 8)
    val layout = Map(AdaptRegisters.Format.addr -> moire.adapt.AdaptLearned.format(ap), AdaptRegisters.Size.addr -> moire.adapt.AdaptLearned.size(ap))
    def corrector(l: moire.adapt.AdaptLearned, index: Long = 0): Map[Int, Long] =
      FakeBoard.registers() ++ layout ++ l.words.map { case (r, v) => r.addr -> v } + (AdaptRegisters.TableIndex.addr -> index)
    val table = IndexedSeq(100L, -250L, 3000L, 0L, -7L, 12L, 40000L, -40000L)
    // offset 61.5 codes, gains for amplitudes 1741 and 1650 codes, tan of -4 degrees
    val gain = (a: Double) => math.round(math.pow(2, 15) / math.sqrt(2) / a * math.pow(2, ap.gainFrac))
    val learned = moire.adapt.AdaptLearned(math.round(61.5 * 4096), -20 * 4096, gain(1741), gain(1650),
      math.round(math.tan(math.toRadians(-4)) * math.pow(2, ap.phaseFrac)), 320, locked = true, table.sum, table)
    val dir = os.temp.dir(prefix = "moire-board-reg")
    val file = dir / "board.json"
    try {
      val a = new FakeBoard(pty, corrector(learned, index = 5), adaptTable = learned.tableWords.toIndexedSeq)
      val out = try run(pty, _.copy(save = Some(file.toString))) finally a.close()
      out.last should include("the corrector's learned values (8 table entries)")
      a.registers(AdaptRegisters.TableIndex.addr) shouldBe 5 // put back as it was
      val j = ujson.read(os.read(file))("learned")
      j("adapt_offset_sin").num shouldBe learned.offsetSin
      j("adapt_phase").num shouldBe (learned.phase & 0xFFFFFFFFL)
      j("adapt_table").arr.map(_.num.toLong) shouldBe learned.tableWords
      j("readout")("offset_sin_codes").num shouldBe 61.5
      j("readout")("amplitude_sin_codes").num shouldBe 1741.0 +- 0.01
      j("readout")("amplitude_ratio_sin_cos").num shouldBe (1741.0 / 1650) +- 1e-4
      j("readout")("phase_error_deg").num shouldBe -4.0 +- 1e-3 // 17 fractional bits: 0.0004 deg a step
      j("readout")("table_deg").arr.map(_.num).sum shouldBe 0.0 +- 1e-9 // the mean removed, as the corrector applies it
      BoardRegFile.read(file).learned.map(_.words) shouldBe Some(learned.words.toMap)
      // the whole table of a corrected board: the learned values too, decoded
      val shown = new FakeBoard(pty, corrector(learned), adaptTable = learned.tableWords.toIndexedSeq)
      val all = try run(pty, o => o) finally shown.close()
      all.init.map(_.split("\\s+")(1)) shouldBe Registers.all.map(_.name) ++ AdaptRegisters.learned.map(_.name)
      all.find(_.contains("adapt_phase")).get should endWith(s"signed ${learned.phase}")
      all.last shouldBe "corrector: offsets 61.50 / -20.00 codes, amplitudes 1741.0 / 1650.0 codes (sin/cos 1.0552), phase error -4.000 deg; table: --save"
      // the same corrector, learned a little differently (or reset): held, restored from the file, read back, released
      val moved = learned.copy(offsetSin = learned.offsetSin + 4096, table = table.updated(2, 3100L))
      val b = new FakeBoard(pty, corrector(moved), adaptTable = moved.tableWords.toIndexedSeq)
      val loaded = try run(pty, _.copy(load = Some(file.toString))) finally b.close()
      loaded(1) shouldBe "restored the corrector's learned values (offsets, gains, phase, 8 table entries and their sum), each read back; " +
        "learning goes on from them"
      for ((r, _) <- AdaptRegisters.presets) b.registers(r.addr) shouldBe learned.words.toMap.apply(r)
      b.adaptTableNow shouldBe learned.tableWords
      val adaptWrites = b.commands.filter(c => c.write && c.addr >= AdaptRegisters.Control.addr).map(c => c.addr -> c.value)
      adaptWrites.head shouldBe (AdaptRegisters.Control.addr -> 1L) // held before the first preset
      adaptWrites.last shouldBe (AdaptRegisters.Control.addr -> 0L) // and released after the read-back
      adaptWrites.count(_ == (AdaptRegisters.Control.addr -> 5L)) shouldBe 4 // a table pair each
      adaptWrites.count(_ == (AdaptRegisters.Control.addr -> 3L)) shouldBe 1 // one load
      b.registers(AdaptRegisters.TableIndex.addr) shouldBe 0 // put back as it was
      // a held corrector stays held
      val held = new FakeBoard(pty, corrector(moved) + (AdaptRegisters.Control.addr -> 1L), adaptTable = moved.tableWords.toIndexedSeq)
      try run(pty, _.copy(load = Some(file.toString)))(1) should endWith("the corrector stays held, as it was") finally held.close()
      held.registers(AdaptRegisters.Control.addr) shouldBe 1
      // a bitstream from before the preset registers: one line, nothing learned changed
      val old = new FakeBoard(pty, corrector(moved), adaptTable = moved.tableWords.toIndexedSeq, presets = false)
      val e0 = try intercept[MoireError](run(pty, _.copy(load = Some(file.toString)))) finally old.close()
      e0.getMessage shouldBe s"${pty.host}: wrote 0x00000001 to adapt_control, the board kept 0x00000000: " +
        "a bitstream without adapt_control and the preset registers (0xf4-0xfc)?"
      old.adaptTableNow shouldBe moved.tableWords
      // a corrector of another size, or none: another kind of board, nothing written
      val other = Map(AdaptRegisters.Size.addr -> moire.adapt.AdaptLearned.size(ap.copy(harmonicEntries = 16)))
      for ((regs, what) <- Seq(corrector(learned) ++ other -> "adapt_size 0x0008100c in the file, 0x0010100c on the board",
                               FakeBoard.registers() -> "the adaptive corrector's learned values in the file, no corrector read-back on the board (adapt_format 0)")) {
        val c = new FakeBoard(pty, regs)
        val e = try intercept[MoireError](run(pty, _.copy(load = Some(file.toString)))) finally c.close()
        e.getMessage should include(s"saved from another kind of board: $what; nothing written")
        c.commands.count(_.write) shouldBe 0
      }
      // bad learned sections: one line each, before the port is opened
      def bad(edit: ujson.Value => Unit): String = {
        val v = ujson.read(os.read(file)); edit(v("learned"))
        os.write.over(dir / "bad.json", ujson.write(v))
        intercept[MoireError](BoardReg.run(BoardReg.Options("/dev/nonexistent", load = Some((dir / "bad.json").toString)), _ => ())).getMessage
      }
      bad { v => v("adapt_table").arr.remove(0); () } should include("learned.adapt_table has 7 entries, adapt_size says 8")
      bad(_("adapt_gain_sin") = -1) should include("learned.adapt_gain_sin must be an integer in 0..4294967295, got -1")
      bad { v => v.obj.remove("adapt_updates"); () } should include("learned.adapt_updates is missing")
      bad(_("offset") = 1) should include("learned.offset is not a value board-reg saves")
      bad(_("adapt_size") = ujson.Num(0x0007100c.toDouble)) should include("do not describe a corrector")
    } finally os.remove.all(dir)
  }
}
