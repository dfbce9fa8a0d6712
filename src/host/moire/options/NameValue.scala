package moire.options

/** `--name=value` as the two words `--name value`, for the commands that read their own words (explain, replay): the
  * others' parser takes it already. Only for an option `takesValue` names (a flag's `=` is left for its refusal).
  */
object NameValue {
  def split(args: Seq[String], takesValue: String => Boolean): Seq[String] = args.flatMap(a => a.indexOf('=') match {
    case k if k > 2 && a.startsWith("--") && takesValue(a.take(k)) => Seq(a.take(k), a.drop(k + 1))
    case _ => Seq(a)
  })
}
