package moire.files

import java.nio.file.Files
import java.nio.file.attribute.BasicFileAttributes

/** One file however it is named: through a symbolic link, a hard link or another spelling of its path. */
object SameFile {
  /** What names the file itself: its file key (device and inode) where the file system has one, else its real path;
    * the path as given when it cannot be read (a missing file is said so where it is read).
    */
  def key(p: os.Path): AnyRef =
    try Option(Files.readAttributes(p.toNIO, classOf[BasicFileAttributes]).fileKey).getOrElse(p.toNIO.toRealPath())
    catch { case _: java.io.IOException => p }

  /** The first of `paths` that names a file an earlier one names, with that earlier one. */
  def repeated(paths: Seq[os.Path]): Option[(os.Path, os.Path)] = {
    val keys = paths.map(key)
    paths.indices.collectFirst { case i if keys.indexOf(keys(i)) < i => (paths(keys.indexOf(keys(i))), paths(i)) }
  }
}
