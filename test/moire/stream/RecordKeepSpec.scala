package moire.stream

import moire.MoireError
import moire.files.{Interrupts, SafeWrite}
import moire.recording.Recording
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers
import scala.concurrent.{Await, Future}
import scala.concurrent.ExecutionContext.Implicits.global
import scala.concurrent.duration._

/** A recording cannot be made again: `record` checks its output before it starts, keeps the records when the file
  * cannot be written at the end (a full disk) and when Ctrl-C stops it, and says in one line where they are.
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
    e.getMessage shouldBe s"${out / os.up}: the folder takes no new file (no such file or folder)"
    e.getMessage.linesIterator.size shouldBe 1
  }

  it should "leave no probe file behind in the output's folder" in {
    val dir = os.temp.dir(prefix = "moire-probe-")
    SafeWrite.checkFile(dir / "rec.csv")
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

  it should "keep what arrived when interrupted (the shutdown hook's path), and fail with one line naming the file" in {
    val out = os.temp.dir(prefix = "moire-int-") / "rec.csv"
    val t0 = System.nanoTime()
    val run = Future(Recorder.record(PacedLink.board(8.0, 500), opts(out, 8.0), _ => (), _ => ()))
    Thread.sleep(1500)
    Interrupts.interrupt() shouldBe true // what Ctrl-C's hook calls first
    val e = intercept[MoireError](Await.result(run, 10.seconds))
    (System.nanoTime() - t0) / 1e9 should be < 4.0
    val m = e.getMessage
    m.linesIterator.size shouldBe 1
    m should fullyMatch regex s"""interrupted after \\d+\\.\\d\\d s of 8 s; \\Q$out\\E holds the \\d+ records received"""
    val rec = Recording.read(out)
    m should include(s"holds the ${rec.length} records received")
    rec.length should be > 300 // 1.5 s at 500 a second, less the frame that starts it
    rec.meta.get("interrupted_after_s").map(_.toDouble) should not be empty
    os.list(out / os.up).map(_.last) shouldBe Seq("rec.csv") // written whole, no temporary left
    Interrupts.interrupt() shouldBe false // nothing stoppable runs any more
  }

  "moire record (command line)" should "write what arrived and say so in one line on Ctrl-C (SIGINT), exit 130" in PtyPair { pty =>
    val board = new FakeBoard(pty, FakeBoard.registers(), streamWhen = Some(_.addr == moire.protocol.Registers.FrameRecords.addr))
    val n = 8
    board.stream(BoardStreamFixture.records(8 * 500, d, 40e6).grouped(n).map(rs => Planned(rs)), moire.protocol.StreamV1.recordFrameBytes(n) * 500 / n)
    val out = pty.dir / "sig.csv"
    val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath
    // a job started in the background by a non-interactive shell inherits SIGINT ignored, and so would the child: perl
    // puts the default action back and execs the JVM (same pid), as InterruptSpec does
    val restore = Seq("perl", "-e", "$SIG{INT} = 'DEFAULT'; exec @ARGV or die \"exec: $!\"")
    val p = new ProcessBuilder((restore ++ Seq(javaBin, "-cp", System.getProperty("java.class.path"), "moire.cli.Main", "record",
      "--port", pty.host.toString, "--seconds", "8", "--out", out.toString)): _*).redirectErrorStream(true).start()
    val lines = new java.util.concurrent.LinkedBlockingQueue[String]()
    val reader = new Thread(() => scala.io.Source.fromInputStream(p.getInputStream).getLines().foreach(lines.add))
    reader.setDaemon(true); reader.start()
    try {
      // the progress line at the start of the capture (no terminal here), then a second and a half of records
      val first = lines.poll(30, java.util.concurrent.TimeUnit.SECONDS)
      withClue(s"first line: $first") { first should startWith("record: ") }
      Thread.sleep(1500)
      os.proc("kill", "-INT", p.pid().toString).call() // Ctrl-C (Process.destroy would close the pipe the last line comes through)
      p.waitFor(20, java.util.concurrent.TimeUnit.SECONDS) shouldBe true
      reader.join(5000)
    } finally { p.destroyForcibly(); board.close() }
    val said = Iterator.continually(lines.poll()).takeWhile(_ != null).toSeq
    withClue(s"exit ${p.exitValue()}, said:\n${said.mkString("\n")}\n") {
      p.exitValue() shouldBe 130
      val err = said.filter(_.startsWith("moire: "))
      err should have size 1
      err.head should fullyMatch regex s"""moire: interrupted after \\d+\\.\\d\\d s of 8 s; \\Q$out\\E holds the \\d+ records received"""
      val rows = err.head.split(" records received")(0).split(' ').last.toInt
      Recording.read(out).length shouldBe rows
      rows should be > 300
    }
  }
}
