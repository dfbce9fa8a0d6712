package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Bad inputs a user (or a fuzzer) gives: each gets exit code 2 and one line that names the problem, no
  * Java class name, and no existing file changes. Runs the command line in this JVM (Main.run).
  */
class BadInputSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-bad-")
  private val head = "# moire-recording v1\n# sample_rate_hz: 1000000\n# adc_bits: 12\n"
  private def rows(n: Int): String = (0 until n).map { i =>
    val a = 2 * math.Pi * i / 50.0; s"${2048 + (1500 * math.sin(a)).round},${2048 + (1500 * math.cos(a)).round}" }.mkString("\n") + "\n"
  private val good = dir / "good.csv"
  os.write(good, head + "sin,cos\n" + rows(2000))

  /** (exit code, stderr) of the command line run here. */
  private def run(args: String*): (Int, String) = {
    val err = new java.io.ByteArrayOutputStream(); val out = new java.io.ByteArrayOutputStream()
    val (e0, o0) = (System.err, System.out)
    System.setErr(new java.io.PrintStream(err, true)); System.setOut(new java.io.PrintStream(out, true))
    val code = try Console.withOut(out)(Console.withErr(err)(Main.run(args.toArray))) finally { System.setErr(e0); System.setOut(o0) }
    (code, err.toString)
  }

  private val classNames = """(java|scala|ujson|mainargs|chisel3|firrtl)\.[a-z]+\.[A-Z]|Exception|\$[A-Z]|\tat """.r

  /** One bad case: exit 2, one line naming `expect`, no class name, files in `keep` unchanged. */
  private def bad(kind: String, expect: String, keep: Seq[os.Path] = Nil)(args: String*): Unit =
    it should s"refuse $kind" in {
      val before = keep.map(f => f -> (if (os.exists(f)) Some(os.read.bytes(f).toSeq) else None))
      val (code, err) = run(args: _*)
      withClue(s"stderr: $err") {
        code shouldBe 2
        err.linesIterator.filter(_.nonEmpty).toSeq should have size 1
        err should include(expect)
        classNames.findFirstIn(err) shouldBe None
      }
      for ((f, b) <- before) withClue(s"$f changed: ") { (if (os.exists(f)) Some(os.read.bytes(f).toSeq) else None) shouldBe b }
    }

  private def rec(name: String, text: String): String = { os.write.over(dir / name, text); (dir / name).toString }

  "explain" should "read a recording with a byte-order mark, CRLF line ends and adc as free text" in {
    val f = rec("bom.csv", "\uFEFF" + (head + "# adc: AD9226\n# operator: bench 3\nsin,cos\n" + rows(2000)).replace("\n", "\r\n"))
    val (code, err) = run("explain", f, "--quiet", "--no-rtl")
    withClue(err) { code shouldBe 0 }
  }

  behavior of "explain"
  bad("a missing file", "no such file")("explain", (dir / "none.csv").toString)
  bad("a file that is not a recording", "first line must be")("explain", rec("text.csv", "hello\n"))
  bad("an empty file", "first line must be")("explain", rec("empty.csv", ""))
  bad("a missing sample rate", "sample_rate_hz' is missing")("explain", rec("nofs.csv", "# moire-recording v1\n# adc_bits: 12\nsin,cos\n1,2\n"))
  bad("a sample rate of 1e300", "not a sample rate")("explain", rec("fs.csv", "# moire-recording v1\n# sample_rate_hz: 1e300\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a sample rate of NaN", "not a sample rate")("explain", rec("fsnan.csv", "# moire-recording v1\n# sample_rate_hz: NaN\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a negative sample rate", "not a sample rate")("explain", rec("fsneg.csv", "# moire-recording v1\n# sample_rate_hz: -5\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("adc_bits out of range", "adc_bits")("explain", rec("bits.csv", "# moire-recording v1\n# sample_rate_hz: 1e6\n# adc_bits: 40\nsin,cos\n" + rows(100)))
  bad("an unknown adc_format", "adc_format")("explain", rec("fmt.csv", head + "# adc_format: gray\nsin,cos\n" + rows(100)))
  bad("a header sin,cos,sin", "column 'sin' appears 2 times")("explain", rec("dupcol.csv", head + "sin,cos,sin\n1,2,3\n"))
  bad("a duplicated metadata key", "metadata key 'adc_bits' appears twice")("explain", rec("dupkey.csv", head + "# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a truncated file (samples says more rows)", "metadata samples says '200000' but the file has 2000 data rows")(
    "explain", rec("trunc.csv", head + "# samples: 200000\nsin,cos\n" + rows(2000)))
  bad("a header without cos", "header must name columns sin and cos")("explain", rec("nocos.csv", head + "sin,x\n1,2\n"))
  bad("a ragged row", "1 cells, the header has 2")("explain", rec("ragged.csv", head + "sin,cos\n1,2\n3\n"))
  bad("a code above the ADC range", "outside the 12-bit ADC range")("explain", rec("range.csv", head + "sin,cos\n5000,2\n"))
  bad("a negative code", "outside the 12-bit ADC range")("explain", rec("neg.csv", head + "sin,cos\n-1,2\n"))
  bad("a code that is not an integer", "is not an integer ADC code")("explain", rec("frac.csv", head + "sin,cos\n1.5,2\n"))
  bad("NaN in an extra column", "is not a finite number")("explain", rec("nan.csv", head + "sin,cos,ref_deg\n1,2,NaN\n"))
  bad("1e400 in an extra column", "is not a finite number")("explain", rec("inf.csv", head + "sin,cos,ref_deg\n1,2,1e400\n"))
  bad("Infinity in an extra column", "is not a finite number")("explain", rec("inf2.csv", head + "sin,cos,ref_deg\n1,2,-Infinity\n"))
  bad("a metadata line without a colon", "metadata line must be '# key: value'")("explain", rec("meta.csv", head + "# nonsense\nsin,cos\n1,2\n"))
  bad("a header but no rows", "no data rows")("explain", rec("norows.csv", head + "sin,cos\n"))
  bad("a 1-row recording", "1 samples; explain needs at least 64")("explain", rec("one.csv", head + "sin,cos\n1,2\n"))
  bad("a 10-row recording", "10 samples; explain needs at least 64")("explain", rec("ten.csv", head + "sin,cos\n" + rows(10)))
  bad("a dead cos channel", "cos channel constant at code 2048")(
    "explain", rec("dead.csv", head + "sin,cos\n" + rows(2000).linesIterator.map(l => l.split(",")(0) + ",2048").mkString("\n") + "\n"))
  bad("a JSON folder that is a file", "is a file, not a folder", Seq(good))("explain", good.toString, "--json-dir", good.toString)
  bad("two inputs with one name and one report folder", "share the name x")({
    os.makeDir.all(dir / "a"); os.makeDir.all(dir / "b"); os.copy.over(good, dir / "a" / "x.csv"); os.copy.over(good, dir / "b" / "x.csv")
    "explain" }, (dir / "a" / "x.csv").toString, (dir / "b" / "x.csv").toString, "--json-dir", (dir / "j").toString)
  bad("an unknown option", "--foo")("explain", good.toString, "--foo")

  behavior of "simulate"
  private val existing = dir / "existing.csv"
  os.write.over(existing, "keep me\n")
  private def sim(args: String*): Seq[String] = Seq("simulate", "--out", existing.toString) ++ args
  bad("--phase-error-deg NaN", "--phase-error-deg must be a finite number", Seq(existing))(sim("--phase-error-deg", "NaN"): _*)
  bad("--noise Infinity", "--noise must be a finite number", Seq(existing))(sim("--noise", "Infinity"): _*)
  bad("--noise -1", "--noise must be 0 or more", Seq(existing))(sim("--noise", "-1"): _*)
  bad("--gain-sin Infinity", "--gain-sin must be a finite number", Seq(existing))(sim("--gain-sin", "Infinity"): _*)
  bad("--sample-rate-hz Infinity", "--sample-rate-hz must be a finite number", Seq(existing))(sim("--sample-rate-hz", "Infinity"): _*)
  bad("--sample-rate-hz 0", "--sample-rate-hz must be above 0", Seq(existing))(sim("--sample-rate-hz", "0"): _*)
  bad("--samples 0", "--samples must be at least 1", Seq(existing))(sim("--samples", "0"): _*)
  bad("--amplitude 0", "--amplitude must be above 0", Seq(existing))(sim("--amplitude", "0"): _*)
  bad("--offset-cos NaN", "--offset-cos must be a finite number", Seq(existing))(sim("--offset-cos", "NaN"): _*)
  bad("an unknown effect", "'wobble' is not an effect", Seq(existing))(sim("--effect", "wobble:x=1"): _*)
  bad("an unknown ADC format", "--adc", Seq(existing))(sim("--adc", "gray"): _*)
  bad("an output through a file", "is a file, not a folder", Seq(good))("simulate", "--out", (good / "x.csv").toString, "--samples", "100")

  behavior of "replay"
  bad("an output that is its input", "is an input of this command", Seq(good))("replay", good.toString, "--out", good.toString)
  bad("a missing recording", "no such file")("replay", (dir / "none.csv").toString)
}
