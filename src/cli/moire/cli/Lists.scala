package moire.cli

/** Comma-separated lists of the command line: a value given twice is a slip (a sweep or a run would do it twice). */
object Lists {
  def once[A](opt: String, vs: Seq[A]): Seq[A] = {
    vs.diff(vs.distinct).headOption.foreach(v => throw new UsageError(s"--$opt: $v is given twice"))
    vs
  }
}
