package moire.options

import mainargs.{arg, main}
import moire.emit.Target
import moire.cordic.Rounding
import moire.signal.AdcFormat
import moire.subdiv.{PhaseMethod, SubdivParams}

/** Options of the subdivider (see moire.subdiv.SubdivParams). */
@main
case class SubdivConfig(
  @arg(doc = "ADC bits, 4..16") inputBits: Int = 12,
  @arg(doc = "atan2 | asin-double") method: String = "atan2",
  @arg(doc = "M, counts per grating period: power of two, 4..65536") counts: Int = 1024,
  @arg(doc = "CORDIC iterations, 4..40") iterations: Int = 16,
  @arg(doc = "CORDIC data width (default input-bits + 6)") cordicWidth: Option[Int] = None,
  @arg(doc = "extra fractional bits inside the CORDIC, 0..8") guardBits: Int = 2,
  @arg(doc = "phase word width (default max(cordic width, log2 M + 2))") phaseBits: Option[Int] = None,
  @arg(doc = "position word width") positionWidth: Int = 32,
  @arg(doc = "A/B edges at least this many clocks apart") minEdgeClocks: Int = 1,
  @arg(doc = "counts the A/B output may lag before overspeed is flagged") backlogLimit: Int = 64,
  @arg(doc = "signal present when the amplitude is at least this (fraction of full scale)") presentThreshold: Double = 0.1,
  @arg(doc = "asin-double: nominal signal amplitude (fraction of full scale, default 0.9)") asinAmplitude: Option[Double] = None,
  @arg(doc = "phase step (turns per sample) above which stepFault is set, <= 0.5") maxStepTurns: Double = 0.46875,
  @arg(doc = "truncate | half-even") rounding: String = "half-even",
  @arg(doc = "ADC pin format: offset-binary | twos-complement") adcFormat: String = "offset-binary"
) {
  def params: SubdivParams = {
    val m = PhaseMethod.parse(method).fold(e => throw new OptionError(e), identity)
    val r = Rounding.parse(rounding).fold(e => throw new OptionError(e), identity)
    // an option that changes nothing is a mistake the user would not see (emit's --peak-table is refused the same way)
    if (asinAmplitude.isDefined && m != PhaseMethod.AsinDouble)
      throw new OptionError(s"--asin-amplitude applies to --method asin-double only, not ${m.name}")
    // left out means the default (-1 inside the params); a negative value given is a mistake, not the default
    for ((opt, v) <- Seq("cordic-width" -> cordicWidth, "phase-bits" -> phaseBits); x <- v if x < 1)
      throw new OptionError(s"--$opt must be a positive width (or left out for the default), got $x")
    try SubdivParams(inputBits, m, counts, iterations, cordicWidth.getOrElse(-1), guardBits, phaseBits.getOrElse(-1), positionWidth, minEdgeClocks,
      backlogLimit, presentThreshold, asinAmplitude.getOrElse(0.9), maxStepTurns, r)
    catch { case e: IllegalArgumentException => throw new OptionError("--" + e.getMessage.stripPrefix("requirement failed: ")) }
  }
  def format: AdcFormat = AdcFormat.parse(adcFormat).fold(e => throw new OptionError(s"--adc-format: $e"), identity)
}
object SubdivCmd {
  /** Writes the board-facing subdivider (ADC front end + subdivider) as SystemVerilog; returns the file,
    * the latency from ADC pins to position, and the top's name.
    */
  def emit(p: SubdivParams, format: AdcFormat, out: String): (os.Path, Int, String) = {
    val d = moire.designs.Designs.subdiv(p, format)
    val files = d.write(os.Path(out, os.pwd), Target.SystemVerilog)
    (files.head, d.latency.get, d.topName)
  }

  def run(c: SubdivConfig, out: String): String = {
    val (file, latency, name) = emit(c.params, c.format, out)
    s"wrote $file ($name, latency $latency clocks from ADC pins to position)"
  }

  private val badValue = """Invalid argument (--\S+) <(\w+)> failed to parse "(.*)" due to.*""".r
  private val firstQuoted = "\"([^\"]*)\"".r
  /** The first line of a mainargs error, reworded for a user. An unknown option is named alone (not with the words
    * after it) and before the missing ones: the parser stops at the first word it does not know, so what follows it
    * (`simulate --fs 0 --out x.csv`: the --out) is missing only because of it.
    */
  def oneLine(msg: String): String = {
    val lines = msg.linesIterator.map(_.trim).filter(_.nonEmpty).toSeq
    // the first word after "Unknown argument(s):", quoted or not
    val word = lines.find(_.startsWith("Unknown argument")).map(_.dropWhile(_ != ':').drop(1).trim)
      .flatMap(w => if (w.startsWith("\"")) firstQuoted.findFirstMatchIn(w).map(_.group(1)) else w.split("\\s+").headOption)
    val head = lines.headOption.getOrElse("bad arguments")
    val first = word match {
      case Some(opt) if opt.startsWith("-") && (head.startsWith("Missing argument") || head.startsWith("Unknown argument")) => s"Unknown argument: $opt"
      // a word that is no option: the options after it are not unknown, the word is
      case Some(w) if head.startsWith("Unknown argument") => s"Unexpected word '$w': the options here are --name value pairs and flags"
      case _ => head
    }
    first.replaceFirst("""^moire\.[\w.$]+Error: """, "") match {
      case badValue(opt, tpe, v) => s"$opt: '$v' is not a valid $tpe"
      case other if other.startsWith("Unknown argument") || other.startsWith("Missing argument") || other.startsWith("Unexpected word") => s"$other (see --help)"
      case other => other
    }
  }
}
