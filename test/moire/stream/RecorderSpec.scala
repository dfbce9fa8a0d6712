package moire.stream

import moire.MoireError
import moire.cli.CliProcess
import moire.protocol.{Registers, StreamV1}
import moire.recording.Recording
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class RecorderSpec extends AnyFlatSpec with Matchers {
  private val d = 80000L
  private val clock = 40000000L
  private val n = 8

  /** 400 frames of simulated records with faults at frames 30 (CRC), 45 (3 dropped), 60 (frame lost), 75 (bad type byte). */
  private def plan(): (IndexedSeq[Planned], IndexedSeq[Record]) = {
    val all = BoardStreamFixture.records(400 * n + 3, d, clock.toDouble)
    var at = 0
    val frames = (0 until 400).flatMap { k =>
      val dropped = if (k == 45) 3 else 0
      at += dropped
      val rs = all.slice(at, at + n); at += n
      k match {
        case 30 => Some(Planned(rs, flip = Seq(8 + 12 * 3 + 5)))
        case 60 => None // lost on the way: the next frame skips its seq
        case 61 => Some(Planned(rs, skipSeq = 1))
        case 75 => Some(Planned(rs, flip = Seq(2)))
        case _ => Some(Planned(rs, dropped))
      }
    }
    (frames, all)
  }

  private def opts(pty: PtyPair, out: os.Path, seconds: Double = 1.2) =
    RecordOptions(pty.host.toString, seconds, out.toString, quiet = true, timeoutMs = 1000)

  "record" should "write every record received, with realistic columns and exact loss figures" in PtyPair { pty =>
    val (frames, _) = plan()
    val board = new FakeBoard(pty, FakeBoard.registers(decimation = 1000), streamWhen = Some(_.addr == Registers.FrameRecords.addr))
    board.stream(frames.iterator)
    val out = pty.dir / "out" / "rec.csv"
    val said = Vector.newBuilder[String]; val warned = Vector.newBuilder[String]
    // 2 s at about 105 frames/s: the faults (frames 30-75) stay inside the recording on a loaded machine
    val r = try Recorder.run(opts(pty, out, seconds = 2.0).copy(decimation = Some(d)), said += _, warned += _) finally board.close()
    board.registers(Registers.Decimation.addr) shouldBe d

    val sent = board.sent
    val rec = Recording.read(out)
    val idx = rec.extra("sample_index").map(_.toLong)
    // the recorded range of sent frames: from the frame holding the first row to the one holding the last
    val first = sent.indexWhere(_.frame.records.exists(_.index == idx.head))
    val last = sent.lastIndexWhere(_.frame.records.exists(_.index == idx.last))
    first should (be >= 1 and be <= 5)
    last should be > 80
    val expected = sent.slice(first, last + 1).filterNot(_.damaged).flatMap(_.frame.records)
    rec.length shouldBe expected.size
    rec.sin.toSeq shouldBe expected.map(_.sin); rec.cos.toSeq shouldBe expected.map(_.cos)
    idx.toSeq shouldBe expected.map(_.index)
    def col(name: String) = rec.extra(name).toSeq
    def flag(f: Boolean) = if (f) 1.0 else 0.0
    col("position") shouldBe expected.map(_.position.toDouble)
    col("otr_sin") shouldBe expected.map(x => flag(x.otrSin)); col("otr_cos") shouldBe expected.map(x => flag(x.otrCos))
    col("present") shouldBe expected.map(x => flag(x.present)); col("over_range") shouldBe expected.map(x => flag(x.overRange))
    col("step_fault") shouldBe expected.map(x => flag(x.stepFault)); col("direction") shouldBe expected.map(x => flag(x.direction))
    rec.extra.keySet shouldBe RecordColumns.extra.toSet
    // the simulated motion is there: positions move back and forth, both directions occur
    col("position").max - col("position").min should be > 1000.0
    col("direction").distinct.size shouldBe 2

    rec.sampleRateHz shouldBe clock.toDouble / d
    val m = rec.meta
    m("adc_format") shouldBe "offset-binary"; m("adc") shouldBe "AD9226"; m("adc_bits") shouldBe "12"; m("source") shouldBe "de2-115"
    m("decimation") shouldBe d.toString; m("adc_clock_hz") shouldBe clock.toString; m("counts_per_period") shouldBe "1024"
    // injected: one CRC error (frame 30), one bad header (frame 75), frames 30, 60, 75 missing from seq,
    // index gaps at 30 (8 records), 45 (3 dropped), 60 (8), 75 (8)
    m("frames") shouldBe (sent.slice(first, last + 1).count(!_.damaged)).toString
    m("crc_errors") shouldBe "1"; m("bad_headers") shouldBe "1"
    m("seq_gaps") shouldBe "3"; m("missing_frames") shouldBe "3"
    m("gaps") shouldBe "4"; m("missing_records") shouldBe "27"
    m("dropped_records") shouldBe "3"; m("truncated") shouldBe "0"
    r.rows shouldBe rec.length
    val w = warned.result()
    w.size shouldBe 1
    w.head should startWith("WARNING: data lost: 1 frame(s) failed the CRC, 1 frame(s) had a bad header, 3 seq gaps (3 frames missing), " +
      "4 sample-index gaps (27 records missing), the board dropped 3 record(s)")
    said.result().head should include(s"${rec.length} records at 500 Hz (adc clock 40000000 Hz / D 80000)")
  }

  it should "record a clean stream without a warning (listen-only, setup by hand)" in PtyPair { pty =>
    val all = BoardStreamFixture.records(200 * n, d, clock.toDouble, first = 0xFFFFFFFFL - 5 * n * d) // index wraps after 5 frames (early: a loaded machine streams fewer in the time)
    val board = new FakeBoard(pty, Map.empty)
    board.stream(all.grouped(n).map(rs => Planned(rs)), 20000)
    val out = pty.dir / "clean.csv"
    val warned = Vector.newBuilder[String]
    val r = try Recorder.run(opts(pty, out, 0.5).copy(listenOnly = true, decimation = Some(d), adcClockHz = Some(clock.toDouble),
      adcFormat = Some("twos-complement"), countsPerPeriod = Some(1024)), _ => (), warned += _) finally board.close()
    warned.result() shouldBe empty
    board.commands shouldBe empty
    r.stats.lost shouldBe false
    val rec = Recording.read(out)
    rec.meta("adc_format") shouldBe "twos-complement"; rec.adc.format.name shouldBe "twos-complement"; rec.meta("crc_errors") shouldBe "0"; rec.meta("gaps") shouldBe "0"
    val idx = rec.extra("sample_index")
    idx.sliding(2).forall(p => p(1) - p(0) == d.toDouble) shouldBe true // unwrapped past 2^32
    idx.last should be > 4294967295.0
  }

  it should "start after the records at the old decimation that were waiting in the board's FIFO" in PtyPair { pty =>
    val old = BoardStreamFixture.records(5 * n + 3, 1000, clock.toDouble)
    val fresh = BoardStreamFixture.records(150 * n, d, clock.toDouble, first = old.last.index + 777)
    val frames = (old ++ fresh).grouped(n).map(rs => Planned(rs)).toIndexedSeq // frame 5 holds both
    val board = new FakeBoard(pty, FakeBoard.registers(decimation = 1000), streamWhen = Some(_.addr == Registers.FrameRecords.addr))
    board.stream(frames.iterator)
    val out = pty.dir / "settle.csv"
    val warned = Vector.newBuilder[String]
    val r = try Recorder.run(opts(pty, out, 0.5).copy(decimation = Some(d)), _ => (), warned += _) finally board.close()
    warned.result() shouldBe empty
    val idx = Recording.read(out).extra("sample_index").map(_.toLong)
    idx.head shouldBe frames(7).records.head.index // frame 6 is the first all at D; the recording starts after it
    r.stats.indexGaps shouldBe 0; r.stats.seqGaps shouldBe 0
  }

  it should "name the record spacing when --decimation given by hand is not the board's (no pty needed)" in {
    val recs = BoardStreamFixture.records(40 * n, 1000, clock.toDouble)
    val bytes = Encoder.frames(recs.grouped(n).zipWithIndex.map { case (rs, k) => RecordFrame(k, 0, rs) }.toSeq)
    val o = RecordOptions("memory", 0.2, "never.csv", baud = 1000000, quiet = true, listenOnly = true, decimation = Some(d),
      adcClockHz = Some(clock.toDouble), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))
    val e = intercept[MoireError](Recorder.record(new MemoryLink(bytes), o, _ => (), _ => ()))
    e.getMessage should startWith(s"memory: records are 1000 samples apart, never the decimation $d in one frame")
    os.exists(os.pwd / "never.csv") shouldBe false
    // with the right D the same bytes record cleanly: all frames after the first
    val out = os.temp.dir() / "mem.csv"
    val r = Recorder.record(new MemoryLink(bytes), o.copy(decimation = Some(1000), out = out.toString), _ => (), _ => ())
    r.rows shouldBe 39 * n; r.stats.lost shouldBe false
  }

  it should "keep what arrived when the link fails mid-recording, and fail with one line naming the file" in {
    val recs = BoardStreamFixture.records(40 * n, 1000, clock.toDouble)
    val bytes = Encoder.frames(recs.grouped(n).zipWithIndex.map { case (rs, k) => RecordFrame(k, 0, rs) }.toSeq)
    // the adapter unplugged once the bytes are out (SerialLink's read fails so)
    val link = new ByteLink {
      private val m = new MemoryLink(bytes)
      private var left = bytes.length
      val name = "memory"
      def write(a: Array[Byte]): Unit = m.write(a)
      def read(buf: Array[Byte]): Int = if (left <= 0) throw new StreamError("memory: read failed (error 5); is the adapter still plugged in?")
        else { val k = m.read(buf); left -= k; k }
      def close(): Unit = ()
    }
    val out = os.temp.dir() / "cut.csv"
    val o = RecordOptions("memory", 5.0, out.toString, baud = 1000000, quiet = true, listenOnly = true, decimation = Some(1000),
      adcClockHz = Some(clock.toDouble), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))
    val e = intercept[MoireError](Recorder.record(link, o, _ => (), _ => ()))
    e.getMessage should (include("read failed") and include(s"$out holds the ${39 * n} records received"))
    e.getMessage.linesIterator.size shouldBe 1
    val rec = Recording.read(out)
    rec.length shouldBe 39 * n
    rec.meta.get("link_failed_after_s") should not be empty
  }

  it should "warn when the stream stops part-way, and keep what arrived" in {
    // 40 frames (320 records) of a board making 40,000 a second, then silence for the rest of the second
    val recs = BoardStreamFixture.records(40 * n, 1000, clock.toDouble)
    val link = new MemoryLink(Encoder.frames(recs.grouped(n).zipWithIndex.map { case (rs, k) => RecordFrame(k, 0, rs) }.toSeq))
    val out = os.temp.dir() / "stopped.csv"
    val o = RecordOptions("memory", 1.0, out.toString, baud = 1000000, quiet = true, listenOnly = true, decimation = Some(1000),
      adcClockHz = Some(clock.toDouble), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))
    val warned = Vector.newBuilder[String]
    val r = Recorder.record(link, o, _ => (), warned += _)
    val w = warned.result()
    withClue(w) { w.exists(x => x.startsWith(s"WARNING: ${r.rows} records arrived in ") && x.contains("stopped or paused part-way")) shouldBe true }
    r.warnings should not be empty
    Recording.read(out).length shouldBe r.rows
    r.rows should be >= 39 * n
  }

  it should "refuse a board's counts per period that is no power of two before it records, and write numbers exactly" in {
    // a file with M = 0 was written, and explain, replay and the monitor then refused it (another tool's fuzz sweep, N1)
    val o = RecordOptions("memory", 1.0, (os.temp.dir() / "m0.csv").toString, quiet = true)
    for (m <- Seq(0L, 1000L, 131072L)) {
      val answers = Iterator(clock, Registers.AdcOffsetBinary.toLong, m)
      val e = intercept[MoireError](Recorder.adcSetup(null, o, _ => answers.next()))
      e.getMessage shouldBe s"memory: the board reports counts_per_period $m (a power of two from 4 to 65536 expected); give --counts-per-period"
    }
    Recorder.adcSetup(null, o, { val a = Iterator(clock, Registers.AdcOffsetBinary.toLong, 1024L); _ => a.next() })._3 shouldBe 1024
    // --ref-counts-per-period 0.000012345678 was written 0.000012, and 1e-7 as "0." (N3)
    for (v <- Seq(0.000012345678, 1e-7, 1e-300, 2.5, 40e6 / 3, 123456789012345678901.0))
      moire.numbers.Decimal.double(Recorder.num(v)) shouldBe Some(v)
  }

  it should "refuse a file of another kind under --out before it records" in {
    val out = os.temp.dir() / "notes.csv"
    os.write(out, "my notes\n")
    val o = RecordOptions("memory", 5.0, out.toString, baud = 1000000, quiet = true, listenOnly = true, decimation = Some(1000),
      adcClockHz = Some(clock.toDouble), adcFormat = Some("offset-binary"), countsPerPeriod = Some(1024))
    val link = new MemoryLink(Array.emptyByteArray)
    val t0 = System.nanoTime()
    val e = intercept[MoireError](Recorder.record(link, o, _ => (), _ => ()))
    (System.nanoTime() - t0) / 1e9 should be < 4.0 // not after the 5 s of recording
    e.getMessage should include("holds text, and this command writes a moire recording")
    os.read(out) shouldBe "my notes\n"
  }

  it should "say in one line when the board does not answer, and write no file" in PtyPair { pty =>
    val out = pty.dir / "none.csv"
    val e = intercept[MoireError](Recorder.run(opts(pty, out), _ => (), _ => ()))
    e.getMessage should include("the board did not answer a read of id within 1000 ms")
    e.getMessage should include("--listen-only")
    e.getMessage.linesIterator.size shouldBe 1
    os.exists(out) shouldBe false
  }

  it should "fail clearly when no frame arrives (silence or a wrong baud rate), and write no file" in PtyPair { pty =>
    val out = pty.dir / "none.csv"
    val hand = opts(pty, out, 0.3).copy(listenOnly = true, decimation = Some(d), adcClockHz = Some(4e7), adcFormat = Some("offset-binary"),
      countsPerPeriod = Some(1024), baud = 1000000)
    val e = intercept[MoireError](Recorder.run(hand, _ => (), _ => ()))
    e.getMessage should include("no frames in")
    e.getMessage should include("nothing received")
    val noise = new Thread(() => pty.feed(Array.tabulate(30000)(i => (i * 7919 % 251).toByte), 20000))
    noise.start()
    val e2 = intercept[MoireError](Recorder.run(hand, _ => (), _ => ()))
    noise.join()
    e2.getMessage should include("bytes but 0 record frames")
    e2.getMessage should include("check --baud")
    os.exists(out) shouldBe false
  }

  it should "refuse bad options before opening the port" in {
    def bad(o: RecordOptions, msg: String) = intercept[MoireError](Recorder.validate(o)).getMessage should include(msg)
    val o = RecordOptions("/dev/null", 1, "x.csv")
    bad(o.copy(seconds = 0), "--seconds")
    bad(o.copy(decimation = Some(0)), "--decimation must be in 1..16777216")
    bad(o.copy(adcFormat = Some("gray")), "--adc-format")
    bad(o.copy(listenOnly = true, decimation = Some(4)), "give --adc-clock-hz, --adc-format, --counts-per-period by hand")
  }

  it should "warn before recording when the link cannot carry the records" in {
    Recorder.linkRecordsPerSecond(115200, 8) shouldBe 11520.0 / 106 * 8 // 869 records/s, as docs/recording.md says
    val s = BoardSetup(1000, 40e6, moire.signal.AdcFormat.OffsetBinary, 1024, Some(8), fromBoard = true)
    Recorder.capacityWarning(s, 115200).get shouldBe
      "WARNING: the board makes 40000 records/s, 115200 baud carries at most 869: records will be dropped; use --decimation 46007 or more"
    Recorder.capacityWarning(s.copy(decimation = 46007), 115200) shouldBe None
    Recorder.capacityWarning(s.copy(decimation = 46006), 115200).isDefined shouldBe true
  }

  "moire record (command line)" should "name a missing port and the ports there are, exit 2" in {
    val missing = (os.temp.dir() / "ttyUSB9").toString
    val (code, out, err) = CliProcess.run("record", "--port", missing, "--seconds", "1", "--out", "x.csv")
    code shouldBe 2
    err.trim should fullyMatch regex s"moire: \\Q$missing\\E: no such serial port \\(available: .*\\)"
    out shouldBe empty
  }

  it should "exit 0 with a WARNING line when frames were lost" in PtyPair { pty =>
    val (frames, _) = plan()
    val board = new FakeBoard(pty, FakeBoard.registers(), streamWhen = Some(_.addr == Registers.FrameRecords.addr))
    board.stream(frames.iterator, StreamV1.recordFrameBytes(n) * 500 / n) // as fast as a real board makes 500 records/s
    val out = pty.dir / "cli.csv"
    val (code, stdout, err) = try CliProcess.run("record", "--port", pty.host.toString, "--seconds", "1.5", "--out", out.toString, "--quiet")
      finally board.close()
    withClue(err) { code shouldBe 0 }
    (stdout.linesIterator ++ err.linesIterator).foreach(l => info(l))
    stdout should include("CRC errors 1")
    err.linesIterator.count(_.startsWith("WARNING: data lost")) shouldBe 1
    Recording.read(out).meta("crc_errors") shouldBe "1"
  }
}
