package moire.timing

/** A timing run that cannot go on (tools missing, a tool failed), said in one line. */
class TimingError(msg: String) extends moire.MoireError(msg)
