package moire.choice

/** The one way a named choice is read (a mode, a rounding, an ADC format, a board, a design, ...): the entry whose
  * name is the text given, or the caller's words for a wrong one followed by the names allowed.
  */
object Choice {
  /** The entry of `all` named `s`; else `Left("<wrong>; allowed: a, b, c")`. */
  def apply[A](all: Seq[A], s: String, wrong: => String)(name: A => String): Either[String, A] =
    all.find(a => name(a) == s).toRight(s"$wrong; allowed: ${all.map(name).mkString(", ")}")
}
