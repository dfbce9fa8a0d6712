package moire.cli

import moire.replay.{ReplayCmd, ReplayError}

/** `replay FILE [--design D] [--out F] [--quiet] [--check-rows N] [--check-windows W] [emit-subdiv options]`:
  * the words to [[ReplayCmd.Options]]; every option it does not know goes, with its value, to the subdivider.
  */
object ReplayArgs {
  /** The subdivider's options (emit-subdiv's), as typed: `--input-bits`. */
  private val SubdivOptions: Set[String] =
    moire.options.SubdivConfig().productElementNames.map(n => "--" + n.replaceAll("([A-Z])", "-$1").toLowerCase).toSet

  def parse(args0: Seq[String]): ReplayCmd.Options = {
    // `--name=value` as `--name value`, as the other commands take it (--quiet takes no value)
    val args = moire.options.NameValue.split(args0, _ != "--quiet")
    var o = ReplayCmd.Options(None)
    def count(opt: String, v: String, min: Int) =
      moire.numbers.Decimal.int(v).filter(_ >= min).getOrElse(throw new ReplayError(s"$opt: '$v' is not a whole number from $min to ${Int.MaxValue}"))
    val rest = Seq.newBuilder[String]
    var i = 0
    def value(opt: String) = { i += 1; args.lift(i).getOrElse(throw new ReplayError(s"$opt needs a value")) }
    val seen = scala.collection.mutable.Set.empty[String]
    while (i < args.length) {
      // an option given twice is refused, as the other commands do (the last would have won)
      if (args(i).startsWith("--") && !seen.add(args(i))) throw new ReplayError(s"${args(i)} is given more than once; give it once")
      args(i) match {
        case "--design" => o = o.copy(design = value("--design"))
        case "--out" => o = o.copy(out = Some(value("--out")))
        case "--quiet" => o = o.copy(quiet = true)
        case "--check-rows" => o = o.copy(checkRows = count("--check-rows", value("--check-rows"), 1))
        case "--check-windows" => o = o.copy(checkWindows = count("--check-windows", value("--check-windows"), 0))
        case opt if opt.startsWith("--") && !SubdivOptions(opt) => throw new ReplayError(s"Unknown argument: $opt (see replay --help)")
        case opt if opt.startsWith("--") => rest += opt; rest += value(opt)
        case "" if o.file.isEmpty => throw new ReplayError("replay: the recording's name is empty (''); give a file name")
        case f if o.file.isEmpty => o = o.copy(file = Some(f))
        case f => throw new ReplayError(s"replay: one recording at a time, got '${o.file.get}' and '$f'")
      }
      i += 1
    }
    o.copy(subdiv = rest.result())
  }
}
