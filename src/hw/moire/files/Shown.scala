package moire.files

/** Text from a user's file, made safe to print in a one-line message: control characters and bytes that are
  * not text appear as `\x00`, `\xff`; long text is cut (with "...") so a message stays one line.
  */
object Shown {
  /** The longest piece of a line a message shows. */
  val MaxChars = 200

  /** `s` with control characters as `\xNN` (those of U+0080..U+009F, which some terminals obey too, as `\u0085`; U+FFFD,
    * an undecodable byte, as `\ufffd`; U+FEFF, an invisible byte-order mark, as `\ufeff`), cut at `max` characters.
    */
  def text(s: String, max: Int = MaxChars): String = {
    val b = new StringBuilder
    var i = 0
    while (i < s.length && b.length < max) {
      val c = s.charAt(i)
      if (c == '\t') b.append(c)
      else if (c < 0x20 || c == 0x7f) b.append(f"\\x${c.toInt}%02x")
      else if (c == '\ufffd' || c == '\ufeff' || (c >= 0x80 && c < 0xa0)) b.append(f"\\u${c.toInt}%04x")
      else b.append(c)
      i += 1
    }
    if (i < s.length) b.append("...")
    b.toString
  }

  /** Bytes as text: printable ASCII as it is, every other byte as `\xNN`. */
  def bytes(b: Array[Byte]): String =
    b.map(x => if (x >= 0x20 && x < 0x7f) x.toChar.toString else f"\\x${x & 0xff}%02x").mkString

  /** The first `n` bytes of a file as text (empty when it cannot be read). */
  def head(path: os.Path, n: Int = 32): String =
    try {
      val in = java.nio.file.Files.newInputStream(path.toNIO)
      try bytes(in.readNBytes(n)) finally in.close()
    } catch { case _: java.io.IOException => "" }

  /** What a file that is not text seems to be, from its first bytes: gzip, UTF-16 or binary; None for text. */
  def binaryKind(path: os.Path): Option[String] = {
    val b = try {
      val in = java.nio.file.Files.newInputStream(path.toNIO)
      try in.readNBytes(512) finally in.close()
    } catch { case _: java.io.IOException => Array.emptyByteArray }
    def starts(p: Int*) = b.length >= p.length && p.indices.forall(i => (b(i) & 0xff) == p(i))
    if (starts(0x1f, 0x8b)) Some("gzip-compressed data (unpack it first)")
    else if (starts(0xff, 0xfe) || starts(0xfe, 0xff)) Some("UTF-16 text (save it as UTF-8)")
    else if (starts(0x50, 0x4b, 0x03, 0x04)) Some("a zip archive (unpack it first)")
    else if (b.contains(0.toByte)) Some("binary data (it holds NUL bytes), not text")
    else None
  }
}
