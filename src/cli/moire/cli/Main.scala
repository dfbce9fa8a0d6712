package moire.cli

import mainargs.{Flag, ParserForClass, ParserForMethods, arg, main}
import moire.cordic._
import moire.emit.Target
import moire.options.{SubdivCmd, SubdivConfig}
import moire.options.DecimalReader._
import moire.paper.AccuracyRow
import moire.reproduce.Reproduce

/** Options shared by every subcommand that builds a CORDIC. */
@main
case class CordicConfig(
  @arg(doc = "sincos | rotate | atan2 | asin | asin-double | acos | acos-double") mode: String = "sincos",
  @arg(doc = "CORDIC iterations n, 4..40") iterations: Int = 16,
  @arg(doc = "data width b in bits, 8..48") width: Int = 18,
  @arg(doc = "fractional bits of data words (default width - 2)") fracBits: Option[Int] = None,
  @arg(doc = "angle word width, one turn = 2^angle-width (default width)") angleWidth: Option[Int] = None,
  @arg(doc = "extra fractional bits inside the iterations, 0..8") guardBits: Int = 0,
  @arg(doc = "extra angle bits inside the iterations (default ceil(log2 n) + 1)") angleGuardBits: Option[Int] = None,
  @arg(doc = "a pipeline register every k iterations (1 = fully pipelined)") pipelineEvery: Int = 1,
  @arg(doc = "truncate | half-even") rounding: String = "half-even",
  @arg(doc = "leave the outputs scaled by the CORDIC gain K") noGainCompensation: Flag = Flag(),
  @arg(doc = "arcsine peak lookup table entries for [83, 90] degrees (0 = none, power of two)") peakTable: Int = 0,
  @arg(doc = "sincos only: lean datapath, same results, fewer cells (docs/cordic-taper.md)") taper: Flag = Flag()
) {
  /** The params, or one line saying which option is wrong. */
  def params: CordicParams = {
    val m = CordicMode.parse(mode).fold(e => throw new UsageError(e), identity)
    val r = Rounding.parse(rounding).fold(e => throw new UsageError(e), identity)
    // left out means the default (-1 inside the params); a negative value given is a mistake, not the default
    for ((opt, v, allowed) <- Seq(("frac-bits", fracBits, s"1..${width - 1}"), ("angle-width", angleWidth, "8..48"),
      ("angle-guard-bits", angleGuardBits, "0..8")); x <- v if x < 0)
      throw new UsageError(s"--$opt must be in $allowed (or left out for the default), got $x")
    try CordicParams(m, iterations, width, fracBits.getOrElse(-1), angleWidth.getOrElse(-1), guardBits, angleGuardBits.getOrElse(-1), pipelineEvery, r,
      !noGainCompensation.value, peakTable, taper.value)
    catch { case e: IllegalArgumentException => throw new UsageError("--" + e.getMessage.stripPrefix("requirement failed: ")) }
  }
}

/** A user mistake: printed as one line, exit code 2. */
final class UsageError(msg: String) extends moire.MoireError(msg)

object Main {
  implicit val configParser: ParserForClass[CordicConfig] = ParserForClass[CordicConfig]
  implicit val subdivParser: ParserForClass[SubdivConfig] = ParserForClass[SubdivConfig]

  @main(doc = "Write the SystemVerilog of one CORDIC configuration into a folder.")
  def emit(config: CordicConfig, @arg(doc = "output folder") out: String = "generated"): Unit = {
    val d = moire.designs.Designs.cordic(config.params)
    val file = d.write(folder(out), Target.SystemVerilog).head
    println(s"wrote $file (${d.topName}, latency ${d.latency.get} clocks)")
  }

  @main(doc = "Logic cells, registers, memory bits, multipliers and longest path (yosys synth_intel, Cyclone IV E) of a design.")
  def cost(config: CordicConfig,
           @arg(doc = "a design of the registry (see designs): cordic (the emit options), subdiv, quadcomp, adapt, corrected, harmonic, ...") design: String = "cordic",
           @arg(doc = "also write the figures as JSON to this file") json: Option[String] = None,
           @arg(doc = "seconds each yosys run may take (default 1800)") timeout: Int = 1800,
           @arg(doc = "keep the Verilog and yosys files in this folder") keep: Option[String] = None,
           @arg(doc = "sweep iterations x width over the CORDIC variants instead; writes CSV, JSON and PNG") sweep: Flag = Flag(),
           @arg(doc = "sweep: output folder (default cost-sweep)") out: String = "cost-sweep",
           @arg(doc = "sweep: comma-separated variants (default sincos,sincos-taper,sincos-taper-g2,asin,asin-double,asin-table; also sincos-truncate)") variants: String = "sincos,sincos-taper,sincos-taper-g2,asin,asin-double,asin-table",
           @arg(doc = "sweep: comma-separated iteration counts (default 8,12,16)") sweepIterations: String = "8,12,16",
           @arg(doc = "sweep: comma-separated widths (default 12,16,20)") sweepWidths: String = "12,16,20",
           @arg(doc = "sweep: keep (n, b) with b - spread <= n <= b (default 4)") spread: Int = 4,
           @arg(doc = "sweep: skip the measured error of the bit-accurate model") noMeasure: Flag = Flag()): Unit =
    if (sweep.value) {
      // the sweep makes its own configurations: a design's options would be ignored
      if (given("--design", "--keep").nonEmpty || cordicGiven.nonEmpty)
        throw new UsageError("--sweep sweeps the CORDIC variants over --sweep-iterations and --sweep-widths; --design, --keep and the CORDIC options (--iterations, --width, ...) do not apply")
      CostCmd.sweep(variants, sweepIterations, sweepWidths, spread, folderName(out), timeout, !noMeasure.value, json)
    } else {
      val sweepOnly = given("--out", "--variants", "--sweep-iterations", "--sweep-widths", "--spread", "--no-measure")
      if (sweepOnly.nonEmpty) throw new UsageError(s"${sweepOnly.mkString(", ")} ${if (sweepOnly.size == 1) "applies" else "apply"} to --sweep only; add --sweep, or leave ${if (sweepOnly.size == 1) "it" else "them"} out")
      cordicOptionsFor(design, config)
      CostCmd.run(config, design, json, timeout, keep.map(folderName(_, "--keep")))
    }

  /** The CORDIC options (the emit options) make the cordic design only: given with another design they would be
    * ignored, and the figures would be for a configuration nobody asked for.
    */
  private def cordicOptionsFor(design: String, config: CordicConfig): Unit =
    if (design != "cordic" && cordicGiven.nonEmpty)
      throw new UsageError(s"the CORDIC options (--mode, --iterations, --width, ...) apply to --design cordic only, not $design; leave them out")

  @main(doc = "Fmax, utilisation and critical path on the LFE5U-85F (yosys synth_ecp5, nextpnr-ecp5) at speed grades 6 and 8; exit code 1 when a design misses its target.")
  def timing(config: CordicConfig,
             @arg(doc = "a design of the registry (see designs): cordic (the emit options), subdiv, quadcomp, adapt, corrected, harmonic, board-de2-115, ...") design: Option[String] = None,
             @arg(doc = "every design of the registry") all: Flag = Flag(),
             @arg(doc = "comma-separated speed grades (default 6,8)") speeds: String = "6,8",
             @arg(doc = "target clock in MHz (default 65, the AD9226's full rate)") targetMhz: Double = 65.0,
             @arg(doc = "nextpnr router: router1 | router2 (default router2)") router: String = "router2",
             @arg(doc = "place with I/O buffers and global clocks (default: out of context)") inContext: Flag = Flag(),
             @arg(doc = "also write the figures as JSON to this file") json: Option[String] = None,
             @arg(doc = "also write a markdown table to this file") markdown: Option[String] = None,
             @arg(doc = "cache folder (default ~/.cache/moire-tools/timing; $MOIRE_TOOLS moves it)") cache: Option[String] = None,
             @arg(doc = "seconds each tool run may take (default 3600)") timeout: Int = 3600): Unit = {
    design.foreach(cordicOptionsFor(_, config))
    if (!TimingCmd.run(config, design, all.value, speeds, targetMhz, router, inContext.value, json, markdown, cache, timeout)) sys.exit(1)
  }

  @main(doc = "Write the SystemVerilog of the subdivider with its ADC front end into a folder.")
  def emitSubdiv(config: SubdivConfig, @arg(doc = "output folder") out: String = "generated"): Unit = println(SubdivCmd.run(config, folderName(out)))

  @main(doc = "Reproduce the papers' accuracy tables; exit code 0 only when every row holds.")
  def accuracy(@arg(doc = "also write the rows as JSON to this file") json: Option[String] = None): Unit = {
    json.foreach(f => moire.files.SafeWrite.checkMade(moire.files.SafeWrite.fileArg(f)))   // before the work, not after it
    val rows = Reproduce.rows(s => System.err.println(s"accuracy: $s ..."))
    AccuracyTable.print(rows)
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      moire.files.SafeWrite.madeText(path, ujson.write(ujson.Arr(rows.map(_.json): _*), indent = 2))
      println(s"wrote $path")
    }
    val failed = rows.count(!_.holds)
    if (failed > 0) { println(s"$failed of ${rows.size} rows do not hold"); sys.exit(1) }
    println(s"all ${rows.size} rows hold")
  }

  @main(doc = "Measured maximum error of the bit-accurate model next to its a priori bound, over an n x b sweep; exit code 1 when the model exceeds a bound. A bound no better than a constant output (half the output's range) is marked vacuous.")
  def bounds(@arg(doc = "one mode, or all when left out") mode: Option[String] = None,
             @arg(doc = "comma-separated iteration counts") iterations: String = "8,12,16,20,24",
             @arg(doc = "comma-separated data widths") widths: String = "12,16,18,24,32"): Unit = {
    def ints(opt: String, s: String) = {
      val vs = s.split(",", -1).toSeq.map(v => moire.numbers.Decimal.int(v).getOrElse(
        throw new UsageError(s"--$opt: '$v' is not an integer list like 8,12,16")))
      Lists.once(opt, vs)
    }
    val modes = mode.map(m => Seq(CordicMode.parse(m).fold(e => throw new UsageError(e), identity))).getOrElse(CordicMode.all)
    val ns = ints("iterations", iterations); val bs = ints("widths", widths)
    val configs = for (m <- modes; n <- ns; b <- bs) yield (m, n, b)
    val ps = configs.map { case (m, n, b) =>
      try CordicParams(m, n, b)
      catch { case e: IllegalArgumentException => throw new UsageError(e.getMessage.stripPrefix("requirement failed: ")) }
    }
    println(f"${"mode"}%-12s ${"n"}%3s ${"b"}%3s ${"measured"}%11s ${"bound"}%11s ${"unit"}%-11s inputs  ok")
    var bad = 0; var vacuous = 0
    for ((p, i) <- ps.zipWithIndex) {
      if (System.console() != null) System.err.print(s"\rbounds: ${i + 1}/${ps.size} ")
      val m = CordicAccuracy.measure(p)
      if (!m.ok) bad += 1 else if (m.vacuous) vacuous += 1
      val ok = if (!m.ok) "NO" else if (m.vacuous) "vacuous" else "yes"
      println(f"\r${p.mode.name}%-12s ${p.iterations}%3d ${p.width}%3d ${m.maxError}%11.4e ${m.bound}%11.4e ${m.unit}%-11s ${m.samples}%6d  $ok")
    }
    if (System.console() != null) System.err.println()
    // met, but a constant output would meet it too: say so rather than "yes"
    if (vacuous > 0) println((if (vacuous == 1) "1 configuration has a vacuous bound" else s"$vacuous configurations have vacuous bounds") +
      " (half the output's range or more, which a constant output meets): the rounding of n iterations swamps b bits; use fewer iterations or more width")
    if (bad > 0) { println(if (bad == 1) "1 configuration exceeds its bound" else s"$bad configurations exceed their bound"); sys.exit(1) }
  }

  @main(doc = "Cheapest (iterations, width) whose error bound meets a target, confirmed by simulation.")
  def design(@arg(doc = "sin | asin | atan2 (cos and sincos name sin's unit, acos asin's)") function: String,
             @arg(doc = "largest error allowed (full scale 1.0 for sin, radians for angles)") maxError: Double,
             @arg(doc = "truncate | half-even") rounding: String = "half-even",
             @arg(doc = "asin only: peak lookup table entries (power of two, 0 = none)") peakTable: Int = 0): Unit = {
    val r = Rounding.parse(rounding).fold(e => throw new UsageError(e), identity)
    if (!(maxError > 0) || maxError.isInfinite) throw new UsageError(s"--max-error must be a positive finite number, got $maxError")
    val d = Designer.cheapest(function, maxError, r, peakTable).fold(e => throw new UsageError(e), identity)
    println(d.report)
  }

  @main(doc = "Write the SystemVerilog of the turntable harmonic compensator (seed 001) and its quadrature counter.")
  def emitHarmonic(@arg(doc = "grating lines per turn, power of two (default 16384)") lines: Int = 16384,
                   @arg(doc = "read-head subdivision, power of two (default 1024)") subdivision: Int = 1024,
                   @arg(doc = "m, parallel CORDIC sines, 1..32 (default 4)") harmonics: Int = 4,
                   @arg(doc = "CORDIC iterations n (default 16)") iterations: Int = 16,
                   @arg(doc = "CORDIC data bits b, the fraction of the sine (default 18)") dataBits: Int = 18,
                   @arg(doc = "output folder (default generated)") out: String = "generated"): Unit =
    CalibrateCmd.emit(lines, subdivision, harmonics, iterations, dataBits, folderName(out))

  @main(doc = "Write the SystemVerilog of a registered design at its default parameters (see designs).")
  def emitDatapath(@arg(doc = "a design name: quadcomp | adapt | corrected | harmonic | ... (see designs)") design: String,
                   @arg(doc = "output folder (default generated)") out: String = "generated"): Unit =
    println(DatapathCmd.run(design, folderName(out)))

  @main(doc = "List the registered designs (emit-datapath, cost, timing, replay and board read this registry).")
  def designs(): Unit = DatapathCmd.list.foreach(println)

  @main(doc = "Fit the m largest harmonics to a moire-calibration v1 CSV; write the coefficient file, register listing and plot.")
  def calibrate(@arg(doc = "calibration CSV (moire-calibration v1)") input: String,
                @arg(doc = "m, harmonics kept (parallel CORDICs on the board), 1..32 (default 4)") harmonics: Int = 4,
                @arg(doc = "highest order fitted (default (distinct angles - 1) / 2, at most 32)") maxOrder: Option[Int] = None,
                @arg(doc = "grating lines per turn, power of two (default 16384)") lines: Int = 16384,
                @arg(doc = "read-head subdivision, power of two (default 1024)") subdivision: Int = 1024,
                @arg(doc = "output folder (default calibration)") out: String = "calibration"): Unit =
    CalibrateCmd.run(input, harmonics, maxOrder.map { k =>
      if (k < 0) throw new UsageError(s"--max-order must be at least 1 (or left out for the default), got $k"); k
    }.getOrElse(-1), lines, subdivision, folderName(out))

  @main(doc = "Write a moire-recording v1 file from the physics model (default part plus named effects).")
  def simulate(@arg(doc = "output CSV file") out: String,
               @arg(doc = "number of samples") samples: Int = 100000,
               @arg(doc = "sample rate in Hz") sampleRateHz: Double = 10e6,
               @arg(doc = "ADC bits") adcBits: Int = 12,
               @arg(doc = "offset-binary | twos-complement") adc: String = "offset-binary",
               @arg(doc = "constant:HZ | ramp:HZ0:HZ1:SECONDS | oscillate:PERIODS:RATE_HZ") motion: String = "ramp:20000:200000:0.01",
               @arg(doc = "fringe amplitude, full scale 1") amplitude: Double = 0.9,
               offsetSin: Double = 0.0, offsetCos: Double = 0.0, gainSin: Double = 1.0, gainCos: Double = 1.0,
               @arg(doc = "quadrature phase error, degrees") phaseErrorDeg: Double = 0.0,
               @arg(doc = "white noise rms, full scale") noise: Double = 0.0005,
               seed: Long = 1L,
               @arg(doc = "grating lines per revolution (amplitude_modulation)") linesPerRev: Option[Double] = None,
               @arg(doc = "an effect NAME:key=value,... (repeat; channel=sin|cos|both where the effect takes it); the effects and their keys are listed below") effect: Seq[String] = Nil,
               @arg(doc = "a model JSON file (the JSON simulate writes into the # model: line); the options set what it does not") model: Option[String] = None): Unit =
    println(moire.files.SafeWrite.writesRecordings.withValue(true)(moire.explain.ExplainCmd.simulate(moire.explain.ExplainCmd.SimOptions(out, samples, sampleRateHz, adcBits, adc, motion,
      amplitude, offsetSin, offsetCos, gainSin, gainCos, phaseErrorDeg, noise, seed, linesPerRev, effect, model, said.value))))

  @main(doc = "Fit the physics model to recordings, locate the misfit, name the effects left out (JSON and PNG per file).")
  def explain(@arg(doc = "recording or calibration files") files: mainargs.Leftover[String],
              @arg(doc = "folder for one JSON report per file") jsonDir: Option[String] = None,
              @arg(doc = "folder for PNG plots") plots: Option[String] = None,
              @arg(doc = "model JSON whose effects are part of the simulation (fitted, not reported)") model: Option[String] = None,
              @arg(doc = "no progress bar or text report") quiet: Flag = Flag(),
              @arg(doc = "emit-subdiv options of the board's subdivider, e.g. \"--counts 4096\" (default: from the metadata)") subdiv: Option[String] = None,
              @arg(doc = "do not compare a recording's board outputs (position column) with the RTL") noRtl: Flag = Flag(),
              @arg(doc = "one self-contained HTML report (plots inline) of the one recording") html: Option[String] = None,
              @arg(doc = "folder for one HTML report per recording") htmlDir: Option[String] = None,
              @arg(doc = "materiality floor in LSB: a finding changes the signal by at least this much (default 0.25)") minEffectLsb: Option[Double] = None,
              @arg(doc = "materiality floor as a fraction of the noise rms (default 0.1)") minEffectNoise: Option[Double] = None,
              @arg(doc = "a longer record is searched on every d-th sample and confirmed on the others (default 250000; 0: search every sample)") searchSamples: Option[String] = None): Unit =
    moire.explain.ExplainCmd.explainArgs(files.value, jsonDir, plots, model, quiet.value, subdiv, noRtl.value, html, htmlDir, minEffectLsb, minEffectNoise,
      searchSamples.map(moire.explain.ExplainCmd.searchSamplesOf).getOrElse(moire.explain.Interleaved.SearchSamples))

  @main(doc = "Benchmark: simulate and explain one recording; print the time, samples per second and peak heap (also per million samples) of reading and of the whole explain.")
  def explainBench(@arg(doc = "samples in the recording (default 1000000)") samples: Int = 1000000,
                   @arg(doc = "folder for the recording, JSON and plots (default: a temporary folder)") out: Option[String] = None,
                   @arg(doc = "explain this moire-recording v1 file instead of a simulated one (not with --samples)") recording: Option[String] = None,
                   @arg(doc = "explain the file this many times in one JVM, each run's figures printed: the first includes the JIT's compiling, the others show the fit alone (1..10, default 1)") runs: Int = 1,
                   @arg(doc = "as explain's: a longer record is searched on every d-th sample and confirmed on the others (default 250000; 0: search every sample)") searchSamples: Option[String] = None): Unit =
    if (recording.isDefined && given("--samples").nonEmpty) throw new UsageError("--samples sets the simulated recording's length; with --recording the file's length is taken: leave --samples out")
    else moire.explain.ExplainCmd.bench(samples, out.map(folderName(_)), recording, println(_), runs,
      searchSamples.map(moire.explain.ExplainCmd.searchSamplesOf).getOrElse(moire.explain.Interleaved.SearchSamples))

  @main(doc = "Write a board project: the board's top in Verilog inside its vendor project, and the command to run next.")
  def board(@arg(doc = "board name, one of the boards below (also accepted as the first word after board)") name: String,
            @arg(doc = "output folder (default generated/NAME)") out: Option[String] = None,
            @arg(doc = "subdiv | corrected | compensated (subdiv + turntable harmonic compensation, coefficients by board-reg)") design: String = "subdiv",
            @arg(doc = "system clock in Hz: de2-115 50000000 only; ulx3s what its PLL makes exactly from 25 MHz, e.g. 65000000 (default 50000000)") clockHz: Int = 50000000,
            @arg(doc = "AD9226 clock in Hz, clock-hz / k (default 50000000)") adcClockHz: Int = 50000000,
            @arg(doc = "ADC strap: offset-binary | twos-complement") adcFormat: String = "offset-binary",
            @arg(doc = "default decimation D, 1..16777216 (default 100000)") decimation: Int = 100000,
            @arg(doc = "UART baud rate (default 115200)") baud: Int = 115200,
            @arg(doc = "records per frame n, 1..255 (default 8)") frameRecords: Int = 8,
            @arg(doc = "record FIFO depth (default 256)") fifoDepth: Int = 256,
            @arg(doc = "encoder inputs: clocks stable before a level is taken (default 16)") glitchFilter: Int = 16,
            @arg(doc = "M, counts per grating period (default 1024)") counts: Int = 1024,
            @arg(doc = "pll | logic (no PLL, for simulation; ulx3s: clock-hz 25000000)") clockSource: String = "pll",
            @arg(doc = "design compensated: fringe periods per turn, a power of two (default 16384)") lines: Option[Int] = None,
            @arg(doc = "design compensated: harmonic slots m, 1..32 (default 4)") harmonics: Option[Int] = None): Unit = {
    import moire.board.BoardCmd
    try {
      BoardCmd.checkBoard(name)
      // options of the compensated design change nothing in the others: given there, they are a mistake
      for ((o, v) <- Seq("--lines" -> lines, "--harmonics" -> harmonics) if v.isDefined && design != "compensated")
        throw new UsageError(s"$o applies to --design compensated only, not $design")
      val p = try BoardCmd.params(name, design, adcClockHz, adcFormat, decimation, baud, frameRecords, fifoDepth, glitchFilter, counts, clockSource,
        clockHz, lines.getOrElse(16384), harmonics.getOrElse(4)) catch {
        // the default ADC clock that a --clock-hz given does not divide: said as that, not as an --adc-clock-hz typed
        case e: BoardCmd.BadOption if e.getMessage.startsWith("--adc-clock-hz") && given("--adc-clock-hz").isEmpty =>
          val k = (math.max(1, math.ceil(clockHz / 65e6).toInt) to 1000).find(clockHz % _ == 0)
          throw new UsageError(s"--clock-hz $clockHz: the default --adc-clock-hz $adcClockHz does not divide it; give --adc-clock-hz, " +
            s"--clock-hz divided by an integer 1..1000" + k.fold("")(k => s" (${clockHz / k} is the fastest within the AD9226's 65 MS/s)"))
      }
      moire.designs.BoardProject.run(name, p, out.fold(os.Path(s"generated/$name", os.pwd))(folder(_))).foreach(println)
    } catch { case e: BoardCmd.BadOption => throw new UsageError(e.getMessage) }
  }

  @main(doc = "Record a board's UART stream for some seconds, or one full-rate burst (--burst N), into a moire-recording v1 file (docs/recording.md).")
  def record(@arg(doc = "serial port, e.g. /dev/ttyUSB0") port: String,
             @arg(doc = "seconds to record (required without --burst); with --burst: seconds to wait for the trigger (default 10)") seconds: Option[Double] = None,
             @arg(doc = "output CSV file") out: String,
             @arg(doc = "UART baud rate (default 115200)") baud: Int = 115200,
             @arg(doc = "write this decimation D to the board first (with --listen-only: the board's D)") decimation: Option[Long] = None,
             @arg(doc = "ADC clock in Hz instead of register adc_clock_hz") adcClockHz: Option[Double] = None,
             @arg(doc = "offset-binary | twos-complement instead of register adc_format") adcFormat: Option[String] = None,
             @arg(doc = "counts per grating period M instead of register counts_per_period") countsPerPeriod: Option[Long] = None,
             @arg(doc = "send no commands; needs --decimation, --adc-clock-hz, --adc-format, --counts-per-period") listenOnly: Flag = Flag(),
             @arg(doc = "capture N consecutive samples at the full ADC rate instead of the decimated stream") burst: Option[Long] = None,
             @arg(doc = "burst trigger: now (default), speed:T (counts per 1024 samples), z (reference Z), position:P (counts)") trigger: String = "now",
             @arg(doc = "burst samples before the trigger (default 0)") pre: Long = 0,
             @arg(doc = "reference encoder counts per grating period (metadata for the ref_counts column)") refCountsPerPeriod: Option[Double] = None,
             @arg(doc = "reference encoder counts per turn (metadata for the ref_counts column)") refCountsPerTurn: Option[Double] = None,
             @arg(doc = "milliseconds to wait for each register reply (default 500)") timeoutMs: Int = 500,
             @arg(doc = "no progress bar") quiet: Flag = Flag()): Unit = {
    val secs = seconds.orElse(burst.map(_ => 10.0)).getOrElse(throw new UsageError("record: give --seconds S (continuous stream) or --burst N (one full-rate burst)"))
    // the trigger and the samples before it belong to a burst: a stream would record without them
    if (burst.isEmpty && given("--trigger", "--pre").nonEmpty) throw new UsageError("--trigger and --pre apply to a burst; add --burst N, or leave them out")
    moire.files.SafeWrite.fileArg(out) // an empty name, a control character, "-" or a trailing / said as that
    val o = moire.stream.RecordOptions(port, secs, out, baud, decimation, adcClockHz, adcFormat, countsPerPeriod,
      listenOnly.value, timeoutMs, quiet.value, refCountsPerPeriod, refCountsPerTurn)
    moire.files.SafeWrite.writesRecordings.withValue(true)(burst match {
      case Some(n) => moire.stream.BurstRecorder.run(o, moire.stream.BurstOptions(n, trigger, pre, secs), println(_), System.err.println(_))
      case None => moire.stream.Recorder.run(o, println(_), System.err.println(_))
    })
  }

  @main(doc = "Read and write the board's registers by name (load, writes, coefficients, reads, save; none: read all).")
  def boardReg(@arg(doc = "serial port, e.g. /dev/ttyUSB0") port: String,
               @arg(doc = "UART baud rate (default 115200)") baud: Int = 115200,
               @arg(doc = "register name or address to read (repeat)") read: Seq[String] = Nil,
               @arg(doc = "NAME=VALUE to write (repeat)") write: Seq[String] = Nil,
               @arg(doc = "harmonic coefficient file from calibrate (.coefficients.json or .registers.txt)") coefficients: Option[String] = None,
               @arg(doc = "milliseconds to wait for each register reply (default 500)") timeoutMs: Int = 500,
               @arg(doc = "save the decimation and the harmonic slots, with the board's model, to this JSON file (docs/recording.md)") save: Option[String] = None,
               @arg(doc = "restore a file of --save (first; the board's model must match)") load: Option[String] = None): Unit =
    moire.stream.BoardReg.run(moire.stream.BoardReg.Options(port, baud, read, write, coefficients, timeoutMs, save, load), println(_))

  @main(doc = "Watch a board live in the browser: Lissajous figure, fitted ellipse, readouts with tolerance marks, position, flags, link; capture a burst and explain it (docs/monitor.md).")
  def monitor(@arg(doc = "serial port of the board, e.g. /dev/ttyUSB0") port: Option[String] = None,
              @arg(doc = "play a moire-recording v1 file at its own rate (in a loop) instead of a board") replay: Option[String] = None,
              @arg(doc = "a simulated board (the physics model) instead of a board") simulate: Flag = Flag(),
              @arg(doc = "with --simulate: an effect NAME:key=value,... (repeat; default a 3rd harmonic of 0.3 % on sin)") effect: Seq[String] = Nil,
              @arg(doc = "UART baud rate (default 115200)") baud: Int = 115200,
              @arg(doc = "write this decimation D to the board first") decimation: Option[Long] = None,
              @arg(doc = "address the web server listens on (default 127.0.0.1, this computer only)") bind: String = "127.0.0.1",
              @arg(doc = "TCP port of the web page (default 8642; 0 = any free port)") httpPort: Int = 8642,
              @arg(doc = "folder that save writes into (default monitor)") out: String = "monitor",
              @arg(doc = "counts per grating period M (default: the board's register or the recording's metadata)") countsPerPeriod: Option[Double] = None,
              @arg(doc = "grating period in um: positions and speeds in um") periodUm: Option[Double] = None,
              @arg(doc = "grating lines per revolution: positions in degrees and arcsec") linesPerRev: Option[Double] = None,
              @arg(doc = "volts at ADC full scale 1.0 (AD9226 at 2 Vpp span: 1): amplitudes in volts") fullScaleV: Option[Double] = None): Unit =
    moire.monitor.MonitorCmd.run(moire.monitor.MonitorCmd.Options(port, replay, simulate.value, effect, baud, decimation, bind, httpPort, folderName(out),
      moire.monitor.Scale(countsPerPeriod, periodUm, linesPerRev, fullScaleV), given("--baud", "--decimation")), println(_), System.err.println(_))

  @main(doc = "Run a recording's ADC codes through the generated RTL (Verilator); see replay --help.")
  def replay(@arg(doc = "FILE [--design subdiv|corrected] [--out OUT.csv] [--quiet] [emit-subdiv options]") args: mainargs.Leftover[String]): Unit =
    if (!moire.replay.ReplayCmd.run(ReplayArgs.parse(args.value))) sys.exit(1)

  def oneLine(msg: String): String = SubdivCmd.oneLine(msg)

  /** The subcommands' names, as typed. */
  def commandNames: Seq[String] = ParserForMethods(this).mains.value.map(_.name(mainargs.Util.kebabCaseNameMapper))

  /** `help CMD` and `CMD --help`: the command's options with their defaults. */
  /** An output folder option as given: an empty name is refused (it would be the working folder, not named). */
  private def folder(given: String, option: String = "--out"): os.Path = moire.files.SafeWrite.folderArg(given, option)
  private def folderName(given: String, option: String = "--out"): String = { folder(given, option); given }

  private def commandHelp(mains: Seq[mainargs.MainData[Any, Main.type]], cmd: String): Int =
    mains.find(_.name(mainargs.Util.kebabCaseNameMapper) == cmd) match {
      case None => say(s"'$cmd' is not a command (moire --help lists them)"); 2
      case Some(_) if cmd == "replay" => println(moire.replay.ReplayCmd.Usage); 0
      case Some(m) =>
        val extra = cmd match {
          case "simulate" => "effects (--effect NAME:key=value,...; channel=sin|cos|both where it is named):\n" +
            moire.explain.EffectSpec.catalogue.map { case (n, keys, doc) => s"  $n (${keys.mkString(", ")}): $doc" }.mkString("\n")
          case "board" => "boards:\n" + moire.board.Boards.all.map(b =>
            s"  ${b.name} (${b.title}): ${b.target.toString.toLowerCase} files, designs ${b.designs.map(_.name).mkString(", ")}" +
              s" (in the design registry: ${b.registryDesigns.map(b.registryName).mkString(", ")})").mkString("\n")
          case _ => ""
        }
        println(Help.command(m, this, extra)); 0
    }

  // a recording stopped by Ctrl-C is waited for until its last line is said (`Interrupts`)
  def main(args: Array[String]): Unit = { val code = moire.files.Interrupts.command(run(args)); if (code != 0) sys.exit(code) }

  /** The command line without leaving the JVM: the exit code (2 for a user's mistake, told in one line). */
  def run(args: Array[String]): Int = {
    val parser = ParserForMethods(this)
    val mains = parser.mains.value
    // the launcher's own words: the overview (also with no argument: it writes nothing), help, the version
    args.toSeq match {
      case Seq() | Seq("-h") | Seq("--help") | Seq("help") => println(Help.overview(mains)); return 0
      case Seq("--version") | Seq("-V") => println(s"moire ${Version.text}"); return 0
      case Seq(o @ ("--version" | "-V" | "--help" | "-h"), extra, _*) =>
        say(s"$o takes no arguments, got '$extra'" + (if (o.startsWith("-h") || o == "--help") " (moire help COMMAND for a command's help)" else "")); return 2
      case Seq("help", cmd) => return commandHelp(mains, cmd)
      case Seq("help", _*) => say("help takes one command name, e.g. moire help explain"); return 2
      case a if a.head.startsWith("-") =>
        say(s"'${a.head}' is not a command; moire COMMAND [options] (moire --help lists the commands)"); return 2
      case a if helpAsked(mains, a) => return commandHelp(mains, a.head)
      case _ => ()
    }
    // a byte of a name that is no UTF-8 (a Latin-1 file name) reaches the JVM as U+FFFD: the file named so is another
    // one (simulate --out wrote "caf\ufffd.csv" for caf\xe9.csv) or none (explain said "no such file" of a file there)
    args.find(_.contains('\uFFFD')).foreach { a =>
      say(s"'$a': holds bytes that are not UTF-8 (shown as \\ufffd), and moire reads and writes UTF-8 names only; rename the file (convmv -f latin1 -t utf8)"); return 2 }
    // `board de2-115 --out DIR`: the board name as a positional word.
    val argv = if (args.length > 1 && args(0) == "board" && !args(1).startsWith("-")) Array("board", "--name") ++ args.tail else args
    repeated(mains, argv.toSeq).foreach { msg => say(msg); return 2 }
    valueless(mains, argv.toSeq).foreach { o => say(s"$o needs a value (give $o VALUE or $o=VALUE)"); return 2 }
    val typed = saidOptions(mains, argv.toSeq)
    // a number beyond a double's range would be taken as Infinity, and told back as that
    typed.collectFirst { case (o, v) if NumberWord.matches(v.trim) && v.trim.toDouble.isInfinite => (o, v) }.foreach { case (o, v) =>
      say(s"$o: '$v' is beyond the range of numbers (about +-1.8e308)"); return 2 }
    // a file option left empty named the working folder, and was told back as "/the/folder: is a folder, not a file"
    typed.collectFirst { case (o, v) if FileOptions(o) && v.isEmpty => o }.foreach { o => say(s"$o: the file's name is empty; give a file name"); return 2 }
    moire.files.SafeWrite.forgetMade()
    val code = said.withValue(typed.map(_._1).toSet) { try {
      // runRaw hands back what a command threw (runEither would print it with its class name)
      parser.runRaw(argv.toSeq, allowPositional = false) match {
        case mainargs.Result.Success(_) => return 0
        case mainargs.Result.Failure.Exception(t) => throw t
        case _ => () // a parse error: worded by runEither below, which fails the same way before running anything
      }
      parser.runEither(argv.toSeq, allowPositional = false) match {
        case Left(msg) =>
          say(s"${oneLine(msg)}")
          2
        case Right(_) => 0
      }
    } catch {
      case e: moire.MoireError => say(s"${e.getMessage}"); 2
      // Last resort: what a library let through still becomes one line in words, never a class name.
      case e: java.io.IOException => say(s"${moire.files.SafeWrite.reason(e)}"); 2
      case e: java.nio.file.InvalidPathException =>
        say(s"${plain(e.getInput)}: a file name this locale's character set (${System.getProperty("sun.jnu.encoding")}) " +
          "cannot hold; run moire under a UTF-8 locale, e.g. LC_CTYPE=C.UTF-8"); 2
      case e: IllegalArgumentException =>
        say(s"${plain(Option(e.getMessage).getOrElse("invalid value").stripPrefix("requirement failed: "))}"); 2
      case e: OutOfMemoryError =>
        if (sys.env.contains("MOIRE_DEBUG")) e.printStackTrace()
        say(s"out of memory in a heap of ${Runtime.getRuntime.maxMemory / 1048576} MB; give the JVM more " +
          "(JAVA_OPTS=-Xmx8g moire ..., or moire -J-Xmx8g ...) or a shorter recording"); 2
      case e: Exception =>
        if (sys.env.contains("MOIRE_DEBUG")) e.printStackTrace()
        say(s"internal error: ${plain(Option(e.getMessage).getOrElse("no message"))} (MOIRE_DEBUG=1 shows where)"); 2
    } }
    // a command that failed leaves no empty output folder behind (its outputs' folders are made before the work)
    if (code != 0) moire.files.SafeWrite.removeEmptyMade()
    code
  }

  /** An error line: "moire: " and the message, a value of thousands of characters in it cut (a 100 kB --effect was told
    * back whole), control characters shown as `\x0a` (a name the user typed with a line break or an escape sequence
    * split the line, or reached the terminal).
    */
  private def say(msg: String): Unit = System.err.println("moire: " + brief(moire.files.Shown.text(msg, Int.MaxValue)))
  def brief(msg: String): String = {
    val cut = LongWord.replaceAllIn(msg, m => java.util.regex.Matcher.quoteReplacement(m.matched.take(100) + s"... (${m.matched.length} characters)"))
    if (cut.length > 2000) cut.take(2000) + s"... (${cut.length} characters)" else cut
  }
  private val LongWord = "\\S{241,}".r

  /** An option of the command given twice (`explain --plots a --plots b` took the last): the parser refuses that for a
    * command without a list of files, and this says it alike for every command. Only the command's own options count
    * (a command that passes the rest on, as `replay` does, checks those where it reads them).
    */
  private def repeated(mains: Seq[mainargs.MainData[Any, Main.type]], argv: Seq[String]): Option[String] =
    optionsOf(mains, argv.headOption.getOrElse("")).flatMap { known =>
      val said = saidOptions(mains, argv).filter(x => known.contains(x._1))
      said.groupBy(_._1).toSeq.filter(_._2.size > 1).sortBy(g => said.indexWhere(_._1 == g._1)).headOption.map { case (name, vs) =>
        if (known(name)) s"$name is given ${vs.size} times; give it once"
        else s"$name is given ${vs.size} times (${vs.map(v => "'" + v._2 + "'").mkString(", ")}); give it once"
      }
    }

  /** An option that takes a value but is followed by another of the command's options (`--out --mode x` took
    * "--mode" as the folder) its name.
    */
  private def valueless(mains: Seq[mainargs.MainData[Any, Main.type]], argv: Seq[String]): Option[String] =
    optionsOf(mains, argv.headOption.getOrElse(""), lists = true).flatMap { known =>
      val words = argv.tail.takeWhile(_ != "--")
      var i = 0; var found = Option.empty[String]
      while (i < words.length && found.isEmpty) {
        val w = words(i)
        if (!w.contains('=') && known.get(w).contains(false)) {
          val next = words.lift(i + 1)
          if (next.exists(n => known.contains(n.takeWhile(_ != '=')))) found = Some(w) else i += 1
        }
        i += 1
      }
      found
    }

  /** The options that name a file to read (or board-reg's --save, one to write). */
  private val FileOptions = Set("--model", "--recording", "--input", "--coefficients", "--load", "--save", "--replay")

  /** A decimal number as typed (sign, digits, point, exponent). */
  private val NumberWord = "[+-]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][+-]?[0-9]+)?".r

  /** The CORDIC (emit) options given to the running command, at any value. */
  private def cordicGiven: Seq[String] = {
    val names = configParser.main.argSigs0.flatMap(_.longName(mainargs.Util.kebabCaseNameMapper)).map("--" + _)
    given(names: _*)
  }

  /** The command's options as given, each with the value it took (a flag takes none; a word after `--` is no option, a
    * word taken as an option's value is none either), in order. List options count too.
    */
  private def saidOptions(mains: Seq[mainargs.MainData[Any, Main.type]], argv: Seq[String]): Seq[(String, String)] =
    optionsOf(mains, argv.headOption.getOrElse(""), lists = true).fold(Seq.empty[(String, String)]) { known =>
      val words = argv.tail.takeWhile(_ != "--")
      val out = Seq.newBuilder[(String, String)]; var i = 0
      while (i < words.length) {
        val w = words(i); val name = w.takeWhile(_ != '=')
        known.get(name) match {
          case Some(flag) =>
            if (w.contains('=')) out += name -> w.dropWhile(_ != '=').drop(1)
            else if (flag) out += name -> ""
            else { out += name -> words.lift(i + 1).getOrElse(""); i += 1 }
          case None => ()
        }
        i += 1
      }
      out.result()
    }
  /** The options the running command was given (by name, `--samples`): an option given at its default value is given. */
  private val said = new scala.util.DynamicVariable[Set[String]](Set.empty)
  /** Those of `names` the command was given, in the order of `names`. */
  private def given(names: String*): Seq[String] = names.filter(said.value)

  /** A command's options: name -> whether it is a flag (takes no value); None for no such command. List options (given
    * several times) are not named: `repeated` does not count them.
    */
  private def optionsOf(mains: Seq[mainargs.MainData[Any, Main.type]], cmd: String, lists: Boolean = false): Option[Map[String, Boolean]] =
    mains.find(_.name(mainargs.Util.kebabCaseNameMapper) == cmd).map { m =>
      def names(sigs: Seq[mainargs.ArgSig]): Seq[(String, Boolean)] = sigs.flatMap { a =>
        a.reader match {
          case c: mainargs.TokensReader.Class[_] => names(c.main.argSigs0)
          case r if r.isLeftover => Nil
          case r: mainargs.TokensReader.Simple[_] if r.alwaysRepeatable && !lists => Nil // a list option (`--effect`, repeated)
          case r => a.longName(mainargs.Util.kebabCaseNameMapper).map(l => ("--" + l, r.isFlag)).toSeq
        }
      }
      names(m.argSigs0).toMap
    }

  /** `--help` or `-h` among a command's words, not as an option's value (`explain f.csv --subdiv --help` gives --subdiv
    * the value "--help", which its own check then refuses, instead of showing the help and doing nothing).
    */
  private def helpAsked(mains: Seq[mainargs.MainData[Any, Main.type]], argv: Seq[String]): Boolean = {
    val known = optionsOf(mains, argv.head, lists = true).getOrElse(Map.empty)
    val words = argv.tail.takeWhile(_ != "--")
    words.indices.exists { i =>
      (words(i) == "--help" || words(i) == "-h") && !(i > 0 && known.get(words(i - 1)).contains(false))
    }
  }

  private val className = """\b(?:[a-z][\w]*\.)+[A-Z][\w$]*(?:Exception|Error)?(?::\s*)?""".r
  /** The first line of a message, without Java class names. */
  def plain(msg: String): String =
    className.replaceAllIn(msg.linesIterator.find(_.trim.nonEmpty).getOrElse(""), "").trim match { case "" => "no message"; case s => s }
}
