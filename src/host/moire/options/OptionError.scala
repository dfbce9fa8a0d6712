package moire.options

/** A bad input to the options library: one line, said by the command line. */
final class OptionError(msg: String) extends moire.MoireError(msg)
