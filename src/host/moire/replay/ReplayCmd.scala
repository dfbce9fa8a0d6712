package moire.replay

import mainargs.ParserForClass
import moire.options.DecimalReader._
import moire.options.SubdivConfig
import moire.recording.Recording

/** `replay FILE [--design subdiv|corrected] [--out OUT.csv] [emit-subdiv options]`. */
object ReplayCmd {
  val Usage: String =
    """Usage: replay FILE [--design subdiv|corrected] [--out OUT.csv] [--check-rows N] [--check-windows W] [--quiet] [emit-subdiv options]
      |  Runs a moire-recording v1 file's ADC codes through the generated RTL (Verilator, built once per
      |  configuration and cached), writes the outputs (row i = outputs for input sample i) and checks a
      |  sample of the rows against the bit-accurate model. Design options default from the recording's
      |  metadata (adc_bits -> --input-bits, adc -> --adc-format, counts_per_period -> --counts); the corrected
      |  chain takes --counts and --adc-format and reads 12-bit codes, the rest at its defaults.
      |    --check-rows N      rows checked clock by clock from the start (default 100000)
      |    --check-windows W   windows of 5000 rows checked over the rest (default 20)""".stripMargin

  private val subdivParser = ParserForClass[SubdivConfig]

  /** Options of the subdivider: the recording's metadata first, then what the user gave (which wins). */
  def config(opts: Seq[String], meta: Map[String, String]): SubdivConfig = {
    def userGave(o: String) = opts.contains(o)
    val keys = Seq("--input-bits" -> "adc_bits", "--adc-format" -> "adc_format", "--counts" -> "counts_per_period")
    val taken = Seq("--input-bits" -> meta.get("adc_bits"), "--adc-format" -> Recording.format(meta).toOption.map(_.name), "--counts" -> meta.get("counts_per_period"))
      .collect { case (o, Some(v)) if !userGave(o) => (o, v) }
    val line = try subdivParser.constructEither(taken.flatMap { case (o, v) => Seq(o, v) } ++ opts, allowPositional = false) match {
      // (the subdivider's own checks run where its parameters are made)
      case Right(c) => c.params; return c
      case Left(msg) => moire.options.SubdivCmd.oneLine(msg)
    } catch {
      case e: moire.options.OptionError => e.getMessage
      case e: IllegalArgumentException => "--" + String.valueOf(e.getMessage).stripPrefix("requirement failed: ").stripPrefix("--")
    }
    // a value the recording's metadata gave, not the user: the metadata is named
    throw new ReplayError(taken.find { case (o, _) => line.startsWith(o + " ") || line.startsWith(o + ":") }.fold(line) { case (o, v) =>
      s"the recording's metadata ${keys.toMap.apply(o)} '$v' is not one the subdivider takes (${line.stripPrefix(o).stripPrefix(":").trim}); give $o to replay it otherwise"
    })
  }

  /** The pins of a recording, or one line saying why it cannot be replayed exactly. */
  def pins(file: String, rec: Recording): PinStream = {
    val dec = rec.meta.get("decimation").map(v => moire.numbers.Decimal.double(v).getOrElse(throw new ReplayError(s"$file: metadata decimation '$v' is not a number")))
    dec.filter(_ != 1.0).foreach { d =>
      throw new ReplayError(s"$file: the recording is decimated (decimation ${fmt(d)}): the RTL needs every ADC sample, so it cannot be replayed exactly")
    }
    rec.extra.get("sample_index").foreach { ix =>
      var i = 1
      while (i < ix.length) {
        val step = (ix(i).toLong - ix(i - 1).toLong) & 0xffffffffL
        if (step != 1) throw new ReplayError(s"$file: sample_index jumps from ${fmt(ix(i - 1))} to ${fmt(ix(i))} (data row ${i + 1}): " +
          "records are missing, so the RTL cannot be replayed exactly")
        i += 1
      }
    }
    def flags(c: String) = rec.extra.get(c).map(_.map(_ != 0)).getOrElse(Array.emptyBooleanArray)
    PinStream(rec.sin, rec.cos, flags("otr_sin"), flags("otr_cos"))
  }
  private def fmt(d: Double) = if (d == math.rint(d)) d.toLong.toString else d.toString

  /** Checks that the design reads the recording's ADC. */
  def matchAdc(file: String, rec: Recording, d: ReplayDesign): Unit = {
    if (rec.adc.bits != d.inputBits) throw new ReplayError(d match {
      case _: ReplayDesign.Corrected => s"$file: the recording has ${rec.adc.bits}-bit ADC codes, the corrected chain reads ${d.inputBits}-bit codes (--design subdiv --input-bits ${rec.adc.bits} reads them)"
      case _ => s"$file: the recording has ${rec.adc.bits}-bit ADC codes, the design reads ${d.inputBits} bits (--input-bits)"
    })
    if (rec.adc.format != d.format)
      throw new ReplayError(s"$file: the recording's ADC format is ${rec.adc.format.name}, the design reads ${d.format.name} (--adc-format)")
  }

  /** Emits and builds (or finds in the cache) the harness of a design. */
  def build(d: ReplayDesign, log: String => Unit): Harness = {
    VerilatorBuild.verilatorVersion
    val t0 = System.nanoTime()
    val v = d.verilog()
    val emitS = (System.nanoTime() - t0) / 1e9
    val h = VerilatorBuild.harness(v, d.topName)
    log((if (h.cached) s"cached build ${h.dir}" else f"built ${h.dir} in ${h.buildSeconds}%.1f s") + f" (emitting the Verilog took $emitS%.1f s)")
    h
  }

  /** Replays pins through a design: build, run with a progress bar on long runs, check against the model. */
  def replay(d: ReplayDesign, p: PinStream, quiet: Boolean, log: String => Unit, head: Int = 100000, windows: Int = 20): (ReplayOutput, CheckResult) = {
    val h = build(d, log)
    val bar = if (quiet || p.length < 2000000) None
      else Some(new moire.progress.Bar("replay", p.length.toLong))
    val t0 = System.nanoTime()
    val out = try Replay.run(h, d, p, k => bar.foreach(_.stepTo(k))) finally bar.foreach(_.close())
    val t1 = System.nanoTime()
    val check = ModelCheck.run(d, p, out, head, windows)
    log(f"harness ${(t1 - t0) / 1e9}%.1f s (clocking loop ${out.loopSeconds}%.2f s), model check ${(System.nanoTime() - t1) / 1e9}%.1f s")
    (out, check)
  }

  /** `replay`'s options, parsed by the command line (moire.cli.ReplayArgs); `subdiv` holds the emit-subdiv options. */
  final case class Options(file: Option[String], design: String = "subdiv", out: Option[String] = None, quiet: Boolean = false,
                           checkRows: Int = 100000, checkWindows: Int = 20, subdiv: Seq[String] = Nil)

  /** Replays a recording through the RTL and writes the outputs; true when the RTL matches the model. */
  def run(opts: Options): Boolean = {
    val (design, out, file, quiet, head, windows) = (opts.design, opts.out, opts.file, opts.quiet, opts.checkRows, opts.checkWindows)
    val f = file.getOrElse(throw new ReplayError("replay: name a recording file (see --help)"))
    if (design == "corrected") opts.subdiv.filter(_.startsWith("--")).map(_.takeWhile(_ != '=')).find(o => !ReplayDesign.correctedOptions.contains(o)).foreach { o =>
      throw new ReplayError(s"$o applies to --design subdiv only: the corrected chain takes ${ReplayDesign.correctedOptions.mkString(", ")} (the rest at its defaults)")
    }
    val path = os.Path(f, os.pwd)
    // The output is checked before the long work: never one of the inputs, always writable.
    if (out.isEmpty) moire.files.SafeWrite.checkNameOf(path) // <stem>-replay.csv
    val dest = out.fold(os.Path(moire.files.Stem.of(path) + "-replay.csv", os.pwd))(moire.files.SafeWrite.fileArg)
    moire.files.SafeWrite.refuseInputs(dest, Seq(path))
    if (out.isEmpty) moire.files.SafeWrite.checkPicked(dest, OutputCsv.Magic, "--out FILE") else moire.files.SafeWrite.checkFile(dest)
    // a file of another kind under --out is refused now, not after the build and the run
    moire.files.SafeWrite.checkKind(dest, "a " + OutputCsv.Magic.drop(2).takeWhile(c => c.isLetterOrDigit || c == '-') + " file")
    var t = System.nanoTime()
    def lap(): Double = { val now = System.nanoTime(); val s = (now - t) / 1e9; t = now; s }
    val rec = Recording.read(path)
    rec.warnings.foreach(w => System.err.println(s"replay: WARNING: $f: $w"))
    val readS = lap()
    moire.recording.FormatCheck.mismatch(rec).foreach(why => throw new ReplayError(s"$f: $why"))
    val cfg = config(opts.subdiv, rec.meta)
    val d = ReplayDesign(design, cfg)
    if (d.isInstanceOf[ReplayDesign.Corrected] && cfg.inputBits != d.inputBits && opts.subdiv.exists(_.takeWhile(_ != '=') == "--input-bits"))
      throw new ReplayError(s"--input-bits: the corrected chain reads ${d.inputBits}-bit codes only")
    matchAdc(f, rec, d)
    val p = pins(f, rec)
    def log(s: String): Unit = if (!quiet) System.err.println(s"replay: $s")
    log(s"${d.describe}, latency ${d.latency} clocks, ${p.length} samples")
    val (o, check) = replay(d, p, quiet, log, head, windows)
    val replayS = lap()
    OutputCsv.write(dest, f, d, o, rec.extra.get("sample_index"))
    val writeS = lap()
    log(f"read CSV $readS%.1f s, emit + build + replay + check $replayS%.1f s, write CSV $writeS%.1f s")
    println(f"wrote $dest (${o.length} rows; harness ${o.length / o.loopSeconds / 1e6}%.2f M samples/s)")
    println(check.text)
    check.ok
  }
}

/** OUT.csv of replay: row i = outputs for input sample i (taken `latency` clocks after it entered). */
object OutputCsv {
  val Magic = "# moire-replay v1"
  def write(dest: os.Path, input: String, d: ReplayDesign, o: ReplayOutput, sampleIndex: Option[Array[Double]]): Unit = {
    moire.files.SafeWrite(dest)(tmp => write(tmp.toIO, input, d, o, sampleIndex))
  }

  private def write(dest: java.io.File, input: String, d: ReplayDesign, o: ReplayOutput, sampleIndex: Option[Array[Double]]): Unit = {
    val w = new java.io.BufferedWriter(new java.io.OutputStreamWriter(new java.io.FileOutputStream(dest), "US-ASCII"), 1 << 20)
    try {
      w.write(s"$Magic\n# input: $input\n# design: ${d.describe}\n# latency: ${d.latency}\n" +
        s"# alignment: row i = the outputs for input sample i, taken ${d.latency} clocks after the sample entered\n" +
        "sample,position,phase,present,over_range,step_fault,a,b,z,overspeed\n")
      val sb = new java.lang.StringBuilder(64)
      var i = 0
      while (i < o.length) {
        sb.setLength(0)
        sb.append(sampleIndex.map(_(i).toLong).getOrElse(i.toLong)).append(',').append(o.position(i)).append(',').append(o.phase(i))
        var bit = Replay.Present
        while (bit <= Replay.Overspeed) { sb.append(',').append((o.flags(i) >> bit) & 1); bit += 1 }
        sb.append('\n')
        w.write(sb.toString)
        i += 1
      }
    } finally w.close()
  }
}
