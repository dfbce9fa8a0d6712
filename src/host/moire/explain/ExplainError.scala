package moire.explain

/** A bad input to the explain library: one line, said by the command line. */
final class ExplainError(msg: String) extends moire.MoireError(msg)
