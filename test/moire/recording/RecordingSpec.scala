package moire.recording

import moire.MoireError
import moire.signal.{Adc, AdcFormat}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class RecordingSpec extends AnyFlatSpec with Matchers {
  private val good = IndexedSeq("# moire-recording v1", "# sample_rate_hz: 1000000", "# adc_bits: 12", "# lines_per_rev: 2500",
    "# operator: bench A", "sin,cos,ref_deg", "2048,4095,0.5", "0,100,1.5")

  "Recording" should "parse metadata, codes and extra columns" in {
    val r = Recording.parse("f.csv", good)
    r.sampleRateHz shouldBe 1e6; r.adc shouldBe Adc(12, AdcFormat.OffsetBinary); r.linesPerRev shouldBe Some(2500.0)
    r.sin.toSeq shouldBe Seq(2048, 0); r.cos.toSeq shouldBe Seq(4095, 100); r.extra("ref_deg").toSeq shouldBe Seq(0.5, 1.5)
    r.meta("operator") shouldBe "bench A"
    r.values(r.sin).toSeq shouldBe Seq(0.0, -1.0)
  }

  it should "read back what it writes, in both ADC formats" in {
    for (f <- AdcFormat.all) {
      val r = Recording(2e6, Adc(14, f), Array(0, 16383, 8192), Array(1, 2, 3), Map("note" -> "x"), Map("position" -> Array(0.0, 0.25, 0.5)))
      val p = os.temp(suffix = ".csv"); Recording.write(p, r)
      val b = Recording.read(p)
      b.sin.toSeq shouldBe r.sin.toSeq; b.cos.toSeq shouldBe r.cos.toSeq; b.adc shouldBe r.adc; b.sampleRateHz shouldBe 2e6
      b.extra("position").toSeq shouldBe Seq(0.0, 0.25, 0.5); b.meta("note") shouldBe "x"
    }
  }

  it should "leave out a last row without a line end (it may be cut short), and say so" in {
    val p = os.temp(suffix = ".csv")
    os.write.over(p, good.mkString("", "\n", "\n"))
    val whole = Recording.read(p)
    whole.length shouldBe 2; whole.warnings shouldBe Nil
    os.write.over(p, good.mkString("\n").dropRight(4)) // '0,100,1.5' cut to '0,100'
    val cut = Recording.read(p)
    cut.length shouldBe 1; cut.sin.toSeq shouldBe Seq(2048)
    cut.warnings shouldBe Seq("line 8, the last, has no line end: the file may be cut short; end it with a line break if it is complete; that row was left out")
    // a blank last line without an end is no row: nothing left out
    os.write.over(p, good.mkString("", "\n", "\n  "))
    Recording.read(p).warnings shouldBe Nil
  }

  it should "say when an empty line stands among the data rows (a lost row or two files joined), not at the file's end" in {
    val rowsAt = good.take(7) ++ Seq("", "") ++ good.drop(7) ++ Seq("", "") // lines 8 and 9 empty between rows, two at the end
    val r = Recording.parse("f.csv", rowsAt)
    r.length shouldBe 2
    r.warnings shouldBe Seq("line 8 is empty among the data rows (2 such lines in all): skipped, the rows around it taken as " +
      "consecutive samples; if rows were lost there, the time base is off from there on")
    Recording.parse("f.csv", good ++ Seq("", "")).warnings shouldBe Nil
    Recording.parse("f.csv", good.take(6) ++ Seq("") ++ good.drop(6)).warnings shouldBe Nil // before the first row
  }

  it should "stream a long file into arrays of the right length, with or without a samples line, CRLF and Latin-1 bytes" in {
    val n = 200003 // more than the first block of 65536 rows: the arrays grow
    val rnd = new scala.util.Random(5)
    val r = Recording(1e6, Adc(12), Array.fill(n)(rnd.nextInt(4096)), Array.fill(n)(rnd.nextInt(4096)), Map.empty,
      Map("ref_counts" -> Array.tabulate(n)(i => (i / 3).toDouble)))
    val p = os.temp(suffix = ".csv"); Recording.write(p, r)
    val b = Recording.read(p)
    b.length shouldBe n; b.sin.toSeq shouldBe r.sin.toSeq; b.extra("ref_counts").toSeq shouldBe r.extra("ref_counts").toSeq
    // another writer: CRLF line ends, no samples line, a Latin-1 micro sign in a comment
    val text = os.read(p).linesIterator.filterNot(_.startsWith("# samples:")).toSeq
    val bytes = (text.take(1) ++ Seq("# probe: 5 µm") ++ text.drop(1)).mkString("", "\r\n", "\r\n").getBytes("ISO-8859-1")
    val q = os.temp(suffix = ".csv"); os.write.over(q, bytes)
    val c = Recording.read(q)
    c.length shouldBe n; c.cos.toSeq shouldBe r.cos.toSeq; c.meta("probe") should startWith("5 ")
  }

  it should "take adc as free text and the code format from adc_format, and still read files that put the format under adc" in {
    def fmt(meta: String*): AdcFormat = Recording.parse("f.csv", good.take(3) ++ meta ++ good.drop(3)).adc.format
    fmt("# adc: AD9226") shouldBe AdcFormat.OffsetBinary
    fmt("# adc: AD9226", "# adc_format: twos-complement") shouldBe AdcFormat.TwosComplement
    fmt("# adc: twos-complement") shouldBe AdcFormat.TwosComplement
    Recording.parse("f.csv", good.take(3) ++ Seq("# adc: AD9226 (12 bit, 65 MS/s)") ++ good.drop(3)).meta("adc") shouldBe "AD9226 (12 bit, 65 MS/s)"
    val e = intercept[MoireError](Recording.parse("f.csv", good.take(3) ++ Seq("# adc_format: gray") ++ good.drop(3)))
    e.getMessage should (startWith("f.csv:") and include("adc_format") and include("gray"))
    val r = Recording(1e6, Adc(12, AdcFormat.TwosComplement), Array(1), Array(2), Map("adc" -> "AD9226"))
    val p = os.temp(suffix = ".csv"); Recording.write(p, r)
    val text = os.read.lines(p)
    text should contain allOf ("# adc_format: twos-complement", "# adc: AD9226")
    Recording.read(p).adc.format shouldBe AdcFormat.TwosComplement
  }

  it should "reject malformed input with one message naming file, line and problem" in {
    def bad(lines: IndexedSeq[String], expect: String): Unit = {
      val e = intercept[MoireError](Recording.parse("f.csv", lines))
      e.getMessage should startWith("f.csv:")
      e.getMessage should include(expect)
      e.getMessage.linesIterator.size shouldBe 1
    }
    bad(IndexedSeq(), "f.csv:1: empty file")
    bad(IndexedSeq("sin,cos", "1,2"), "f.csv:1: first line must be")
    bad(good.filterNot(_.contains("sample_rate")), "metadata 'sample_rate_hz' is missing")
    bad(good.filterNot(_.contains("adc_bits")), "metadata 'adc_bits' is missing")
    bad(good.updated(2, "# adc_bits: twelve"), "adc_bits 'twelve'")
    bad(good.updated(6, "2048,x,0.5"), "f.csv:7: cos 'x' is not an integer")
    bad(good.updated(7, "0,4096,1.5"), "f.csv:8: cos code 4096 is outside the 12-bit ADC range 0..4095")
    bad(good.updated(7, "0,-1,1.5"), "outside the 12-bit ADC range")
    // a negative code read as offset binary: the line that declares signed codes is named
    bad(good.updated(7, "-1085,-1290,1.5"), "'-1085,-1290,1.5'; signed codes need the line '# adc_format: twos-complement' before the header")
    bad(good.updated(7, "0,-3000,1.5"), "outside the 12-bit ADC range 0..4095: '0,-3000,1.5'")
    bad(good.updated(6, "2048,4095"), "f.csv:7: 2 cells, the header has 3")
    bad(good.updated(6, "2048,4095,NaN"), "f.csv:7: ref_deg 'NaN' is not a finite number")
    bad(good.take(6), "no data rows")
    bad(good.updated(5, "a,b"), "header must name columns sin and cos")
    bad(good.updated(5, "sin,cos,ref_deg,x"), "f.csv:7: 3 cells, the header has 4: '2048,4095,0.5'")
  }

  it should "show the offending line whole in its message, up to 200 characters" in {
    val long = "2048,4095," + "9" * 150 + "x"
    val e = intercept[MoireError](Recording.parse("f.csv", good.updated(6, long)))
    e.getMessage should endWith(s"'$long'")
    val longer = "2048,4095,1.5" + ",0" * 200
    val e2 = intercept[MoireError](Recording.parse("f.csv", good.updated(6, longer)))
    e2.getMessage should include(s"'${longer.take(200)}...'")
  }

  "The header" should "keep comment lines without a key (also with a colon in their text) and write them back" in {
    val lines = good.take(5) ++ IndexedSeq("# exported by scope-dump rev 7 (CH1 = sin, CH2 = cos)", "# taken at 12:30 by J. Doe",
      "# operator bench A", "#", "# Note: probe 5 cm from the grating") ++ good.drop(5)
    val r = Recording.parse("f.csv", lines)
    r.comments shouldBe Seq("exported by scope-dump rev 7 (CH1 = sin, CH2 = cos)", "taken at 12:30 by J. Doe", "operator bench A")
    r.meta("Note") shouldBe "probe 5 cm from the grating"   // a plain identifier before the colon: a key
    r.meta.keySet should not contain "taken at 12"
    val p = os.temp(suffix = ".csv"); Recording.write(p, r)
    Recording.read(p).comments shouldBe r.comments
  }

  "A twos-complement file" should "hold signed codes or pin patterns, told apart by the values" in {
    def rec(rows: String*) = Recording.parse("t.csv", IndexedSeq("# moire-recording v1", "# sample_rate_hz: 1000000", "# adc_bits: 12",
      "# adc_format: twos-complement", "sin,cos") ++ rows)
    val signed = rec("-2048,2047", "-1,0", "100,-100")
    val pins = rec("2048,2047", "4095,0", "100,3996")
    signed.sin.toSeq shouldBe pins.sin.toSeq; signed.cos.toSeq shouldBe pins.cos.toSeq
    signed.values(signed.sin).toSeq shouldBe Seq(-1.0, -1.0 / 2048, 100.0 / 2048)
    // all in 0..2047: both readings are the same numbers
    rec("0,2047", "5,6").values(rec("0,2047", "5,6").cos).toSeq shouldBe Seq(2047.0 / 2048, 6.0 / 2048)
    val mixed = intercept[MoireError](rec("-5,0", "3000,0")).getMessage
    mixed should include("t.csv:7: signed codes (a negative one on line 6) and pin patterns above 2047 (line 7)")
    intercept[MoireError](rec("-2049,0")).getMessage should include("outside the 12-bit ADC range -2048..4095")
    intercept[MoireError](Recording.parse("o.csv", good.updated(7, "-5,100,1.5"))).getMessage should include("outside the 12-bit ADC range 0..4095")
  }

  "Calibration" should "reject duplicate angles and bad directions, naming the line" in {
    val c = IndexedSeq("# moire-calibration v1", "angle_deg,error_arcsec,direction", "0,1.5,cw", "10,2,cw", "0,1,ccw", "20,1,cw")
    Calibration.parse("c.csv", c).hasDirection shouldBe true
    intercept[MoireError](Calibration.parse("c.csv", c :+ "10,3,cw")).getMessage should include("c.csv:7: angle 10.0 repeats line 4 (cw)")
    intercept[MoireError](Calibration.parse("c.csv", c :+ "30,3,up")).getMessage should include("c.csv:7: direction 'up'")
    intercept[MoireError](Calibration.parse("c.csv", c :+ "30,nan,cw")).getMessage should include("c.csv:7: error_arcsec 'nan' is not a number")
  }
}
