package moire.stream

/** A bad input to the stream library: one line, said by the command line. */
final class StreamError(msg: String) extends moire.MoireError(msg)
