package moire.files

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import moire.cli.CliInProcess.{classNames, runCli}

/** A write that fails (a full disk, injected through SafeWrite's `beforeRename` hook) leaves every old file
  * byte for byte and no partial or temporary file; the user gets one line and exit code 2. And a read-only
  * folder is refused before any work.
  */
class WriteErrorSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-write-")
  private val diskFull = "No space left on device"

  /** Runs `body` with writes under `dir` whose target passes `fails` failing as on a full disk. */
  private def failing[T](fails: os.Path => Boolean)(body: => T): T = {
    val old = SafeWrite.beforeRename
    SafeWrite.beforeRename = t => { if (t.startsWith(dir) && fails(t)) throw new java.io.IOException(diskFull); old(t) }
    try body finally SafeWrite.beforeRename = old
  }

  /** Every file under `d` with its bytes. */
  private def snapshot(d: os.Path): Map[os.Path, Seq[Byte]] = os.walk(d).filter(os.isFile).map(f => f -> os.read.bytes(f).toSeq).toMap

  /** The command fails on its first write with one line naming a file, exit 2, no file changed, none left over. */
  private def keepsEverything(folder: os.Path, fails: os.Path => Boolean)(args: String*): Unit = {
    val before = snapshot(folder)
    before should not be empty
    val (code, err) = failing(fails)(runCli(args: _*))
    withClue(s"stderr: $err") {
      code shouldBe 2
      err.linesIterator.filter(_.nonEmpty).toSeq should have size 1
      err should include(diskFull)
      err should include("nothing was changed")
      classNames.findFirstIn(err) shouldBe None
    }
    val after = snapshot(folder)
    after.keySet.filter(_.last.contains(".tmp-")) shouldBe empty
    after.keySet shouldBe before.keySet
    for ((f, b) <- before) withClue(s"$f changed: ") { after(f) shouldBe b }
  }

  "SafeWrite" should "keep the old file and leave no temporary file when the write fails" in {
    val f = dir / "unit" / "x.txt"
    SafeWrite.text(f, "old\n")
    val e = intercept[FileError](failing(_ == f)(SafeWrite.text(f, "new\n")))
    e.getMessage should (include(f.toString) and include(diskFull))
    os.read(f) shouldBe "old\n"
    os.list(f / os.up).map(_.last) shouldBe Seq("x.txt")
    SafeWrite.text(f, "new\n")
    os.read(f) shouldBe "new\n"
  }

  it should "write several files as one: a failure on the last keeps the first too" in {
    val (a, b) = (dir / "two" / "a.txt", dir / "two" / "b.txt")
    SafeWrite.text(a, "old a\n"); SafeWrite.text(b, "old b\n")
    val e = intercept[FileError](failing(_ == b)(SafeWrite.all(Seq(a -> (t => os.write(t, "new a\n")), b -> (t => os.write(t, "new b\n"))))))
    e.getMessage should (include(b.toString) and include("nothing was changed"))
    (os.read(a), os.read(b)) shouldBe (("old a\n", "old b\n"))
    os.list(a / os.up).map(_.last) shouldBe Seq("a.txt", "b.txt")
    intercept[FileError](SafeWrite.all(Seq(a -> (t => os.write(t, "x")), a -> (t => os.write(t, "y"))))).getMessage should include("named twice")
  }

  "simulate" should "keep the old recording when the disk is full" in {
    val out = dir / "sim"; val f = out / "rec.csv"
    runCli("simulate", "--out", f.toString, "--samples", "2000")._1 shouldBe 0
    keepsEverything(out, _ == f)("simulate", "--out", f.toString, "--samples", "3000", "--seed", "2")
  }

  private lazy val recording = {
    val f = dir / "in" / "rec.csv"
    runCli("simulate", "--out", f.toString, "--samples", "4000")._1 shouldBe 0
    f
  }

  "explain" should "keep the old JSON report when the disk is full" in {
    val json = dir / "json"
    runCli("explain", recording.toString, "--quiet", "--no-rtl", "--json-dir", json.toString)._1 shouldBe 0
    keepsEverything(json, _.ext == "json")("explain", recording.toString, "--quiet", "--no-rtl", "--json-dir", json.toString)
  }

  it should "keep the old plots when the disk is full" in {
    val plots = dir / "plots"
    runCli("explain", recording.toString, "--quiet", "--no-rtl", "--plots", plots.toString)._1 shouldBe 0
    keepsEverything(plots, _.ext == "png")("explain", recording.toString, "--quiet", "--no-rtl", "--plots", plots.toString)
  }

  it should "replace a record's plots and report all or none when one plot's write fails" in {
    val out = dir / "report"
    runCli("explain", recording.toString, "--quiet", "--no-rtl", "--plots", out.toString, "--json-dir", out.toString)._1 shouldBe 0
    // another recording of the same name: every plot and the JSON would change; the spectrum's write fails
    val other = dir / "in2" / "rec.csv"
    runCli("simulate", "--out", other.toString, "--samples", "5000", "--seed", "3", "--effect", "harmonic:order=3,amplitude_rel=0.02")._1 shouldBe 0
    val spectrum = (t: os.Path) => t.last == "rec_residual_spectrum.png"
    keepsEverything(out, spectrum)("explain", other.toString, "--quiet", "--no-rtl", "--plots", out.toString, "--json-dir", out.toString)
    // into a new folder: no plot, no list, no folder left
    val fresh = dir / "fresh" / "plots"
    val (code, err) = failing(spectrum)(runCli("explain", other.toString, "--quiet", "--no-rtl", "--plots", fresh.toString))
    withClue(err) { code shouldBe 2; err should include("nothing was changed") }
    os.exists(fresh / os.up) shouldBe false
  }

  "calibrate" should "keep the old coefficient file, listing and plot when the disk is full" in {
    val cal = dir / "cal.csv"
    os.write.over(cal, "# moire-calibration v1\nangle_deg,error_arcsec\n" + (0 until 360 by 10).map { a =>
      val t = math.toRadians(a); f"$a,${2 * math.sin(t) + 0.5 * math.cos(3 * t)}%.4f" }.mkString("\n") + "\n")
    val out = dir / "calibration"
    runCli("calibrate", "--input", cal.toString, "--out", out.toString)._1 shouldBe 0
    os.list(out).filterNot(_.last == SafeWrite.Manifest).map(_.ext).toSet shouldBe Set("json", "txt", "png")
    for (ext <- Seq("json", "txt", "png"))
      keepsEverything(out, _.ext == ext)("calibrate", "--input", cal.toString, "--out", out.toString, "--harmonics", "2")
  }

  "board" should "keep the old project whole when the disk fills on the tenth file" in {
    val out = dir / "board"
    runCli("board", "de2-115", "--out", out.toString)._1 shouldBe 0
    os.write(out / "notes.txt", "the user's own file\n")
    var n = 0
    keepsEverything(out, _ => { n += 1; n == 10 })("board", "de2-115", "--out", out.toString, "--design", "corrected")
  }

  "a read-only folder" should "be refused before any work, the old file kept" in {
    val uid = os.proc("id", "-u").call().out.trim()
    assume(uid != "0", "running as root: chmod does not stop root's writes, so a read-only folder cannot be tested here")
    val ro = dir / "ro"; val f = ro / "rec.csv"
    os.makeDir.all(ro); os.write(f, "old\n")
    os.perms.set(ro, "r-xr-xr-x")
    try {
      val (code, err) = runCli("simulate", "--out", f.toString, "--samples", "1000")
      withClue(err) {
        code shouldBe 2
        err should include(s"$ro: the folder is not writable")
        err.linesIterator.filter(_.nonEmpty).toSeq should have size 1
      }
      os.read(f) shouldBe "old\n"
      os.list(ro).map(_.last) shouldBe Seq("rec.csv")
    } finally os.perms.set(ro, "rwxr-xr-x")
  }
}
