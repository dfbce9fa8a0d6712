package moire.recording

/** The lines of a text (LF, CRLF or CR ends), none longer than `maxChars`: a file that is one endless "line" (a
  * gigabyte of zeros, a binary file) is refused after `maxChars` characters, not after reading it whole.
  */
final class BoundedLines(in: java.io.Reader, maxChars: Int, tooLong: Long => Nothing) {
  private val buf = new Array[Char](1 << 16)
  private var len = 0; private var pos = 0
  private var lineNo = 0L
  private var skipLf = false
  private var ended = true
  private val sb = new java.lang.StringBuilder(256)

  private def fill(): Boolean = { len = in.read(buf); pos = 0; len > 0 }

  /** Whether the last line returned had a line end (false: the text stopped inside it). */
  def lastEnded: Boolean = ended

  /** The next line without its end, or null at the end of the text. */
  def readLine(): String = {
    sb.setLength(0)
    var any = false
    while (true) {
      if (pos >= len && !fill()) return if (any) { lineNo += 1; ended = false; sb.toString } else null
      if (skipLf) { skipLf = false; if (buf(pos) == '\n') pos += 1 }
      if (pos < len) {
        var i = pos
        while (i < len && buf(i) != '\n' && buf(i) != '\r') i += 1
        sb.append(buf, pos, i - pos)
        any = true
        if (sb.length > maxChars) tooLong(lineNo + 1)
        if (i < len) {
          skipLf = buf(i) == '\r'
          pos = i + 1
          lineNo += 1
          ended = true
          return sb.toString
        }
        pos = len
      }
    }
    null
  }
}
