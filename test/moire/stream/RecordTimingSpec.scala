package moire.stream

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A recording's progress lines in a log. */
class RecordTimingSpec extends AnyFlatSpec with Matchers {
  private val d = 80000L
  private def opts(clock: Double, seconds: Double = 1.2) = RecordOptions("paced", seconds, "unused.csv", quiet = true, listenOnly = true,
    decimation = Some(d), adcClockHz = Some(clock), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))
  private def record(o: RecordOptions, link: ByteLink): (RecordResult, Seq[String]) = {
    val out = os.temp.dir(prefix = "moire-clock-") / "rec.csv"
    val warned = Vector.newBuilder[String]
    val r = Recorder.record(link, o.copy(out = out.toString), _ => (), warned += _)
    (r, warned.result())
  }

  "record's progress" should "say only its start and end in a log (not a terminal), not a line each 0.4 s" in {
    assume(!moire.progress.Bar.terminal, "stderr is a terminal here")
    val err = new java.io.ByteArrayOutputStream(); val e0 = System.err
    System.setErr(new java.io.PrintStream(err, true))
    try record(opts(40e6, 1.5).copy(quiet = false), PacedLink.board(1.5, 500)) finally System.setErr(e0)
    val lines = err.toString.linesIterator.filter(_.startsWith("record: ")).toSeq
    withClue(lines.mkString("\n")) {
      lines should have size 2
      lines.head should startWith("record: 0.0/1.5 s")
      lines.last should startWith("record: 1.")
    }
  }
}
