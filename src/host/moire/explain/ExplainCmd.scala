package moire.explain

import scala.jdk.CollectionConverters._

import moire.recording.{Calibration, CsvText, Recording}
import moire.signal.{Adc, AdcFormat, Motion, SignalParams}

/** The logic behind `simulate`, `explain` and `explain-bench`. */
object ExplainCmd {
  final case class SimOptions(out: String, samples: Int, sampleRateHz: Double, adcBits: Int, adc: String, motion: String,
                              amplitude: Double, offsetSin: Double, offsetCos: Double, gainSin: Double, gainCos: Double,
                              phaseErrorDeg: Double, noise: Double, seed: Long, linesPerRev: Option[Double],
                              effects: Seq[String], model: Option[String], given: Set[String] = Set.empty)

  def model(o: SimOptions): PhysicsModel = {
    val fmt = AdcFormat.parse(o.adc).fold(e => throw new ExplainError(s"--adc: $e"), identity)
    PhysicsModel.check(Map("sample_rate_hz" -> o.sampleRateHz, "samples" -> o.samples.toDouble, "amplitude" -> o.amplitude,
      "offset_sin" -> o.offsetSin, "offset_cos" -> o.offsetCos, "gain_sin" -> o.gainSin, "gain_cos" -> o.gainCos,
      "phase_error_deg" -> o.phaseErrorDeg, "noise_rms" -> o.noise) ++ o.linesPerRev.map("lines_per_rev" -> _), PhysicsModel.NumberKeys.toMap)
      .foreach(w => throw new ExplainError(w))
    val base = SignalParams(o.amplitude, o.offsetSin, o.offsetCos, o.gainSin, o.gainCos, o.phaseErrorDeg, Nil, o.noise, o.seed)
    val d = try PhysicsModel(base, PhysicsModel.parseMotion(o.motion), o.sampleRateHz, o.samples, Adc(o.adcBits, fmt), o.linesPerRev,
      o.effects.map(EffectSpec.parse))
    catch { case e: IllegalArgumentException => throw new ExplainError(e.getMessage.stripPrefix("requirement failed: ")) }
    o.model.map(f => PhysicsModel.fromJson(readText(f), f, d, SimOptionKeys.filter(k => o.given(k._2)))).getOrElse(d)
  }

  /** The model file's key each of simulate's options sets. */
  val SimOptionKeys: Map[String, String] = Map("samples" -> "--samples", "sample_rate_hz" -> "--sample-rate-hz", "adc_bits" -> "--adc-bits",
    "adc" -> "--adc", "motion" -> "--motion", "amplitude" -> "--amplitude", "offset_sin" -> "--offset-sin", "offset_cos" -> "--offset-cos",
    "gain_sin" -> "--gain-sin", "gain_cos" -> "--gain-cos", "phase_error_deg" -> "--phase-error-deg", "noise_rms" -> "--noise",
    "seed" -> "--seed", "lines_per_rev" -> "--lines-per-rev", "effects" -> "--effect")

  private def readText(f: String): String = {
    val p = os.Path(f, os.pwd)
    moire.files.PathKind.notAFile(p).foreach(m => throw new ExplainError(m))
    os.read(p)
  }

  def simulate(o: SimOptions): String = {
    // the model line keeps the seed as a JSON number: beyond 2^53 it would name another seed than the one used
    if (o.seed > PhysicsModel.MaxSeed || o.seed < -PhysicsModel.MaxSeed)
      throw new ExplainError(s"--seed must be a whole number from -${PhysicsModel.MaxSeed} to ${PhysicsModel.MaxSeed} (the # model: line keeps it exactly), got ${o.seed}")
    val m = model(o)
    val (rec, truth) = try m.generate() catch { case e: IllegalArgumentException => throw new ExplainError(e.getMessage.stripPrefix("requirement failed: ")) }
    aliased(truth, o.sampleRateHz).orElse(aliasedMotion(m.motion, o.sampleRateHz)).foreach(w => throw new ExplainError(w))
    val path = moire.files.SafeWrite.fileArg(o.out)
    moire.files.SafeWrite.refuseInputs(path, o.model.toSeq.map(os.Path(_, os.pwd)))
    Recording.write(path, rec)
    s"wrote $path (${rec.length} samples, ${m.effects.map(_.effect).mkString(", ") match { case "" => "default model only"; case s => s }})" +
      atRails(rec).fold("")(w => s"; note: $w")
  }

  /** Why a simulated fringe cannot be sampled (it moves half a period or more between samples: the samples alias), or
    * None. `truth`: the fringe phase in periods at each sample.
    */
  def aliased(truth: Array[Double], fs: Double): Option[String] = {
    var mx = 0.0; var i = 1
    while (i < truth.length) { val d = math.abs(truth(i) - truth(i - 1)); if (!(d <= mx)) mx = d; i += 1 }
    if (mx < 0.5) None
    else Some(f"the fringe moves up to ${mx}%.4g periods between samples (${mx * fs}%.4g Hz at ${fs}%.4g samples/s): at half a " +
      "period or more the samples alias; slow the motion or raise --sample-rate-hz")
  }

  /** An oscillation's own peak speed against the sample rate: one at the sample rate stands still at its samples, which
    * the samples' steps (`aliased`) cannot see.
    */
  def aliasedMotion(m: moire.signal.Motion, fs: Double): Option[String] = m match {
    case o: moire.signal.Motion.Oscillate =>
      val hz = math.abs(2 * math.Pi * o.periodsPeak * o.rateHz); val mx = hz / fs
      if (!(mx >= 0.5)) None
      else Some(f"the oscillation moves the fringe at up to ${hz}%.4g Hz, ${mx}%.4g periods between samples at ${fs}%.4g samples/s: " +
        "at half a period or more the samples alias; slow the motion or raise --sample-rate-hz")
    case _ => None
  }

  /** The share of a simulated record's samples at the ADC's end codes, when above 1 % on a channel. */
  def atRails(rec: Recording): Option[String] = {
    val lo = -rec.adc.half; val hi = rec.adc.half - 1
    def share(c: Array[Int]) = { var k = 0; var i = 0; while (i < c.length) { val v = rec.adc.fromPins(c(i)); if (v <= lo || v >= hi) k += 1; i += 1 }; k.toDouble / math.max(1, c.length) }
    val (s, c) = (share(rec.sin), share(rec.cos))
    if (math.max(s, c) <= 0.01) None
    else Some(f"${100 * s}%.1f %% of the sin samples and ${100 * c}%.1f %% of the cos samples are at the ADC's end codes (the signal exceeds the converter's range)")
  }

  /** Explains each file; writes `<stem>.json` into jsonDir and PNGs into plotDir. Returns the text reports. */
  def explain(files: Seq[String], jsonDir: Option[String], plotDir: Option[String], modelFile: Option[String], quiet: Boolean,
              rtl: Option[Seq[String]] = Some(Nil), html: Option[String] = None, htmlDir: Option[String] = None,
              materiality: Materiality = Materiality(), searchSamples: Int = Interleaved.SearchSamples): Seq[Report] = {
    if (files.isEmpty) throw new ExplainError("explain: name at least one recording file")
    if (html.isDefined && files.size > 1) throw new ExplainError(s"--html names one file, but ${files.size} recordings were given; use --html-dir DIR (one DIR/<name>.html each)")
    if (html.isDefined && htmlDir.isDefined) throw new ExplainError("give --html FILE or --html-dir DIR, not both")
    html.foreach { f =>
      val p = moire.files.SafeWrite.fileArg(f)
      moire.files.SafeWrite.refuseInputs(p, files.map(os.Path(_, os.pwd)) ++ modelFile.map(os.Path(_, os.pwd)))
      moire.files.SafeWrite.checkFile(p)
    }
    val givenEffects = modelFile.map { f =>
      // the whole file checked as simulate checks it (a misspelled key, a number that is text): explain uses its effects
      val fx = PhysicsModel.fromJson(readText(f), f, ModelCheck).effects
      val terms = SignalExplain.specOf(fx).terms.size
      if (terms > MaxModelTerms) throw new ExplainError(s"$f: ${fx.size} effects make $terms terms of the backward model; explain --model fits at most $MaxModelTerms")
      fx
    }.getOrElse(Nil)
    // an empty name is the working folder: it was told back as "/the/folder: is a folder, not a file"
    if (files.exists(_.isEmpty)) throw new ExplainError("explain: a recording's name is empty (''); give a file name")
    val paths = files.map(f => os.Path(f, os.pwd))
    // one file named twice would be explained twice, the second report over the first (or, through a link, beside it)
    moire.files.SameFile.repeated(paths).foreach { case (a, b) =>
      if (a == b) throw new ExplainError(s"$a: given ${paths.count(_ == a)} times; name each recording once")
      throw new ExplainError(s"$a and $b are one file (through a link); name each recording once")
    }
    // the subdivider's options are checked now, not found wrong file by file in a note
    rtl.filter(_.nonEmpty).foreach(opts => try moire.replay.ReplayDesign("subdiv", moire.replay.ReplayCmd.config(opts, Map.empty))
      catch { case e: moire.MoireError => throw new ExplainError(s"--subdiv: ${e.getMessage}") })
    // Outputs are checked before the long work: writable folders, no two reports under one name.
    val outDirs = (jsonDir.map(_ -> "--json-dir") ++ plotDir.map(_ -> "--plots") ++ htmlDir.map(_ -> "--html-dir"))
      .map { case (d, o) => moire.files.SafeWrite.folderArg(d, o) }
    // the reports and plots in them are named after the recordings
    if (outDirs.nonEmpty) paths.foreach(moire.files.SafeWrite.checkNameOf)
    outDirs.foreach(moire.files.SafeWrite.checkFolder)
    // no report written over a recording or the model file
    val inputs = paths ++ modelFile.map(os.Path(_, os.pwd))
    for (d <- jsonDir; p <- paths) moire.files.SafeWrite.refuseInputs(os.Path(d, os.pwd) / s"${moire.files.Stem.of(p)}.json", inputs)
    html.foreach(f => moire.files.SafeWrite.refuseInputs(os.Path(f, os.pwd), inputs))
    for (d <- htmlDir; p <- paths) moire.files.SafeWrite.refuseInputs(os.Path(d, os.pwd) / s"${moire.files.Stem.of(p)}.html", inputs)
    // a user's own JSON, page or image under a report's name is refused now, not after the fit (nor after some plots)
    for (d <- jsonDir; p <- paths) moire.files.SafeWrite.checkKind(os.Path(d, os.pwd) / s"${moire.files.Stem.of(p)}.json", ReportJson)
    html.foreach(f => moire.files.SafeWrite.checkKind(os.Path(f, os.pwd), ReportHtml))
    for (d <- htmlDir; p <- paths) moire.files.SafeWrite.checkKind(os.Path(d, os.pwd) / s"${moire.files.Stem.of(p)}.html", ReportHtml)
    // the plots' names depend on the findings (<stem>_<what>.png): no input may have such a name in --plots
    for (d <- plotDir; p <- paths; i <- inputs; stem = moire.files.Stem.of(p))
      if (i.last.startsWith(stem + "_") && i.last.endsWith(".png") && moire.files.SafeWrite.same(os.Path(d, os.pwd) / i.last, i))
        throw new ExplainError(s"$i: is an input of this command, and --plots writes ${stem}_*.png into its folder; choose another --plots folder")
    for (d <- plotDir.map(os.Path(_, os.pwd)).filter(os.isDir(_)); p <- paths; stem = moire.files.Stem.of(p); f <- os.list(d) if os.isFile(f, followLinks = false) &&
      f.last.startsWith(stem + "_") && f.last.endsWith(".png")) moire.files.SafeWrite.checkKind(f, "a PNG image")
    if (outDirs.nonEmpty) paths.groupBy(p => moire.files.Stem.of(p)).collectFirst { case (stem, ps) if ps.distinct.size > 1 =>
      throw new ExplainError(s"${ps.distinct.mkString(" and ")} share the name $stem: their reports would overwrite each other; rename one")
    }
    // the plotting library's start (fonts, image classes) on a side thread while the first file is read and fitted
    if (plotDir.isDefined || html.isDefined || htmlDir.isDefined) Plots.warmUp()
    // Every file gets its report or its one-line error; the command fails after all were tried.
    def htmlOf(p: os.Path) = html.map(os.Path(_, os.pwd)).orElse(htmlDir.map(d => os.Path(d, os.pwd) / s"${moire.files.Stem.of(p)}.html"))
    def one(p: os.Path, progress: Progress, say: String => Unit) =
      explainOne(p, givenEffects, jsonDir, plotDir, progress, say, rtl, htmlOf(p), materiality, searchSamples)
    val results = if (paths.size > 1) batch(paths, quiet, one) else {
      val p = paths.head
      val r = one(p, if (quiet) Progress.none else Progress.bar(moire.files.Stem.of(p)), s => if (!quiet) System.err.println(s"explain: $s"))
      if (!quiet) print(r.text)
      Seq(Right(r))
    }
    val failed = results.collect { case Left(e) => e }
    if (failed.nonEmpty) {
      if (paths.size == 1) throw failed.head
      throw new ExplainError(s"${failed.size} of ${paths.size} files failed (their errors are above); the other reports are complete")
    }
    results.collect { case Right(r) => r }
  }

  /** Called with each file of a batch when it starts (true) and ends (false); tests watch the overlap here. */
  @volatile var batchWatch: (os.Path, Boolean) => Unit = (_, _) => ()

  /** The files side by side ([[Batch]]); each error is said when found, the text reports in the files' order. */
  private def batch(paths: Seq[os.Path], quiet: Boolean, one: (os.Path, Progress, String => Unit) => Report): Seq[Either[moire.MoireError, Report]] = {
    val shown = new BatchProgress(paths.size, terminal = !quiet && moire.progress.Bar.terminal)
    val results = Array.fill[Either[moire.MoireError, Report]](paths.size)(null)
    try Batch.run(paths.size, Batch.threads(paths.size), Batch.budget, i => Batch.heapOf(paths(i))) { i =>
      val p = paths(i)
      batchWatch(p, true)
      try Right(one(p, if (quiet) Progress.none else shown.start(i, p), s => if (!quiet) shown.say(s"explain: $s")))
      catch { case e: moire.MoireError => shown.say(s"moire: ${moire.files.Shown.text(e.getMessage, Int.MaxValue)}"); Left(e) }
      finally { batchWatch(p, false); shown.finish(i) }
    } { (i, r) => results(i) = r; if (!quiet) r.foreach(rep => shown.report(rep.text)) }
    finally shown.close()
    results.toSeq
  }

  private def explainOne(p: os.Path, givenEffects: Seq[EffectSpec], jsonDir: Option[String], plotDir: Option[String],
                         progress: Progress, say: String => Unit, rtl: Option[Seq[String]], html: Option[os.Path],
                         materiality: Materiality, searchSamples: Int): Report = {
    val kind = kindOf(p)
    val stem = moire.files.Stem.of(p)
    // plots for --plots or the HTML, drawn in memory and written at the end with the report (all or none)
    val plotFolder = plotDir.map(os.Path(_, os.pwd))
    val drawn = plotDir.isDefined || html.isDefined
    var plots = Seq.empty[Plots.Drawn]
    var extra = Seq.empty[(String, ujson.Value)]
    val report = try {
      if (kind == "calibration") {
        val r = CalibrationExplain.run(p.toString, Calibration.read(p))
        if (drawn) plots = CalibrationExplain.plots(r, stem)
        r.report
      } else {
        val rec = Recording.read(p)
        checkSignals(p, rec)
        // the interpolation error and plots from the searched engine (a long record's subsample, `Interleaved`)
        // on a side thread while the other subsamples are fitted (the plots read the searched engine alone)
        var shown: Option[java.util.concurrent.CompletableFuture[Unit]] = None
        def done(): Unit = shown.foreach { f =>
          try f.join() catch { case e: java.util.concurrent.CompletionException => throw e.getCause }
          shown = None
        }
        def show(r: SignalExplain.Result): Unit = {
          done()
          shown = Some(java.util.concurrent.CompletableFuture.supplyAsync(() => draw(r), Plots.Pool))
        }
        def draw(r: SignalExplain.Result): Unit = {
          val t0 = System.nanoTime()
          val ie = Laps("interpolation error")(InterpolationError.of(r.engine.rec, r.engine))
          // a second call (a long record searched again on all samples) draws the plots written in place of the first's
          if (drawn) plots = Laps("plots")(Plots.signals(r, stem, ie))
          extra = extra.filterNot(_._1 == "interpolation_error") :+ ("interpolation_error" -> ie.json)
          if (sys.props.contains("moire.timing")) System.err.println(f"interpolation error and plots ${(System.nanoTime() - t0) / 1e6}%.0f ms")
        }
        val r = try SignalExplain.run(p.toString, rec, givenEffects, progress, materiality = materiality, searchSamples = searchSamples, searched = show)
          catch { case e: Throwable => try done() catch { case _: Throwable => () }; throw e }
        done()
        progress.close()
        // Board outputs (a `position` column) against the RTL run on the recorded codes.
        val checked = rtl.filter(_ => rec.extra.contains("position")).map { opts =>
          val (f, notes) = BoardCheck.run(p.toString, rec, opts, say)
          r.report.copy(findings = r.report.findings ++ f, notes = r.report.notes ++ notes)
        }.getOrElse(r.report)
        // --subdiv given for a recording the RTL check cannot run on: said, not dropped
        val unused = rtl.filter(o => o.nonEmpty && !rec.extra.contains("position")).map(_ =>
          "--subdiv not used: the RTL check runs on a recording with the board's position column, and this one has none")
        // what the reader left out (a last row cut short) comes first among the notes
        checked.copy(notes = rec.warnings ++ checked.notes ++ unused)
      }
    } finally progress.close()
    // new keys beside the report's: the readouts of the interpolation error, the HTML and the plots written
    val json = report.json
    extra.foreach { case (k, v) => json(k) = v }
    html.foreach(h => json("html") = h.toString)
    val plotFiles = plotFolder.toSeq.flatMap(d => plots.map(p => d / p._1))
    if (plotDir.isDefined) json("plots") = ujson.Arr.from(plotFiles.map(f => ujson.Str(f.toString)))
    val page = html.map(h => h -> HtmlReport.render(json, plots))
    val text = ujson.write(json, indent = 2)
    // the record's plots, HTML and JSON as one: a failed write changes none of them (the old ones kept, none half-new)
    moire.files.SafeWrite.made(plotFolder.toSeq.flatMap(Plots.writes(_, plots)),
      plain = page.toSeq.map { case (h, t) => h -> ((f: os.Path) => os.write(f, t)) } ++
        jsonDir.map(d => (os.Path(d, os.pwd) / s"$stem.json") -> ((f: os.Path) => os.write(f, text))))
    // the record's plots this run did not make go: an earlier run's (an effect it found and this one not), as moire wrote them
    plotFolder.foreach(d => moire.files.SafeWrite.removeStale(d, Plots.ofStem(stem), plotFiles))
    report
  }

  /** What `SafeWrite.kind` calls explain's JSON and HTML reports. */
  val ReportJson = "an explain report (JSON)"
  val ReportHtml = "an explain report (HTML)"

  /** The defaults a `--model` file is checked against (its own values replace them; explain uses only its effects). */
  private lazy val ModelCheck: PhysicsModel = PhysicsModel(SignalParams(0.8, 0, 0, 1, 1, 0, Nil, 1e-3, 1), Motion.Constant(1e3), 1e6, 1000, Adc(12), None, Nil)
  /** The most linear terms a `--model` file's effects may add to the backward model (each is fitted at every refit). */
  val MaxModelTerms = 64

  /** Fewest samples explain fits (a one-period recording of 1000 samples is fine; ten rows are not). */
  val MinSamples = 64

  /** What no fit can use: too few samples, a channel that never changes (dead or unconnected). */
  def checkSignals(p: os.Path, rec: Recording, who: String = "explain"): Unit = {
    if (rec.length < MinSamples)
      throw new ExplainError(s"$p: ${rec.length} samples; $who needs at least $MinSamples (and a few fringe periods)")
    for ((name, c) <- Seq("sin" -> rec.sin, "cos" -> rec.cos) if c.forall(_ == c(0)))
      throw new ExplainError(s"$p: $name channel constant at code ${c(0)} over all ${rec.length} samples: a dead or unconnected channel, nothing to fit")
    moire.recording.FormatCheck.mismatch(rec).foreach(why => throw new ExplainError(s"$p: $why"))
    gap(rec).foreach(why => throw new ExplainError(s"$p: $why"))
    // a channel mostly at the end codes holds its fringe only near the zero crossings: too little to fit it by
    for ((name, c) <- Seq("sin" -> rec.sin, "cos" -> rec.cos)) {
      val (lo, hi) = (rec.adc.pins(-rec.adc.half), rec.adc.pins(rec.adc.half - 1))
      var k = 0; var i = 0
      while (i < c.length) { if (c(i) == lo || c(i) == hi) k += 1; i += 1 }
      val share = k.toDouble / c.length
      if (share > MaxRailShare) throw new ExplainError(f"$p: the $name channel is at the ADC's end codes on ${100 * share}%.1f %% of " +
        f"its samples (at most ${100 * MaxRailShare}%.0f %%): too little of the fringe is within the converter's range to fit; lower the gain before the ADC")
    }
  }
  /** Why the rows are not evenly spaced in time, or None: a `sample_index` (a 32-bit count of ADC samples) that steps
    * other than its first step (a decimated recording steps by its decimation throughout). The fit's time axis is the
    * row number over the sample rate: records lost on the link would shift every later sample's time.
    */
  def gap(rec: Recording): Option[String] = {
    // the decimation (ADC samples per row) a file states: a whole number from 1, and the index's step where it has one
    val dec = rec.meta.get("decimation").map(v => v -> moire.numbers.Decimal.double(v).filter(d => d >= 1 && d == math.rint(d) && d <= MaxCount))
    def show(x: Double) = if (x == math.rint(x)) x.toLong.toString else x.toString
    dec.collect { case (v, None) => s"metadata decimation '$v' is not a whole number from 1 to ${MaxCount.toLong} (ADC samples per row)" }.orElse(
      rec.extra.get("sample_index").filter(_.length > 1).flatMap { ix =>
        def step(i: Int) = (ix(i).toLong - ix(i - 1).toLong) & 0xffffffffL
        val d = step(1)
        ix.indices.find(i => !(ix(i) == math.rint(ix(i)) && ix(i) >= 0 && ix(i) <= MaxCount)).map(i =>
          s"sample_index ${show(ix(i))} (data row ${i + 1}) is no count of ADC samples (a whole number from 0 to ${MaxCount.toLong})")
          .orElse(if (d == 0 || d > (1L << 31)) Some(s"sample_index steps from ${show(ix(0))} to ${show(ix(1))} (data rows 1 and 2): it counts ADC samples, " +
            "up (modulo 2^32) by the decimation each row") else None)
          .orElse(dec.flatMap(_._2).filter(_ != d.toDouble).map(x => s"sample_index steps by $d from row to row, and the metadata says decimation ${show(x)}: " +
            "one of them is wrong (the fit's time axis is the row number over the sample rate)"))
          .orElse((2 until ix.length).find(i => step(i) != d).map { i =>
            s"sample_index steps by ${step(i)} from ${show(ix(i - 1))} to ${show(ix(i))} (data row ${i + 1}) where it stepped by $d before: " +
              "records are missing, and the fit's time axis needs every row in its place; explain the rows before and after apart"
          })
      })
  }
  /** A 32-bit count's largest value (the board's sample index wraps after it). */
  private val MaxCount = 4294967295.0

  /** A channel's share of samples at the end codes above which a recording is not explained. */
  val MaxRailShare = 0.5

  /** Options may also follow the file names (mainargs puts everything after the first file into `rest`). */
  def explainArgs(rest0: Seq[String], jsonDir: Option[String], plots: Option[String], model: Option[String], quiet: Boolean,
                  subdiv: Option[String] = None, noRtl: Boolean = false, html: Option[String] = None, htmlDir: Option[String] = None,
                  minEffectLsb: Option[Double] = None, minEffectNoise: Option[Double] = None,
                  searchSamples: Int = Interleaved.SearchSamples): Unit = {
    // help where --help or -h is a word of its own, not an option's value (`--subdiv --help` is --subdiv's, refused there)
    val valued = Set("--json-dir", "--plots", "--model", "--subdiv", "--html", "--html-dir", "--min-effect-lsb", "--min-effect-noise", "--search-samples")
    // `--name=value` as `--name value`, as mainargs reads the options before the files
    val rest = moire.options.NameValue.split(rest0, valued)
    if (rest.indices.exists(k => (rest(k) == "--help" || rest(k) == "-h") && !(k > 0 && valued(rest(k - 1))))) { println(Usage); return }
    var j = jsonDir; var p = plots; var m = model; var q = quiet; val files = Seq.newBuilder[String]
    var h = html; var hd = htmlDir
    var sd = subdiv; var nr = noRtl; var ml = minEffectLsb; var mn = minEffectNoise; var ss = searchSamples
    var i = 0
    def value(o: String) = { i += 1; rest.lift(i).getOrElse(throw new ExplainError(s"$o needs a value")) }
    def number(o: String): Double = { val v = value(o); moire.numbers.Decimal.double(v).getOrElse(throw new ExplainError(s"$o needs a number, got '$v'")) }
    while (i < rest.length) {
      rest(i) match {
        case "--json-dir" => j = Some(value("--json-dir"))
        case "--plots" => p = Some(value("--plots"))
        case "--model" => m = Some(value("--model"))
        case "--quiet" => q = true
        case "--subdiv" => sd = Some(value("--subdiv"))
        case "--no-rtl" => nr = true
        case "--html" => h = Some(value("--html"))
        case "--html-dir" => hd = Some(value("--html-dir"))
        case "--min-effect-lsb" => ml = Some(number("--min-effect-lsb"))
        case "--min-effect-noise" => mn = Some(number("--min-effect-noise"))
        case "--search-samples" => ss = searchSamplesOf(value("--search-samples"))
        case o if o.startsWith("--") => throw new ExplainError(s"Unknown argument: $o (see --help)")
        case f => files += f
      }
      i += 1
    }
    // emit-subdiv options start with "--": a file name there was taken as the option's value
    sd.filter(v => v.trim.nonEmpty && !v.trim.startsWith("-")).foreach(v => throw new ExplainError(
      s"--subdiv takes the subdivider's emit-subdiv options as one quoted word (e.g. --subdiv \"--counts 4096\"), got '$v'"))
    if (nr && sd.exists(_.trim.nonEmpty)) throw new ExplainError("--subdiv sets the subdivider the RTL check runs, and --no-rtl leaves that check out: give one of them")
    val floor = try Materiality(ml.getOrElse(Materiality.MinLsb), mn.getOrElse(Materiality.MinNoise))
      catch { case e: IllegalArgumentException => throw new ExplainError(e.getMessage.stripPrefix("requirement failed: ")) }
    explain(files.result(), j, p, m, q, if (nr) None else Some(sd.toSeq.flatMap(_.trim.split("\\s+")).filter(_.nonEmpty)), h, hd, floor, ss)
  }

  /** The least `--search-samples` (a subsample shorter than this holds too few fringe periods to search). */
  val MinSearchSamples = 10000
  /** `--search-samples N`: N in MinSearchSamples..2^31-1, or 0 (every sample searched, however long the record). */
  def searchSamplesOf(v: String): Int = moire.numbers.Decimal.double(v.trim).filter(x => x == math.rint(x)) match {
    case Some(0.0) => Int.MaxValue
    case Some(k) if k >= MinSearchSamples && k <= Int.MaxValue => k.toInt
    case _ => throw new ExplainError(s"--search-samples needs 0 (search every sample) or a whole number of samples from $MinSearchSamples to ${Int.MaxValue}, got '${moire.files.Shown.text(v)}'")
  }

  val Usage: String =
    """Usage: explain FILE... [--json-dir DIR] [--plots DIR] [--html FILE | --html-dir DIR] [--model MODEL.json] [--quiet]
      |  Fit the physics model to each recording (moire-recording v1) or calibration file (moire-calibration v1),
      |  locate where the residual departs from noise, and name the catalogued effects that lower BIC by more than 10.
      |    --json-dir DIR       one JSON report per file (DIR/<name>.json)
      |    --plots DIR          PNG plots (residual against time, phase, frequency; one per finding; Lissajous before
      |                         and after correction; interpolation error); the JSON lists them under "plots"
      |    --html FILE          one self-contained HTML report (plots inline; opens offline, prints); one recording only
      |    --html-dir DIR       one HTML report per recording (DIR/<name>.html); the JSON names it under "html"
      |    --model MODEL.json   effects the simulation already has: fitted, not reported
      |    --quiet              no progress bar or text report
      |    --subdiv "OPTIONS"   emit-subdiv options of the board's subdivider (default: from the metadata adc_bits,
      |                         adc_format, counts_per_period); a recording with a position column is replayed through this
      |                         RTL (Verilator) and the board's outputs are compared with it, sample by sample
      |    --no-rtl             do not compare board outputs with the RTL
      |    --min-effect-lsb X   materiality floor: a finding changes the signal by at least X LSB (default 0.25) ...
      |    --min-effect-noise F ... and F times the noise rms (default 0.1); smaller but significant: `negligible`
      |    --search-samples N   a record of more than N samples (default 250000) is searched on every d-th sample and
      |                         the model found is fitted again on the other d - 1 interleaved subsamples: its parameters
      |                         combined over all samples, or all samples searched where they disagree; 0: search every sample
      |  Effects (the catalogue; docs/explain.md says what each is):
      |""".stripMargin + effects.Effects.help

  def kindOf(p: os.Path): String = {
    moire.files.PathKind.notAFile(p).foreach(m => throw new ExplainError(m))
    CsvText.checkText(p)
    val first = CsvText.firstLine(p).trim
    if (first == Calibration.Magic) "calibration"
    else if (first == Recording.Magic) "signals"
    else throw new ExplainError(s"$p:1: first line must be '${Recording.Magic}' or '${Calibration.Magic}', got '${moire.files.Shown.text(first)}'")
  }

  /** explain-bench's range of --samples: a few fringe periods of the ramp up to the 2^31-sample limit of an array. */
  val BenchMinSamples = 10000
  val BenchMaxSamples = 1 << 30
  /** explain-bench's range of --runs (the same file explained again in the same JVM). */
  val BenchMaxRuns = 10

  /** Simulates a recording with five effects (skew, bandwidth, harmonic, stuck bit, interference), or takes
    * `recording`, and explains it; `say` gets two lines: reading (with the per-file checks) and the whole
    * explain, each with its time, the peak heap and the peak heap per million samples.
    */
  def bench(samples: Int, out: Option[String], recording: Option[String], say: String => Unit, runs: Int = 1,
            searchSamples: Int = Interleaved.SearchSamples): Unit = {
    if (recording.isEmpty && (samples < BenchMinSamples || samples > BenchMaxSamples))
      throw new ExplainError(s"--samples must be in $BenchMinSamples..$BenchMaxSamples, got $samples")
    if (runs < 1 || runs > BenchMaxRuns) throw new ExplainError(s"--runs must be in 1..$BenchMaxRuns, got $runs")
    out.foreach(d => moire.files.SafeWrite.checkFolder(os.Path(d, os.pwd)))
    // without --out the recording, JSON and plots go to a temporary folder, removed at the end (a 20 M recording is 180 MB)
    // named by the process: a test counts its own (other processes' benches come and go beside it)
    val temp = if (out.isEmpty) Some(os.temp.dir(prefix = s"moire-bench-${ProcessHandle.current().pid()}-", deleteOnExit = false)) else None
    try benchIn(out.map(os.Path(_, os.pwd)).orElse(temp).get, samples, recording, say, runs, searchSamples)
    finally temp.foreach(d => try os.remove.all(d) catch { case _: java.io.IOException => () })
  }

  private def benchIn(dir: os.Path, samples: Int, recording: Option[String], say: String => Unit, runs: Int, searchSamples: Int): Unit = {
    val file = recording.map { f =>
      val p = os.Path(f, os.pwd)
      moire.files.PathKind.notAFile(p).foreach(m => throw new ExplainError(m))
      p
    }.getOrElse {
      moire.files.SafeWrite.checkPicked(dir / "bench.csv", Recording.Magic, "another --out folder")
      benchRecording(samples, dir / "bench.csv")
    }
    val mb = os.size(file) / 1048576.0
    val maxMb = Runtime.getRuntime.maxMemory / 1048576.0
    val (n, readS, readPeak) = readChecked(file)
    def perM(peak: Double) = peak / (n / 1e6)
    say(f"explain-bench: read and checked $n rows ($mb%.0f MB file) in $readS%.1f s; peak heap in use $readPeak%.0f MB of $maxMb%.0f MB " +
      f"(${perM(readPeak)}%.1f MB per million samples)")
    // the first run in a new JVM (its JIT compiles the code as it runs), then the same file again in the same JVM
    for (k <- 1 to runs) {
      val cpu0 = cpuSeconds
      val (rep, s, peak) = peakHeap(explain(Seq(file.toString), Some((dir / "json").toString), Some((dir / "plots").toString), None, quiet = runs > 1 && k > 1,
        searchSamples = searchSamples).head)
      val cpu = cpuSeconds - cpu0
      val which = if (runs == 1) "" else if (k == 1) s"run 1 of $runs (new JVM): " else s"run $k of $runs (same JVM): "
      say(f"explain-bench: $which$n samples explained in $s%.1f s (read, fit, JSON, plots) = ${n / s}%.0f samples/s, ${1e6 * s / n}%.1f us per sample; " +
        f"CPU $cpu%.1f s (${cpu / s}%.2f cores busy); " +
        f"peak heap in use $peak%.0f MB of $maxMb%.0f MB (${perM(peak)}%.1f MB per million samples); ${Runtime.getRuntime.availableProcessors} cores" +
        processor.fold("")(m => s" ($m)") + s"; findings: ${rep.findings.map(_.effect).mkString(", ")}")
    }
    Laps.lines.foreach(l => say(s"explain-bench: $l"))
  }

  /** The processor's model (Linux's /proc/cpuinfo), so that figures from different machines are told apart. */
  private def processor: Option[String] =
    try os.read.lines(os.root / "proc" / "cpuinfo").collectFirst { case l if l.startsWith("model name") && l.contains(":") => l.split(":", 2)(1).trim }
      .filter(_.nonEmpty)
    catch { case _: Exception => None }

  /** The rows of a recording read and checked, the seconds and the peak heap it took. The recording is returned to
    * `peakHeap`, so that the collection at the end counts it, and dropped with this method's frame (a local of the
    * caller's frame would hold it, its heap counted again in the explain that follows).
    */
  private def readChecked(file: os.Path): (Int, Double, Double) = {
    val (r, s, p) = peakHeap { val r = Recording.read(file); checkSignals(file, r); r }
    (r.length, s, p)
  }

  /** CPU seconds this process has used (all threads), NaN where the JVM does not say. */
  private def cpuSeconds: Double = java.lang.management.ManagementFactory.getOperatingSystemMXBean match {
    case o: com.sun.management.OperatingSystemMXBean => o.getProcessCpuTime / 1e9
    case _ => Double.NaN
  }

  /** Writes the bench's simulated recording; its arrays are garbage once this returns. */
  private def benchRecording(samples: Int, file: os.Path): os.Path = {
    val m = PhysicsModel(SignalParams(amplitude = 0.9, phaseErrorDeg = 1.0, noiseRms = 0.0007, seed = 7),
      moire.signal.Motion.Ramp(20e3, 250e3, samples / 10e6), 10e6, samples, Adc(12), None,
      Seq(EffectSpec(effects.ChannelSkew.name, Map("skew_s" -> 20e-9)), EffectSpec(effects.Bandwidth.name, Map("cutoff_hz" -> 600e3)),
        EffectSpec(effects.Harmonic.name, Map("order" -> 3, "amplitude_rel" -> 0.001), "sin"),
        EffectSpec(effects.AdcBitFault.name, Map("bit" -> 2, "stuck_at" -> 0), "cos"),
        EffectSpec(effects.Interference.name, Map("frequency_hz" -> 50e3, "amplitude_fs" -> 3e-4))))
    Recording.write(file, m.generate()._1)
    file
  }

  /** The result of `body`, its seconds and its peak heap in MB: the most the heap held after any garbage collection
    * while it ran, or at its end (with its result alive). That is the memory it needs; the heap before a collection
    * also holds garbage, and the heap pools' separate peaks do not happen at one time.
    */
  def peakHeap[T](body: => T): (T, Double, Double) = {
    import java.lang.management.{ManagementFactory, MemoryType}
    import com.sun.management.GarbageCollectionNotificationInfo
    val heap = ManagementFactory.getMemoryPoolMXBeans.asScala.filter(_.getType == MemoryType.HEAP).map(_.getName).toSet
    val peak = new java.util.concurrent.atomic.AtomicLong(0)
    val listener = new javax.management.NotificationListener {
      def handleNotification(n: javax.management.Notification, handback: Any): Unit =
        if (n.getType == GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION) {
          val info = GarbageCollectionNotificationInfo.from(n.getUserData.asInstanceOf[javax.management.openmbean.CompositeData])
          val used = info.getGcInfo.getMemoryUsageAfterGc.asScala.collect { case (pool, u) if heap(pool) => u.getUsed }.sum
          peak.accumulateAndGet(used, (a: Long, b: Long) => math.max(a, b))
        }
    }
    val emitters = ManagementFactory.getGarbageCollectorMXBeans.asScala.collect { case e: javax.management.NotificationEmitter => e }
    System.gc()
    emitters.foreach(_.addNotificationListener(listener, null, null))
    val t0 = System.nanoTime()
    val r = body
    val s = (System.nanoTime() - t0) / 1e9
    System.gc()
    val rt = Runtime.getRuntime
    peak.accumulateAndGet(rt.totalMemory - rt.freeMemory, (a: Long, b: Long) => math.max(a, b))
    emitters.foreach(e => try e.removeNotificationListener(listener) catch { case _: javax.management.ListenerNotFoundException => () })
    (r, s, peak.get / 1048576.0)
  }
}
