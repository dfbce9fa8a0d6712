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
    val tmps = targets.map(tmpOf)
    tmps.foreach(Temporaries.add)
    var at = targets.head; var renamed = 0
    try {
      for (((t, write), tmp) <- writes.zip(tmps)) { at = t; write(tmp) }
      for ((t, tmp) <- targets.zip(tmps)) otherKind(t, tmp).foreach(m => throw new FileError(m))
      for (t <- targets) { at = t; beforeRename(t) }
      Temporaries.commit {
        for ((t, tmp) <- targets.zip(tmps)) {
          at = t
          Files.move(tmp.toNIO, t.toNIO, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
          renamed += 1
        }
      }
    } catch {
      case e: IOException =>
        val kept = if (renamed == 0) "nothing was changed" else s"${targets.take(renamed).mkString(", ")} already replaced, the rest kept"
        throw new FileError(s"$at: cannot write (${reason(e)}); $kept")
    } finally tmps.foreach { tmp => try Files.deleteIfExists(tmp.toNIO) catch { case _: IOException => () }; Temporaries.done(tmp) }
  }

  /** Writes a project folder as one: `write` fills a fresh folder (given to it) and returns its files; then each
    * of that folder's entries replaces its namesake in `dir` (a sub-folder such as rtl/ as a whole, by renames).
    * A failed or interrupted `write` leaves `dir` as it was; files of `dir` the new project does not name are
    * kept. Returns the files as they are in `dir`.
    */
  def project(dir: os.Path)(write: os.Path => Seq[os.Path]): Seq[os.Path] = {
    checkFolder(dir)
    val tag = s"${ProcessHandle.current().pid()}-${Thread.currentThread().getId}"
    val stage = dir / s".moire-new-$tag"
    Temporaries.add(stage)
    try {
      os.remove.all(stage)
      val files = write(stage)
      val entries = os.list(stage)
      entries.foreach(e => checkReplaceable(dir / e.last))
      // what the new project replaces (its files' namesakes, and all that its folders' namesakes hold) must be moire's
      // own as it wrote it: a user's file in rtl/ went with the folder, an edited .qsf was written over
      val written = manifest(dir)
      val foreign = entries.flatMap { e =>
        val old = dir / e.last
        if (!os.exists(old, followLinks = false)) Nil
        else if (os.isDir(old, followLinks = false)) os.walk(old, includeTarget = false).filter(p => !os.isDir(p, followLinks = false) || os.list(p).isEmpty)
        else Seq(old)
      }.filterNot(p => os.isFile(p, followLinks = false) && (p.last == Manifest || moires(p, p.relativeTo(dir).toString, written)))
      if (foreign.nonEmpty) {
        val names = foreign.take(5).map(_.relativeTo(dir).toString).mkString(", ") + (if (foreign.size > 5) s", ... (${foreign.size} in all)" else "")
        throw new FileError(s"$dir: $names ${if (foreign.size == 1) "is" else "are"} not as moire wrote ${if (foreign.size == 1) "it" else "them"} " +
          "(your own, or edited since); moire does not replace or remove them: move them, or give another output folder")
      }
      Temporaries.commit {
        // folders first, each swapped with its old self (moved aside, then removed), then the files one by one
        val (folders, plain) = entries.partition(os.isDir)
        val aside = folders.map(f => dir / s".${f.last}.old-$tag")
        aside.foreach(Temporaries.add)
        var replaced = 0
        try {
          for ((f, old) <- folders.zip(aside)) {
            if (os.exists(dir / f.last)) Files.move((dir / f.last).toNIO, old.toNIO, StandardCopyOption.ATOMIC_MOVE)
            Files.move(f.toNIO, (dir / f.last).toNIO, StandardCopyOption.ATOMIC_MOVE)
          }
          for (f <- plain) { Files.move(f.toNIO, (dir / f.last).toNIO, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE); replaced += 1 }
        } catch {
          case e: IOException =>
            // the old folders back in place; a file already replaced cannot be (say which)
            if (replaced == 0) for ((f, old) <- folders.zip(aside) if os.exists(old)) {
              if (os.exists(dir / f.last)) os.remove.all(dir / f.last)
              Files.move(old.toNIO, (dir / f.last).toNIO, StandardCopyOption.ATOMIC_MOVE)
            }
            val kept = if (replaced == 0) "nothing was changed" else s"${plain.take(replaced).map(_.last).mkString(", ")} and the folders already replaced"
            throw new FileError(s"$dir: cannot write the project (${reason(e)}); $kept")
        } finally aside.foreach { old => try os.remove.all(old) catch { case _: IOException => () }; Temporaries.done(old) }
      }
      val out = files.map(f => dir / f.relativeTo(stage))
      text(dir / Manifest, out.filter(os.isFile(_)).map(f => s"${sha256(f)}  ${f.relativeTo(dir)}\n").mkString)
      out
    } catch {
      case e: IOException => throw new FileError(s"$dir: cannot write the project (${reason(e)}); nothing was changed")
    } finally { try os.remove.all(stage) catch { case _: IOException => () }; Temporaries.done(stage) }
  }

  /** Checks, before the work, that `target` may take a file moire makes again at will (Verilog, a table, a JSON result,
    * a plot): it is new, empty, or as moire wrote it: its hash in its folder's list `Manifest`, or, where the list does
    * not name it, first lines that name moire or firtool. A user's file of the same name, or one edited since, is refused.
    */
  def checkMade(target: os.Path): Unit = checkMade(target, earlier)

  /** `checkMade`, where a file its folder's list does not name is taken as moire's only when `unlisted` says so. */
  def checkMade(target: os.Path, unlisted: os.Path => Boolean): Unit = {
    checkFile(target)
    if (os.isFile(target, followLinks = false) && os.size(target) > 0 && !asWritten(target, unlisted))
      throw new FileError(s"$target: is not as moire wrote it (your own, or edited since); moire does not replace it: move it, or give another output name")
  }

  /** Writes files moire makes again at will as one (`all`), each checked by `checkMade` first; their hashes go into their
    * folders' lists, so that the next run knows them as its own.
    */
  def made(writes: Seq[(os.Path, os.Path => Unit)], unlisted: os.Path => Boolean = earlier, plain: Seq[(os.Path, os.Path => Unit)] = Nil): Unit = {
    writes.foreach(w => checkMade(w._1, unlisted))
    // `plain`: files written with them as one (a report the user named), each as `all` writes it and not listed
    all(writes ++ plain)
    listed(writes.map(_._1))
  }
  def madeText(target: os.Path, s: String): Unit = made(Seq(target -> (t => os.write(t, s))))

  /** Files of `dir` whose names are `named` that an earlier run wrote (in the folder's list, as written) and that are
    * not in `kept`: removed, and the list updated; returns them. A file edited since, or not in the list, stays.
    */
  def removeStale(dir: os.Path, named: String => Boolean, kept: Seq[os.Path]): Seq[os.Path] = synchronized {
    val list = manifest(dir)
    val stale = list.keys.toSeq.filter(n => !n.contains('/') && named(n) && !kept.contains(dir / n))
      .map(dir / _).filter(f => os.isFile(f, followLinks = false) && asWritten(f))
    stale.foreach(f => try os.remove(f) catch { case _: IOException => () })
    val gone = stale.filterNot(os.exists(_, followLinks = false))
    if (gone.nonEmpty) text(dir / Manifest, lines(list -- gone.map(_.last)))
    gone
  }

  private def asWritten(t: os.Path, unlisted: os.Path => Boolean = earlier): Boolean =
    manifest(t / os.up).get(t.last) match {
      case Some(h) => h == sha256(t)
      case None => unlisted(t)
    }

  /** A file its folder's list does not name, taken as moire's all the same: in a folder no list names (written before
    * the lists), a plot (its earlier plots would otherwise stop every explain there after its fit); text by first lines
    * that name moire or firtool (or an earlier timing table's).
    */
  def earlier(t: os.Path): Boolean = (manifest(t / os.up).isEmpty && kind(t) == "a PNG image") ||
    headerOf(t).exists(l => l.contains("moire") || l.startsWith("// Generated by CIRCT") || l.startsWith("Measured with `./sbt \"run timing"))
  /** Adds the files' hashes to their folders' lists (one writer at a time: a batch writes plots side by side). */
  private def listed(ts: Seq[os.Path]): Unit = synchronized {
    for ((dir, fs) <- ts.groupBy(_ / os.up)) text(dir / Manifest, lines(manifest(dir) ++ fs.map(f => f.last -> sha256(f))))
  }
  private def lines(list: Map[String, String]): String = list.toSeq.sortBy(_._1).map { case (n, h) => s"$h  $n\n" }.mkString

  /** A folder's list of the files moire's last writes put there, each with its SHA-256 (as `sha256sum` prints it). */
  val Manifest = ".moire-files"

  /** The list `Manifest` of `dir` (empty: none, or not readable). */
  private def manifest(dir: os.Path): Map[String, String] =
    try os.read.lines(dir / Manifest).flatMap { l => val i = l.indexOf("  "); if (i == 64) Some(l.drop(66) -> l.take(64)) else None }.toMap
    catch { case _: IOException | _: IllegalArgumentException => Map.empty }

  /** A file moire wrote, as it wrote it: its hash in the folder's list; without a list (a project written before it),
    * one whose first lines say moire or firtool made it.
    */
  private def moires(p: os.Path, rel: String, written: Map[String, String]): Boolean =
    if (written.nonEmpty) written.get(rel).contains(sha256(p))
    else headerOf(p).exists(l => l.contains("moire") || l.startsWith("// Generated by CIRCT"))

  private def headerOf(p: os.Path): Seq[String] =
    try { val in = Files.newInputStream(p.toNIO); try new String(in.readNBytes(512), java.nio.charset.StandardCharsets.UTF_8).linesIterator.take(3).toSeq finally in.close() }
    catch { case _: IOException => Nil }

  def sha256(p: os.Path): String = {
    val md = java.security.MessageDigest.getInstance("SHA-256")
    val in = Files.newInputStream(p.toNIO)
    try { val buf = new Array[Byte](1 << 16); var k = in.read(buf); while (k > 0) { md.update(buf, 0, k); k = in.read(buf) } } finally in.close()
    md.digest().map(b => f"${b & 0xff}%02x").mkString
  }

  /** What a file holds, from its first bytes: a PNG image, an HTML page, JSON, a moire recording, another moire format
    * (a replay's, a calibration's), text or other data.
    */
  def kind(p: os.Path): String = {
    val head = try { val in = Files.newInputStream(p.toNIO); try in.readNBytes(4096) finally in.close() } catch { case _: IOException => Array.emptyByteArray }
    if (head.length >= 4 && (head(0) & 0xff) == 0x89 && head(1) == 'P' && head(2) == 'N' && head(3) == 'G') return "a PNG image"
    if (head.take(256).contains(0.toByte)) return "binary data"
    val t = new String(head, java.nio.charset.StandardCharsets.UTF_8).stripPrefix("\uFEFF").dropWhile(_.isWhitespace).toLowerCase
    // explain's reports name themselves near their start (its HTML's title, its JSON's criterion): a page or JSON of a
    // user's of the same name is another kind, not one to write over
    if (t.startsWith("<!doctype html") || t.startsWith("<html")) { if (t.contains("<title>explain: ")) "an explain report (HTML)" else "an HTML page" }
    else if (t.startsWith("{") || t.startsWith("[")) { if (t.contains("\"criterion\": \"bic = ")) "an explain report (JSON)" else "JSON" }
    else if (t.startsWith("# moire-recording")) "a moire recording"
    // moire's other files name their own format on their first line (`# moire-replay v1`, `# moire-calibration v1`)
    else if (t.startsWith("# moire-")) s"a ${t.drop(2).takeWhile(c => c.isLetterOrDigit || c == '-')} file"
    // calibrate's register listing before it named its format on its first line
    else if (t.startsWith("# moire harmonic registers")) "a moire-harmonic-registers file"
    else "text"
  }

  /** Why the new content `tmp` must not replace the existing file `t`: it holds another kind of content (an HTML
    * report over a model's JSON, a recording over notes). None for a new or empty file, or one of the same kind.
    */
  private def otherKind(t: os.Path, tmp: os.Path): Option[String] =
    if (!os.isFile(t, followLinks = false) || os.size(t) == 0) None else kindClash(t, kind(tmp))

  private def kindClash(t: os.Path, now: String): Option[String] = {
    val old = kind(t)
    if (old == now) None
    else Some(s"$t: holds $old, and this command writes $now; moire does not write over another kind of file (choose another name, or remove it first)")
  }

  /** Checks before a long piece of work (a recording) that `target` holds nothing of another kind than `writes` (as
    * `kind` names it): the write at the end would refuse it, and the work would be lost.
    */
  def checkKind(target: os.Path, writes: String): Unit =
    if (os.isFile(target, followLinks = false) && os.size(target) > 0) kindClash(target, writes).foreach(m => throw new FileError(m))

  /** An existing output that is no plain file or folder is refused: a link, a pipe or a device is never replaced. */
  private def checkReplaceable(target: os.Path): Unit = PathKind.of(target) match {
    case Some(k) if k != "a file" && k != "a folder" =>
      throw new FileError(s"$target: is $k; moire does not write over it (give a plain file's name)")
    case _ => ()
  }

  def text(target: os.Path, s: String): Unit = apply(target)(t => os.write(t, s))

  /** Checks, before any work, that `dir` is (or can become) a writable folder. */
  def checkFolder(dir: os.Path): Unit = {
    if (os.exists(dir) && !os.isDir(dir)) throw new FileError(s"$dir: is ${PathKind.of(dir).getOrElse("a file")}, not a folder")
    // the folders this makes, the deepest first (`removeEmptyMade`)
    val missing = Iterator.iterate(dir)(_ / os.up).takeWhile(p => p.segmentCount > 0 && !os.exists(p, followLinks = false)).toList
    try os.makeDir.all(dir) catch { case e: IOException => throw new FileError(s"$dir: cannot make the folder (${reason(e)})") }
    missing.reverse.foreach(made.push)
    if (!Files.isWritable(dir.toNIO)) throw new FileError(s"$dir: the folder is not writable")
    probe(dir)
  }
  /** The temporary file `all` writes `t` through. */
  private def tmpOf(t: os.Path): os.Path = t / os.up / s".${t.last}.tmp-${ProcessHandle.current().pid()}-${Thread.currentThread().getId}"

  /** Makes a file of one byte in `dir` and removes it: the permission bits do not tell (root may write anywhere by
    * them, yet /proc or a read-only mount takes no file, and a full disk no byte), and a command found that out only at
    * its end, after its work (a recording's, which cannot be made again).
    */
  private def probe(dir: os.Path): Unit =
    probeAt(dir / s".moire-probe-${ProcessHandle.current().pid()}-${Thread.currentThread().getId}", e => s"$dir: the folder takes no new file (${reason(e)})")
  /** Makes `p` with one byte and removes it; `why` words a failure. */
  private def probeAt(p: os.Path, why: IOException => String): Unit = {
    Temporaries.add(p)
    try { Files.createFile(p.toNIO); Files.write(p.toNIO, Array[Byte]('\n')); Files.delete(p.toNIO) }
    catch {
      case _: FileAlreadyExistsException => () // a probe of this thread's left by a killed run: the folder took it
      case e: IOException => throw new FileError(why(e))
    } finally { try Files.deleteIfExists(p.toNIO) catch { case _: IOException => () }; Temporaries.done(p) }
  }
  private val made = new java.util.concurrent.ConcurrentLinkedDeque[os.Path]()

  /** Removes the folders `checkFolder` made that are still empty, the deepest first: a command that failed after
    * checking its outputs leaves no empty folder behind (one that holds anything stays).
    */
  def removeEmptyMade(): Unit = {
    var p = made.poll()
    while (p != null) {
      try if (os.isDir(p, followLinks = false) && os.list(p).isEmpty) os.remove(p) catch { case _: IOException => () }
      p = made.poll()
    }
  }
  /** Forgets the folders made so far (a new command starts). */
  def forgetMade(): Unit = made.clear()

  /** Checks, before any work, that `target` can be written: its folder is writable, it is no folder, and it is no
    * recording this output would lose (`guardRecording`).
    */
  def checkFile(target: os.Path): Unit = {
    if (target.last == "-") throw new FileError(Stdout)
    controlChar(target.last).foreach(m => throw new FileError(m))
    if (os.isDir(target, followLinks = false)) throw new FileError(s"$target: is a folder, not a file")
    checkReplaceable(target)
    guardRecording(target)
    checkFolder(target / os.up)
    // the name the write goes through: one too long for the file system failed only at the end
    probeAt(tmpOf(target), e => s"$target: cannot be written (${reason(e)})")
    if (os.exists(target) && !Files.isWritable(target.toNIO)) throw new FileError(s"$target: the file is read-only")
  }

  /** The command running writes recordings (simulate, record): its outputs may replace a simulated recording. */
  val writesRecordings = new scala.util.DynamicVariable[Boolean](false)

  /** A moire recording is replaced only by a recording, and only when `simulate` wrote it (its header holds the
    * `model` it was made from, so it can be made again): a measured one is never written over, whatever the command.
    */
  private def guardRecording(target: os.Path): Unit = if (os.isFile(target)) {
    val head = headerLines(target)
    if (head.headOption.exists(_.startsWith("# moire-recording"))) {
      if (!head.exists(_.startsWith("# model:")))
        throw new FileError(s"$target: is a measured recording (simulate did not write it, so it cannot be made again); moire does not write over it: move it, or give another output name")
      if (!writesRecordings.value)
        throw new FileError(s"$target: is a recording, and this command's output is not one; give another output name")
    }
  }
  /** The file's first lines while they start with '#' (at most 64 KB read; a byte-order mark dropped, as the reader
    * drops it); none when it cannot be read (the write then says why).
    */
  private def headerLines(p: os.Path): Seq[String] =
    try {
      val in = Files.newInputStream(p.toNIO)
      val text = try new String(in.readNBytes(1 << 16), java.nio.charset.StandardCharsets.UTF_8) finally in.close()
      text.stripPrefix("\uFEFF").linesIterator.takeWhile(_.startsWith("#")).toSeq
    } catch { case _: IOException => Nil }

  /** An output whose name the command picks (the user did not name it) replaces only a file of its own kind: one whose
    * first line starts with `magic`; else one line that says how to name another output (`option`).
    */
  def checkPicked(target: os.Path, magic: String, option: String): Unit = {
    checkFile(target)
    if (os.isFile(target) && !firstLine(target).startsWith(magic))
      throw new FileError(s"$target: exists and is not a file this command writes (its first line is not '$magic'); move it, or give $option")
  }
  private def firstLine(p: os.Path): String = {
    val in = Files.newInputStream(p.toNIO)
    try new String(in.readNBytes(256), java.nio.charset.StandardCharsets.ISO_8859_1).takeWhile(c => c != '\n' && c != '\r')
    finally in.close()
  }

  /** An output named `-`: other tools' name for standard output, which no command here writes to (a file named `-`
    * would be written in the working folder instead).
    */
  val Stdout = "-: moire writes no output to standard output; give a file name (e.g. out.csv)"

  /** An output file's name as the user gave it: a name ending in a slash names a folder (a file of the folder's name
    * would be written), an empty one no file at all.
    */
  def fileArg(given: String): os.Path = {
    if (given.trim.isEmpty) throw new FileError("an output file's name is empty; give a file name")
    controlChar(given).foreach(m => throw new FileError(m))
    if (given.trim == "-") throw new FileError(Stdout)
    if (given.endsWith("/")) throw new FileError(s"$given: ends with /, so it names a folder; give a file name (e.g. ${given}out.csv)")
    os.Path(given, os.pwd)
  }

  /** An output folder's name as the user gave it (`option` names it): an empty one is refused (it would be the
    * working folder, which the user did not name).
    */
  def folderArg(given: String, option: String): os.Path = {
    if (given.trim.isEmpty) throw new FileError(s"$option: the folder's name is empty; give a folder (. for the working folder)")
    controlChar(given).foreach(m => throw new FileError(s"$option: $m"))
    if (given.trim == "-") throw new FileError(s"$option: - names no folder (moire writes nothing to standard output); give a folder")
    os.Path(given, os.pwd)
  }

  /** A name with a line break, tab or other control character: legal on the file system, but no listing or message
    * shows it as one name (a `wrote` line would split over two).
    */
  def controlChar(given: String): Option[String] = given.find(_.isControl).map(c =>
    f"an output name holds a control character (U+${c.toInt}%04X, e.g. a line break) in '${given.map(x => if (x.isControl) '?' else x)}'; give a plain name")

  /** An input whose name names outputs (`<stem>.json`): one with a control character is refused before the work, as
    * `controlChar` refuses an output's name (the outputs would have it too).
    */
  def checkNameOf(input: os.Path): Unit = input.last.find(_.isControl).foreach(c => throw new FileError(
    f"${Shown.text(input.toString)}: its name holds a control character (U+${c.toInt}%04X, e.g. a line break), and the outputs named after it would too; rename it"))

  /** Refuses an output that is one of the inputs (also through links or another spelling of the path). */
  def refuseInputs(output: os.Path, inputs: Seq[os.Path]): Unit =
    inputs.find(same(_, output))
      .foreach(i => throw new FileError(s"$output: is an input of this command${if (i != output) s" ($i)" else ""}; choose another output name"))

  /** The two paths name one file (also through links or another spelling of the path). */
  def same(a: os.Path, b: os.Path): Boolean = a == b || (os.exists(a) && os.exists(b) && Files.isSameFile(a.toNIO, b.toNIO))

  /** [[refuseInputs]] for path strings as the user gave them (relative to the working folder). */
  def refuseInputs(output: String, inputs: Seq[String]): Unit = refuseInputs(os.Path(output, os.pwd), inputs.map(os.Path(_, os.pwd)))

  /** Plain words for an I/O failure (no Java class names). */
  def reason(e: IOException): String = e match {
    case _: AccessDeniedException => "permission denied"
    case _: NoSuchFileException => "no such file or folder"
    case _: FileAlreadyExistsException | _: NotDirectoryException => "a file is in the way of the folder"
    case f: FileSystemException => Option(f.getReason).getOrElse("file system error")
    case o => Option(o.getMessage).filter(_.nonEmpty).getOrElse("input/output error")
  }
}
