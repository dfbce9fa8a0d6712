package moire.recording

/** A bad input to the recording library: one line, said by the command line. */
final class RecordingError(msg: String) extends moire.MoireError(msg)
