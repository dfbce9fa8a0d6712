package moire

/** A mistake in what a user gave (a file, an option, a value). Libraries throw a subclass of their own;
  * only the command line turns it into one line and an exit code.
  */
class MoireError(msg: String) extends Exception(msg)
