package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import scala.sys.process._

/** simulate and explain as a user runs them: a fresh JVM, files, exit codes. */
class ExplainCliSpec extends AnyFlatSpec with Matchers {
  def run(args: String*): (Int, String, String) = moire.cli.CliProcess.run(args: _*)

  "simulate then explain" should "write a JSON report with the documented fields and the PNG plots" in {
    val dir = os.temp.dir()
    val (c1, _, e1) = run("simulate", "--out", (dir / "rec.csv").toString, "--samples", "60000", "--phase-error-deg", "2",
      "--effect", "channel_skew:skew_s=3e-8")
    withClue(e1) { c1 shouldBe 0 }
    val (c2, out, e2) = run("explain", (dir / "rec.csv").toString, "--json-dir", (dir / "json").toString, "--plots", (dir / "png").toString, "--quiet")
    withClue(e2) { c2 shouldBe 0 }
    val j = ujson.read(os.read(dir / "json" / "rec.json"))
    j("kind").str shouldBe "signals"
    j("file").str should endWith("rec.csv")
    j("baseline")("rms").num should be > j("final")("rms").num
    j("baseline")("bic").num should be > j("final")("bic").num
    val f = j("findings").arr.head
    f("effect").str shouldBe "channel_skew"
    for (k <- Seq("summary", "params", "uncertainty", "delta_bic", "rms_before", "rms_after", "where")) f.obj.keySet should contain(k)
    f("params")("skew_s").num shouldBe 3e-8 +- 6e-9
    j("unexplained").arr shouldBe empty
    val pngs = os.list(dir / "png").map(_.last)
    pngs should contain allOf ("rec_residual_time.png", "rec_residual_phase.png", "rec_residual_spectrum.png", "rec_effect_1_channel_skew.png")
  }

  "explain-bench" should "print the time, samples per second and peak heap of reading and of explain (small recording, not timed)" in {
    val lines = Seq.newBuilder[String]
    ExplainCmd.bench(40000, Some(os.temp.dir().toString), None, lines += _)
    val Seq(read, all) = lines.result()
    read should fullyMatch regex """explain-bench: read and checked 40000 rows \([0-9]+ MB file\) in [0-9.]+ s; peak heap in use [0-9]+ MB of [0-9]+ MB \([0-9.]+ MB per million samples\)"""
    all should fullyMatch regex """explain-bench: 40000 samples explained in [0-9.]+ s .* = [0-9]+ samples/s, [0-9.]+ us per sample; CPU [0-9.]+ s \([0-9.]+ cores busy\); peak heap in use [0-9]+ MB of [0-9]+ MB \([0-9.]+ MB per million samples\); .*findings: .*"""
    // without --out its temporary folder (recording, JSON, plots) does not outlive it
    // this JVM's bench folders only: another test run on the machine makes and removes its own beside this one
    val mine = s"moire-bench-${ProcessHandle.current().pid()}-"
    val before = os.list(os.temp.dir() / os.up).count(_.last.startsWith(mine))
    // --runs 2: the same file again in the same JVM, each run's figures on its own line
    val again = Seq.newBuilder[String]
    ExplainCmd.bench(20000, None, None, again += _, runs = 2)
    again.result().tail.map(_.takeWhile(_ != ':')) shouldBe Seq("explain-bench", "explain-bench")
    again.result().tail.map(_.split(": ")(1)) shouldBe Seq("run 1 of 2 (new JVM)", "run 2 of 2 (same JVM)")
    os.list(os.temp.dir() / os.up).count(_.last.startsWith(mine)) shouldBe before
    // the peak is what the heap held at one time: never more than the heap itself, never nothing
    for (l <- Seq(read, all)) {
      val Seq(peak, max) = """heap in use ([0-9]+) MB of ([0-9]+) MB""".r.findFirstMatchIn(l).get.subgroups.map(_.toDouble)
      peak should (be > 0.0 and be <= max)
    }
  }

  "explain on calibration data" should "write a calibration report and its plots" in {
    val dir = os.temp.dir()
    val rows = for (d <- Seq("cw", "ccw"); k <- 0 until 360) yield {
      val r = math.toRadians(k); val e = 4 * math.cos(r) + 1.5 * math.sin(2 * r) + 0.8 * math.cos(5 * r) + (if (d == "cw") 0.3 else -0.3) +
        0.2 * math.sin(k * 12.9898 + (if (d == "cw") 0 else 1)) // deterministic small scatter
      s"$k,$e,$d"
    }
    os.write(dir / "turntable.csv", ("# moire-calibration v1\n# instrument: test\nangle_deg,error_arcsec,direction\n" +: rows).mkString("\n") + "\n")
    val (c, out, err) = run("explain", (dir / "turntable.csv").toString, "--json-dir", (dir / "j").toString, "--plots", (dir / "p").toString)
    withClue(err) { c shouldBe 0 }
    val j = ujson.read(os.read(dir / "j" / "turntable.json"))
    j("kind").str shouldBe "calibration"
    j("findings").arr.map(_("effect").str).toSet shouldBe Set("harmonic_order", "reversal")
    j("findings").arr.find(_("effect").str == "reversal").get("params")("reversal_arcsec").num shouldBe 0.6 +- 0.05
    os.list(dir / "p").map(_.last) should contain allOf ("turntable_fit.png", "turntable_residual_angle.png", "turntable_residual_spectrum.png")
    out should include("harmonic_order")
  }

  "explain" should "name the file and line of malformed input, exit 2, one line" in {
    val dir = os.temp.dir()
    os.write(dir / "bad.csv", "# moire-recording v1\n# sample_rate_hz: 1e6\n# adc_bits: 12\nsin,cos\n1,2\n3\n")
    val (c, _, err) = run("explain", (dir / "bad.csv").toString, "--quiet")
    c shouldBe 2
    val lines = err.linesIterator.filter(_.nonEmpty).toSeq
    lines.size shouldBe 1
    lines.head should include("bad.csv:6: 1 cells, the header has 2")
    val (c2, _, err2) = run("explain", (dir / "none.csv").toString)
    c2 shouldBe 2; err2 should include("no such file")
    // several files: the good one gets its report, the bad ones their line each, exit 2 after all were tried
    val (c4, _, _) = run("simulate", "--out", (dir / "good.csv").toString, "--samples", "20000")
    c4 shouldBe 0
    os.write.over(dir / "good.csv", os.read(dir / "good.csv").replace("# adc_format:", "# adc: AD9226\n# adc_format:"))
    val (c5, out5, err5) = run("explain", (dir / "bad.csv").toString, (dir / "good.csv").toString, (dir / "none.csv").toString,
      "--json-dir", (dir / "j").toString)
    c5 shouldBe 2
    out5 should include("good.csv")
    os.exists(dir / "j" / "good.json") shouldBe true
    err5 should (include("bad.csv:6:") and include("none.csv: no such file") and include("2 of 3 files failed"))
    println(s"explain on bad, good, missing file: exit $c5; stderr:\n$err5")
    val (c3, _, err3) = run("simulate", "--out", (dir / "x.csv").toString, "--effect", "wobble:x=1")
    c3 shouldBe 2; err3 should include("'wobble' is not an effect")
  }

  it should "give every file of a batch its report or its one-line error, and exit 2 after trying all" in {
    val dir = os.temp.dir()
    os.write(dir / "bad.csv", "# moire-recording v1\n# sample_rate_hz: 1e6\n# adc_bits: 12\nsin,cos\n1,2\n3\n")
    val (c1, _, e1) = run("simulate", "--out", (dir / "good.csv").toString, "--samples", "20000")
    withClue(e1) { c1 shouldBe 0 }
    val (c, _, err) = run("explain", (dir / "bad.csv").toString, (dir / "good.csv").toString, "--json-dir", (dir / "json").toString, "--quiet")
    c shouldBe 2
    os.exists(dir / "json" / "good.json") shouldBe true
    os.exists(dir / "json" / "bad.json") shouldBe false
    err should include("bad.csv:6: 1 cells, the header has 2")
    err should include("1 of 2 files failed")
  }
}
