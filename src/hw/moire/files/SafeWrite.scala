package moire.files

import java.io.IOException
import java.nio.file.{AccessDeniedException, FileAlreadyExistsException, FileSystemException, Files, NoSuchFileException,
  NotDirectoryException, StandardCopyOption}

/** An output that cannot be written, or one that would replace an input. */
class FileError(msg: String) extends moire.MoireError(msg)

/** The one way moire writes a file: into a temporary file beside the target, renamed over it only when
  * complete. A failed or interrupted write leaves the old file as it was and no partial file behind.
  */
object SafeWrite {
  /** Called with the target after the content is written and before the rename; tests inject write errors here. */
  @volatile var beforeRename: os.Path => Unit = _ => ()

  /** Writes `target` through `write`, which fills the temporary path it is given. */
  def apply(target: os.Path)(write: os.Path => Unit): Unit = all(Seq(target -> write))

  /** Writes several files as one: every temporary file is complete before the first rename, so a failed
    * write changes none of them.
    */
  def all(writes: Seq[(os.Path, os.Path => Unit)]): Unit = {
    if (writes.isEmpty) return
    val targets = writes.map(_._1)
    targets.groupBy(identity).collectFirst { case (t, ts) if ts.size > 1 => throw new FileError(s"$t: named twice as an output of one command") }
    targets.foreach(checkFile)
    val tmps = targets.map(t => t / os.up / s".${t.last}.tmp-${ProcessHandle.current().pid()}-${Thread.currentThread().getId}")
    var at = targets.head; var renamed = 0
    try {
      for (((t, write), tmp) <- writes.zip(tmps)) { at = t; write(tmp) }
      for (t <- targets) { at = t; beforeRename(t) }
      for ((t, tmp) <- targets.zip(tmps)) {
        at = t
        Files.move(tmp.toNIO, t.toNIO, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
        renamed += 1
      }
    } catch {
      case e: IOException =>
        val kept = if (renamed == 0) "nothing was changed" else s"${targets.take(renamed).mkString(", ")} already replaced, the rest kept"
        throw new FileError(s"$at: cannot write (${reason(e)}); $kept")
    } finally tmps.foreach(tmp => try Files.deleteIfExists(tmp.toNIO) catch { case _: IOException => () })
  }

  def text(target: os.Path, s: String): Unit = apply(target)(t => os.write(t, s))

  /** Checks, before any work, that `dir` is (or can become) a writable folder. */
  def checkFolder(dir: os.Path): Unit = {
    if (os.exists(dir) && !os.isDir(dir)) throw new FileError(s"$dir: is a file, not a folder")
    try os.makeDir.all(dir) catch { case e: IOException => throw new FileError(s"$dir: cannot make the folder (${reason(e)})") }
    if (!Files.isWritable(dir.toNIO)) throw new FileError(s"$dir: the folder is not writable")
  }

  /** Checks, before any work, that `target` can be written: its folder is writable and it is no folder. */
  def checkFile(target: os.Path): Unit = {
    if (os.isDir(target)) throw new FileError(s"$target: is a folder, not a file")
    checkFolder(target / os.up)
    if (os.exists(target) && !Files.isWritable(target.toNIO)) throw new FileError(s"$target: the file is read-only")
  }

  /** Refuses an output that is one of the inputs (also through links or another spelling of the path). */
  def refuseInputs(output: os.Path, inputs: Seq[os.Path]): Unit =
    inputs.find(i => i == output || (os.exists(i) && os.exists(output) && Files.isSameFile(i.toNIO, output.toNIO)))
      .foreach(i => throw new FileError(s"$output: is an input of this command; choose another output name"))

  /** Plain words for an I/O failure (no Java class names). */
  def reason(e: IOException): String = e match {
    case _: AccessDeniedException => "permission denied"
    case _: NoSuchFileException => "no such file or folder"
    case _: FileAlreadyExistsException | _: NotDirectoryException => "a file is in the way of the folder"
    case f: FileSystemException => Option(f.getReason).getOrElse("file system error")
    case o => Option(o.getMessage).filter(_.nonEmpty).getOrElse("input/output error")
  }
}
