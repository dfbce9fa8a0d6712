package moire.stream

import moire.MoireError
import moire.files.SafeWrite
import moire.recording.Recording
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A recording cannot be made again: `record` checks its output before it starts, keeps the records when the file
  * cannot be written at the end (a full disk), and says in one line where they are.
  */
class RecordKeepSpec extends AnyFlatSpec with Matchers {
  private val d = 80000L
  private def opts(out: os.Path, seconds: Double) = RecordOptions("paced", seconds, out.toString, quiet = true, listenOnly = true,
    decimation = Some(d), adcClockHz = Some(40e6), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))

  "record" should "refuse an output no file can be made in (/proc) before it records, not after" in {
    assume(os.isDir(os.root / "proc"), "no /proc here")
    val out = os.root / "proc" / "moire-rec.csv"
    val t0 = System.nanoTime()
    val e = intercept[MoireError](Recorder.record(PacedLink.board(1.0, 500), opts(out, 1.0), _ => (), _ => ()))
    (System.nanoTime() - t0) / 1e9 should be < 0.5 // the 1 s was not recorded first
    e.getMessage shouldBe s"$out: cannot write a file there (no such file or folder)"
    e.getMessage.linesIterator.size shouldBe 1
  }

  it should "leave no probe file behind in the output's folder" in {
    val dir = os.temp.dir(prefix = "moire-probe-")
    SafeWrite.checkWritable(dir / "rec.csv")
    os.list(dir) shouldBe empty
  }

  it should "keep the records in a file of the temporary folder when the disk is full at the end, and name it" in {
    val dir = os.temp.dir(prefix = "moire-full-")
    val out = dir / "rec.csv"
    val old = SafeWrite.beforeRename
    SafeWrite.beforeRename = t => { if (t == out) throw new java.io.IOException("No space left on device"); old(t) }
    val e = try intercept[MoireError](Recorder.record(PacedLink.board(0.6, 500), opts(out, 0.6), _ => (), _ => ()))
      finally SafeWrite.beforeRename = old
    val m = e.getMessage
    m.linesIterator.size shouldBe 1
    m should (startWith(s"$out: cannot write (No space left on device); the ") and include(" records received are in "))
    val kept = os.Path(m.split(" records received are in ").last.stripSuffix(" instead"))
    try {
      kept / os.up shouldBe os.Path(System.getProperty("java.io.tmpdir"), os.pwd)
      kept.last should fullyMatch regex """moire-record-\d{8}-\d{6}(-\d+)?\.csv"""
      val rows = m.split(" records received")(0).split(' ').last.toInt
      rows should be > 100
      Recording.read(kept).length shouldBe rows
    } finally os.remove(kept)
    os.exists(out) shouldBe false
  }
}
