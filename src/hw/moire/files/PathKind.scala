package moire.files

import java.nio.file.{Files, LinkOption}

/** What a path is, in words: a file, a folder, a link, a named pipe, a device or a socket (a link is not followed). */
object PathKind {
  /** "a folder", "a symbolic link", "a named pipe (FIFO)", "a character device", ...; None when nothing is there. */
  def of(p: os.Path): Option[String] = {
    val n = p.toNIO
    if (Files.isSymbolicLink(n)) Some("a symbolic link")
    else if (!Files.exists(n, LinkOption.NOFOLLOW_LINKS)) None
    else if (Files.isDirectory(n, LinkOption.NOFOLLOW_LINKS)) Some("a folder")
    else if (Files.isRegularFile(n, LinkOption.NOFOLLOW_LINKS)) Some("a file")
    else Some(special(n))
  }

  /** A special file: the file type bits of its mode (Linux, macOS), or "a special file" where they cannot be read. */
  private def special(n: java.nio.file.Path): String =
    try Files.getAttribute(n, "unix:mode", LinkOption.NOFOLLOW_LINKS).asInstanceOf[Int] & 0xf000 match {
      case 0x1000 => "a named pipe (FIFO)"
      case 0x2000 => "a character device"
      case 0x6000 => "a block device"
      case 0xc000 => "a socket"
      case _ => "a special file"
    } catch { case _: UnsupportedOperationException | _: IllegalArgumentException | _: java.io.IOException => "a special file" }

  /** Why `p` cannot be read as a data file (None when it can be: a regular file, also through a link). */
  def notAFile(p: os.Path): Option[String] =
    if (Files.isRegularFile(p.toNIO)) None
    else if (Files.isSymbolicLink(p.toNIO) && !Files.exists(p.toNIO)) Some(s"$p: a symbolic link to nothing (no such file)")
    else of(if (Files.exists(p.toNIO)) os.Path(p.toNIO.toRealPath()) else p) match {
      case None => Some(s"$p: no such file")
      case Some(k) => Some(s"$p: is ${k}, not a file")
    }
}
