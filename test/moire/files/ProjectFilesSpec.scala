package moire.files

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import moire.cli.CliInProcess.{classNames, runCli}

/** A board project written again into its folder replaces only what moire wrote there, as it wrote it: a user's file
  * in rtl/ went with the folder, and an edited .qsf was written over (another tool's fuzz sweep).
  */
class ProjectFilesSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-project-")

  private def refused(out: os.Path, names: String*): Unit = {
    val before = os.walk(out).filter(os.isFile).map(f => f -> os.read(f)).toMap
    val (code, err) = runCli("board", "de2-115", "--out", out.toString, "--design", "corrected")
    withClue(err) {
      code shouldBe 2
      err.linesIterator.count(_.nonEmpty) shouldBe 1
      names.foreach(n => err should include(n))
      err should include("not as moire wrote")
      classNames.findFirstIn(err) shouldBe None
    }
    os.walk(out).filter(os.isFile).map(f => f -> os.read(f)).toMap shouldBe before
  }

  "board" should "refuse to remove a user's files from rtl/" in {
    val out = dir / "own"
    os.makeDir.all(out / "rtl" / "sub")
    os.write(out / "rtl" / "mine.v", "module mine; endmodule\n")
    os.write(out / "rtl" / "sub" / "deep.sv", "x\n")
    refused(out, "rtl/mine.v", "rtl/sub/deep.sv")
  }

  it should "write again over its own files and refuse an edited one" in {
    val out = dir / "edited"
    runCli("board", "de2-115", "--out", out.toString)._1 shouldBe 0
    os.isFile(out / SafeWrite.Manifest) shouldBe true
    os.write(out / "notes.md", "the user's own notes, not named by the project\n")
    runCli("board", "de2-115", "--out", out.toString, "--design", "corrected")._1 shouldBe 0
    os.read(out / "notes.md") should include("own notes")
    os.write.append(out / "moire_de2_115.qsf", "# my pin edits\n")
    refused(out, "moire_de2_115.qsf")
    os.read(out / "moire_de2_115.qsf") should include("my pin edits")
  }
}

/** A board project whose default decimation makes more records than its UART carries: said when it is written (it
  * was a plain summary line, another tool's fuzz sweep, F20).
  */
class ProjectRateSpec extends AnyFlatSpec with Matchers {
  "board" should "warn when the default decimation's records exceed what the UART carries" in {
    val dir = os.temp.dir(prefix = "moire-project-rate-")
    val (code, out, err) = moire.cli.CliInProcess.runCliOut("board", "de2-115", "--decimation", "1", "--out", (dir / "fast").toString)
    withClue(err) { code shouldBe 0 }
    out.linesIterator.filter(_.startsWith("WARNING: decimation 1 makes 50000000 records/s")).toSeq should have size 1
    out should include("--decimation 74870 or more streams every record")
    val (_, slow, _) = moire.cli.CliInProcess.runCliOut("board", "de2-115", "--out", (dir / "slow").toString)
    slow should not include "WARNING"
  }
}
