package moire.replay

/** A bad input to the replay library: one line, said by the command line. */
final class ReplayError(msg: String) extends moire.MoireError(msg)
