package moire.stream

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A recording's wall time against its stated clock, and its progress lines in a log. */
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

  "record" should "warn when the sample index runs far from the stated ADC clock (records at 500/s, 1 kHz stated)" in {
    // a board at 40 MHz / D 80000 streams 500 records a second; --adc-clock-hz 1000 would make the file 0.0125 Hz
    val (r, w) = record(opts(1000), PacedLink.board(1.2, 500))
    withClue(w) {
      w should have size 1
      w.head should startWith("WARNING: the sample index ran at about ")
      w.head should include("not the 1000 Hz of --adc-clock-hz: the file's sample rate (0.0125 Hz) and its times are off by a factor of ")
      w.head should endWith("record again with --adc-clock-hz " + r.meta("adc_clock_measured_hz"))
    }
    r.meta("adc_clock_measured_hz").toDouble shouldBe 40e6 +- 8e6
  }

  it should "say nothing of the clock when it is the one stated, nor when the stream is too short to time" in {
    val (r, w) = record(opts(40e6), PacedLink.board(1.2, 500))
    w shouldBe empty
    r.meta("adc_clock_measured_hz").toDouble shouldBe 40e6 +- 8e6
    // all frames at once from memory: no wall time to compare
    val recs = BoardStreamFixture.records(40 * 8, d, 40e6)
    val bytes = Encoder.frames(recs.grouped(8).zipWithIndex.map { case (rs, k) => RecordFrame(k, 0, rs) }.toSeq)
    val (r2, w2) = record(opts(1000, 0.6).copy(baud = 1000000), new MemoryLink(bytes))
    w2.filter(_.contains("sample index")) shouldBe empty
    r2.meta.get("adc_clock_measured_hz") shouldBe None
  }

  "ClockCheck" should "not time a stream the link cannot keep up with (records dropped, or arriving at the link's limit)" in {
    val sp = Some(ClockCheck.Span(0, 0, 2000000000L, 80000L * 1000, 125))
    val st = StreamStats(frames = 125, records = 1000)
    ClockCheck.measured(sp, st, 115200) shouldBe Some(40e6)
    ClockCheck.measured(sp, st.copy(dropped = 3), 115200) shouldBe None
    ClockCheck.measured(sp, st, 9600) shouldBe None // 500 records/s over a 9600 baud link that carries 72
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
