package moire.stream

import moire.files.FileError
import moire.recording.Recording

/** Writes a recording that cannot be made again. When its file cannot be written after all (the disk filled during
  * the recording; the folder was checked before it), the records go to a new file in the system's temporary folder,
  * else the home folder, and the caller's error names it: they are never dropped for want of the place asked for.
  */
object KeepRecording {
  /** The file written, and why it is not the one asked for (one line), if it is not. */
  final case class Saved(file: os.Path, failure: Option[String])

  def apply(file: os.Path, rec: Recording, stem: String): Saved =
    try { Recording.write(file, rec); Saved(file, None) } catch {
      case e: FileError =>
        val why = e.getMessage.stripSuffix("; nothing was changed")
        val tried = Seq("java.io.tmpdir", "user.home").flatMap(sys.props.get).distinct.map(d => fresh(os.Path(d, os.pwd), stem))
        val fails = Seq.newBuilder[String]
        tried.iterator.map { f =>
          try { Recording.write(f, rec); Some(Saved(f, Some(why))) }
          catch { case x: FileError => fails += x.getMessage.stripSuffix("; nothing was changed"); None }
        }.collectFirst { case Some(s) => s }
          .getOrElse(throw new StreamError(s"$why; nor elsewhere (${fails.result().mkString("; ")}): the ${rec.length} records are lost"))
    }

  /** A name no file has yet: `stem-YYYYMMDD-HHMMSS.csv` in `dir`, with -2, -3, ... when taken. */
  def fresh(dir: os.Path, stem: String): os.Path = {
    val t = java.time.LocalDateTime.now().format(java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss"))
    Iterator.from(1).map(k => dir / s"$stem-$t${if (k == 1) "" else s"-$k"}.csv").find(p => !os.exists(p, followLinks = false)).get
  }
}
