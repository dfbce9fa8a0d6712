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

  import CliInProcess.{classNames, runCli}

  /** The kinds registered by [[bad]]. */
  private var kinds = 0

  private def bad(kind: String, expect: String, keep: Seq[os.Path] = Nil)(args: String*): Unit = {
    kinds += 1
    it should s"refuse $kind" in {
      val before = keep.map(f => f -> (if (os.exists(f)) Some(os.read.bytes(f).toSeq) else None))
      val (code, err) = runCli(args: _*)
      withClue(s"stderr: $err") {
        code shouldBe 2
        err.linesIterator.filter(_.nonEmpty).toSeq should have size 1
        err should include(expect)
        classNames.findFirstIn(err) shouldBe None
      }
      for ((f, b) <- before) withClue(s"$f changed: ") { (if (os.exists(f)) Some(os.read.bytes(f).toSeq) else None) shouldBe b }
    }
  }

  private def rec(name: String, text: String): String = { os.write.over(dir / name, text); (dir / name).toString }
  private def mine(folder: String, name: String, text: String): os.Path = { os.makeDir.all(dir / folder); os.write.over(dir / folder / name, text); dir / folder / name }
  /** A 36-point calibration table (10 degree steps): header and rows. */
  private val calRows = "angle_deg,error_arcsec\n" + (0 until 360 by 10).map { a =>
    val t = math.toRadians(a); f"$a,${2 * math.sin(t) + 0.5 * math.cos(3 * t)}%.4f" }.mkString("\n") + "\n"
  private val cal = dir / "cal.csv"
  os.write.over(cal, "# moire-calibration v1\n" + calRows)
  /** A file where a folder is wanted. */
  private val aFile = dir / "a-file"
  os.write.over(aFile, "keep\n")

  "explain" should "read a recording with a byte-order mark, CRLF line ends and adc as free text" in {
    val f = rec("bom.csv", "\uFEFF" + (head + "# adc: AD9226\n# operator: bench 3\nsin,cos\n" + rows(2000)).replace("\n", "\r\n"))
    val (code, err) = runCli("explain", f, "--quiet", "--no-rtl")
    withClue(err) { code shouldBe 0 }
  }

  it should "take an option after the file written as --name=value" in {
    val (code, err) = runCli("explain", good.toString, "--quiet", "--no-rtl", "--min-effect-lsb=0.5", "--search-samples=0")
    withClue(err) { code shouldBe 0 }
  }

  "explain" should "say a reference its scale takes out of range so, not as 'within NaN degree' (counts_per_period 2^63)" in {
    val f = rec("cpp63.csv", head + "# counts_per_period: 9223372036854775808\nsin,cos,position\n" +
      rows(2000).linesIterator.zipWithIndex.map { case (r, i) => s"$r,$i" }.mkString("\n") + "\n")
    val (code, err) = runCli("explain", f, "--quiet", "--no-rtl", "--json-dir", (dir / "cpp63").toString)
    withClue(err) { code shouldBe 0 }
    val text = os.read(dir / "cpp63" / "cpp63.json")
    text should not include "NaN"
    text should include("take the fit out of range")
  }

  behavior of "explain"
  bad("a missing file", "no such file")("explain", (dir / "none.csv").toString)
  // an empty file name was the working folder, told back as "/the/folder: is a folder, not a file"
  bad("an empty recording name", "explain: a recording's name is empty ('')")("explain", good.toString, "", "--quiet", "--no-rtl")
  bad("an empty replay recording name", "replay: the recording's name is empty ('')")("replay", "")
  for ((opt, args) <- Seq("--model" -> Seq("explain", good.toString, "--quiet", "--model", ""), "--input" -> Seq("calibrate", "--input", ""),
    "--recording" -> Seq("explain-bench", "--recording", ""), "--replay" -> Seq("monitor", "--replay", ""),
    "--coefficients" -> Seq("board-reg", "--port", "/dev/null", "--coefficients", ""), "--save" -> Seq("board-reg", "--port", "/dev/null", "--save", "")))
    bad(s"an empty $opt file name", s"$opt: the file's name is empty; give a file name")(args: _*)
  // a user's own file under a report's name: refused before the fit, left as it was
  private val okRec = rec("ok.csv", "# moire-recording v1\n# sample_rate_hz: 1000\n# adc_bits: 12\nsin,cos\n1,2\n")
  private val userJson = mine("oj", "ok.json", "{\"mine\": 1}\n")
  for (v <- Seq("5000", "abc", "1.5", "-1", "1e10", ""))
    bad(s"explain --search-samples '$v'", s"--search-samples needs 0 (search every sample) or a whole number of samples from 10000 to 2147483647, got '$v'")(
      "explain", okRec, "--search-samples", v)
  bad("explain-bench --search-samples 99", "--search-samples needs 0 (search every sample) or a whole number")("explain-bench", "--samples", "10000", "--search-samples", "99")
  bad("--json-dir over a user's JSON of the report's name", "holds JSON, and this command writes an explain report (JSON)", Seq(userJson))(
    "explain", okRec, "--json-dir", (dir / "oj").toString)
  private val userPage = mine("oh", "page.html", "<html><body>my own page</body></html>\n")
  bad("--html over a user's own page", "holds an HTML page, and this command writes an explain report (HTML)", Seq(userPage))(
    "explain", okRec, "--html", userPage.toString)
  private val userNote = mine("op", "ok_residual_time.png", "a note\n")
  bad("--plots where a plot's name holds text", "holds text, and this command writes a PNG image", Seq(userNote))(
    "explain", okRec, "--plots", (dir / "op").toString)
  bad("a file that is not a recording", "first line must be")("explain", rec("text.csv", "hello\n"))
  bad("an empty file", "first line must be")("explain", rec("empty.csv", ""))
  bad("a missing sample rate", "sample_rate_hz' is missing")("explain", rec("nofs.csv", "# moire-recording v1\n# adc_bits: 12\nsin,cos\n1,2\n"))
  // the codes in the other ADC format: read so, a sine jumps by nearly the full range at each zero crossing
  private def pinRows(n: Int, bits: Int => Int): String = (0 until n).map { i =>
    val a = 2 * math.Pi * i / 50.0; s"${bits((1500 * math.sin(a)).round.toInt)},${bits((1500 * math.cos(a)).round.toInt)}" }.mkString("\n") + "\n"
  bad("two's-complement codes read as offset binary (no adc_format)", "the codes look twos-complement, not offset-binary as read (no adc_format line")(
    "explain", rec("tc.csv", head + "sin,cos\n" + pinRows(2000, _ & 4095)))
  bad("offset-binary codes stated as two's complement", "correct the line '# adc_format: offset-binary'")(
    "explain", rec("ob.csv", head + "# adc_format: twos-complement\nsin,cos\n" + pinRows(2000, _ + 2048)))
  "explain" should "read the same two's-complement codes when the file states their format" in {
    val f = rec("tc-stated.csv", head + "# adc_format: twos-complement\nsin,cos\n" + pinRows(2000, _ & 4095))
    val (code, err) = runCli("explain", "--quiet", "--json-dir", (dir / "tc-json").toString, f)
    withClue(s"stderr: $err") { code shouldBe 0 }
  }
  bad("a sample rate of 1e300", "not a sample rate")("explain", rec("fs.csv", "# moire-recording v1\n# sample_rate_hz: 1e300\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a sample rate of NaN", "not a sample rate")("explain", rec("fsnan.csv", "# moire-recording v1\n# sample_rate_hz: NaN\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a sample rate of 4.9e-324 (subnormal)", "not a sample rate")("explain", rec("fstiny.csv", "# moire-recording v1\n# sample_rate_hz: 4.9e-324\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("simulate --motion oscillate at the sample rate", "the oscillation moves the fringe at up to 6.283e+07 Hz")(
    "simulate", "--out", (dir / "osc.csv").toString, "--samples", "100", "--motion", "oscillate:1:1e7")
  bad("simulate --seed 2^53 + 1", "--seed must be a whole number from -9007199254740992 to 9007199254740992")(
    "simulate", "--out", (dir / "seed.csv").toString, "--seed", "9007199254740993")
  bad("simulate --sample-rate-hz 1e-320", "--sample-rate-hz must be from 1e-6 to 1e11 Hz")("simulate", "--out", (dir / "tiny.csv").toString, "--sample-rate-hz", "1e-320")
  bad("a negative sample rate", "not a sample rate")("explain", rec("fsneg.csv", "# moire-recording v1\n# sample_rate_hz: -5\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("adc_bits out of range", "adc_bits")("explain", rec("bits.csv", "# moire-recording v1\n# sample_rate_hz: 1e6\n# adc_bits: 40\nsin,cos\n" + rows(100)))
  bad("an unknown adc_format", "adc_format")("explain", rec("fmt.csv", head + "# adc_format: gray\nsin,cos\n" + rows(100)))
  bad("a header sin,cos,sin", "column 'sin' appears 2 times")("explain", rec("dupcol.csv", head + "sin,cos,sin\n1,2,3\n"))
  bad("a duplicated metadata key", "metadata key 'adc_bits' appears twice")("explain", rec("dupkey.csv", head + "# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a truncated file (samples says more rows)", "metadata samples says '200000' but the file has 2000 data rows")(
    "explain", rec("trunc.csv", head + "# samples: 200000\nsin,cos\n" + rows(2000)))
  bad("a file cut in its last row (samples says one more)", "the last line (2005), left out, has no line end: the file may be cut short")(
    "explain", rec("cutrow.csv", head + "# samples: 2000\nsin,cos\n" + rows(2000).dropRight(3)))
  bad("a file whose one row has no line end", "no data rows after the header but the last line (5), which has no line end")(
    "explain", rec("cutone.csv", head + "sin,cos\n2048,20"))
  "explain" should "leave out a last row without a line end, and say so in the report's notes" in {
    val jdir = dir / "j-cut"
    val (code, err) = runCli("explain", rec("cutlast.csv", head + "sin,cos\n" + rows(2000).dropRight(3)), "--quiet", "--no-rtl", "--json-dir", jdir.toString)
    withClue(err) { code shouldBe 0 }
    val j = ujson.read(os.read(jdir / "cutlast.json"))
    j("samples").num shouldBe 1999
    j("notes").arr.head.str should startWith("line 2004, the last, has no line end: the file may be cut short")
  }
  bad("a header without cos", "header must name columns sin and cos")("explain", rec("nocos.csv", head + "sin,x\n1,2\n"))
  bad("a ragged row", "1 cells, the header has 2")("explain", rec("ragged.csv", head + "sin,cos\n1,2\n3\n"))
  bad("a code above the ADC range", "outside the 12-bit ADC range")("explain", rec("range.csv", head + "sin,cos\n5000,2\n"))
  bad("a negative code", "outside the 12-bit ADC range")("explain", rec("neg.csv", head + "sin,cos\n-1,2\n"))
  bad("a code that is not an integer", "is not an integer ADC code")("explain", rec("frac.csv", head + "sin,cos\n1.5,2\n"))
  bad("NaN in an extra column", "is not a finite number")("explain", rec("nan.csv", head + "sin,cos,ref_deg\n1,2,NaN\n"))
  bad("1e400 in an extra column", "is not a finite number")("explain", rec("inf.csv", head + "sin,cos,ref_deg\n1,2,1e400\n"))
  bad("Infinity in an extra column", "is not a finite number")("explain", rec("inf2.csv", head + "sin,cos,ref_deg\n1,2,-Infinity\n"))
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
  bad("a --model that is a JSON list", "the model must be a JSON object")("explain", good.toString, "--quiet", "--model", rec("list.json", "[1]"))
  bad("a --model whose effects are no list", "effects must be a list")("explain", good.toString, "--quiet", "--model", rec("eff5.json", """{"effects": 5}"""))
  bad("calibration metadata harmonics beyond what 36 points support", "metadata harmonics '100' must be an integer in 0..16")(
    "explain", rec("calh.csv", "# moire-calibration v1\n# harmonics: 100\n" + calRows), "--quiet")

  behavior of "simulate"
  private val existing = dir / "existing.csv"
  os.write.over(existing, "keep me\n")
  private def sim(args: String*): Seq[String] = Seq("simulate", "--out", existing.toString) ++ args
  bad("--phase-error-deg NaN", "--phase-error-deg must be a finite number", Seq(existing))(sim("--phase-error-deg", "NaN"): _*)
  bad("--noise Infinity", "--noise must be a finite number", Seq(existing))(sim("--noise", "Infinity"): _*)
  bad("--noise -1", "--noise must be 0 or more", Seq(existing))(sim("--noise", "-1"): _*)
  bad("--gain-sin Infinity", "--gain-sin must be a finite number", Seq(existing))(sim("--gain-sin", "Infinity"): _*)
  bad("--sample-rate-hz Infinity", "--sample-rate-hz must be a finite number", Seq(existing))(sim("--sample-rate-hz", "Infinity"): _*)
  bad("--sample-rate-hz 0", "--sample-rate-hz must be from 1e-6", Seq(existing))(sim("--sample-rate-hz", "0"): _*)
  bad("--samples 0", "--samples must be at least 1", Seq(existing))(sim("--samples", "0"): _*)
  bad("--samples in Arabic-Indic digits", "--samples", Seq(existing))(sim("--samples", "\u0661\u0662"): _*)
  bad("--amplitude 0", "--amplitude must be above 0", Seq(existing))(sim("--amplitude", "0"): _*)
  // a fringe faster than half the sample rate: the samples would alias (the record would not be the motion asked for)
  bad("a motion above the Nyquist frequency", "the samples alias", Seq(existing))(sim("--samples", "2000", "--motion", "constant:1e300"): _*)
  bad("a motion at 0.6 periods per sample", "0.6000 periods between samples", Seq(existing))(sim("--samples", "2000", "--sample-rate-hz", "1000000", "--motion", "constant:600000"): _*)
  bad("a warm-up's gain step of -1", "gain_sin_step_rel must be above -1", Seq(existing))(
    sim("--effect", "warmup:gain_sin_step_rel=-1,time_constant_s=0.001"): _*)

  "simulate" should "say when the signal exceeds the converter's range" in {
    val out = dir / "rails.csv"
    val (code, outText, err) = CliInProcess.runCliOut("simulate", "--out", out.toString, "--samples", "2000", "--amplitude", "1e308")
    withClue(err) { code shouldBe 0 }
    outText should include("of the sin samples and")
    outText should include("at the ADC's end codes")
  }

  "a command that fails" should "leave no empty output folder behind, and keep one that holds files" in {
    val fresh = dir / "fresh" / "json"; val kept = dir / "kept"; os.makeDir.all(kept); os.write.over(kept / "a.txt", "a")
    val (code, err) = runCli("explain", rec("text2.csv", "hello\n"), "--json-dir", fresh.toString, "--plots", (kept / "p").toString)
    withClue(err) { code shouldBe 2 }
    os.exists(dir / "fresh") shouldBe false
    os.exists(kept / "p") shouldBe false
    os.read(kept / "a.txt") shouldBe "a"
  }
  bad("--offset-cos NaN", "--offset-cos must be a finite number", Seq(existing))(sim("--offset-cos", "NaN"): _*)
  bad("an unknown effect", "'wobble' is not an effect", Seq(existing))(sim("--effect", "wobble:x=1"): _*)
  bad("an unknown ADC format", "--adc", Seq(existing))(sim("--adc", "gray"): _*)
  bad("an output through a file", "is a file, not a folder", Seq(good))("simulate", "--out", (good / "x.csv").toString, "--samples", "100")

  // a --model file's numbers as the options' (the values simulate would write, and explain then refuse)
  private def simModel(name: String, json: String): Seq[String] = sim("--model", rec(name, json))
  bad("a --model sample_rate_hz 1e300", "sample_rate_hz must be from 1e-6 to 1e11 Hz", Seq(existing))(simModel("fs.json", """{"sample_rate_hz": 1e300}"""): _*)
  bad("a --model lines_per_rev 0", "lines_per_rev must be a whole number of grating lines", Seq(existing))(simModel("lpr.json", """{"lines_per_rev": 0}"""): _*)
  bad("a --model samples 100.5", "samples must be a whole number", Seq(existing))(simModel("n.json", """{"samples": 100.5}"""): _*)
  bad("a --model noise_rms -1", "noise_rms must be 0 or more", Seq(existing))(simModel("nz.json", """{"noise_rms": -1}"""): _*)
  bad("a --model with a misspelled key", "unknown key 'amplitud'", Seq(existing))(simModel("typo.json", """{"amplitud": 0.1}"""): _*)
  bad("a --model seed of 2^63 (was 'not valid JSON' with the digits)", "seed must be a whole number (up to 9007199254740992), got 9.223372036854776E18", Seq(existing))(
    simModel("seed63.json", """{"seed": 9223372036854775808}"""): _*)
  bad("a --model with a byte-order mark whose values are wrong (the mark was refused as 'not valid JSON')", "bom.json: amplitude must be above 0", Seq(existing))(
    simModel("bom.json", "\uFEFF{\"amplitude\": -1}"): _*)
  bad("a --model adc that is a number (was passed over for offset-binary)", "adc must be a name (offset-binary or twos-complement), got 5", Seq(existing))(
    simModel("adc5.json", """{"adc": 5}"""): _*)

  bad("--motion constant:NaN", "--motion 'constant:NaN'", Seq(existing))(sim("--motion", "constant:NaN"): _*)
  bad("--lines-per-rev -3", "--lines-per-rev must be a whole number of grating lines", Seq(existing))(sim("--lines-per-rev", "-3"): _*)
  bad("an effect parameter NaN", "order 'NaN' is not a finite number", Seq(existing))(sim("--effect", "harmonic:order=NaN"): _*)
  bad("--adc-bits 99", "bits must be within 4..24", Seq(existing))(sim("--adc-bits", "99"): _*)
  // effects and motions that make no sense (each exited 0 before): (what, the message, --effect)
  for ((kind, expect, effect) <- Seq(
    ("adc_bit_fault stuck_at=2", "--effect adc_bit_fault: stuck_at must be 0 or 1, got 2", "adc_bit_fault:bit=3,stuck_at=2,channel=sin"),
    ("adc_bit_fault without stuck_at or bridged_to", "adc_bit_fault changes nothing without stuck_at or bridged_to: give one, e.g. adc_bit_fault:bit=3,stuck_at=1,channel=cos", "adc_bit_fault:bit=3,channel=sin"),
    ("adc_bit_fault with both stuck_at and bridged_to", "give stuck_at or bridged_to, not both", "adc_bit_fault:bit=3,stuck_at=1,bridged_to=4,channel=sin"),
    ("harmonic without keys", "harmonic changes nothing without amplitude_rel: give it", "harmonic"),
    ("harmonic order 2.5", "--effect harmonic: order must be a whole number from 2 to 100, got 2.5", "harmonic:order=2.5,amplitude_rel=0.01"),
    ("a key given twice", "--effect harmonic: key 'order' given twice", "harmonic:order=3,order=4,amplitude_rel=0.01"),
    ("a negative jitter", "--effect jitter: jitter_s must be from 0 to 1e-3 s rms (1 ms), got -1", "jitter:jitter_s=-1"),
    ("a negative phase noise", "--effect phase_noise: phase_noise_rad must be from 0 to 6.283 rad rms", "phase_noise:phase_noise_rad=-1"),
    ("clipping high below low", "--effect clipping: high_fs must be from -1 to 1 full scale, got -5", "clipping:high_fs=-5,low_fs=5"),
    ("clipping high under low within full scale", "--effect clipping: high_fs (-0.5) must be above low_fs (0.5)", "clipping:high_fs=-0.5,low_fs=0.5"),
    ("a skew of 1e300 s", "--effect channel_skew: skew_s must be from -1e-3 to 1e-3 s (1 ms either way), got 1.0E300", "channel_skew:skew_s=1e300"),
    ("a cut-off of 1e-300 Hz", "--effect bandwidth: cutoff_hz must be from 1 Hz to 1e12 Hz", "bandwidth:cutoff_hz=1e-300")
  )) bad(kind, expect, Seq(existing))(sim("--samples", "2000", "--effect", effect): _*)
  bad("a negative jitter in a --model", "neg.json: jitter: jitter_s must be from 0 to 1e-3 s rms", Seq(existing))(
    sim("--model", rec("neg.json", """{"effects": [{"effect": "jitter", "jitter_s": -1}]}""")): _*)
  bad("--motion constant:1:2", "--motion 'constant:1:2': too many values, expected constant:HZ", Seq(existing))(sim("--motion", "constant:1:2"): _*)
  bad("--motion oscillate:10:1000:5", "too many values, expected oscillate:PERIODS:RATE_HZ", Seq(existing))(sim("--motion", "oscillate:10:1000:5"): _*)
  bad("--motion constant:100000:", "--motion 'constant:100000:': too many values, expected constant:HZ", Seq(existing))(sim("--motion", "constant:100000:"): _*)
  bad("--motion oscillate:-1:1000", "--motion 'oscillate:-1:1000': PERIODS (the peak excursion) must be > 0, got -1", Seq(existing))(
    sim("--motion", "oscillate:-1:1000"): _*)
  bad("a model's oscillation at a negative rate", "motion: RATE_HZ must be > 0", Seq(existing))(
    sim("--model", rec("osc.json", """{"motion": {"kind": "oscillate", "periods_peak": 10, "rate_hz": -5}}""")): _*)
  "simulate" should "still take effects whose defaults act, and a harmonic in explain's --model without its amplitude" in {
    val (code, err) = runCli("simulate", "--out", (dir / "defaults.csv").toString, "--samples", "2000", "--effect", "bandwidth:cutoff_hz=4e5", "--effect", "clipping:high_fs=0.8,channel=sin",
      "--effect", "adc_bit_fault:bit=5,bridged_to=6,channel=cos")
    withClue(err) { code shouldBe 0 }
    val m = rec("harm.json", """{"effects": [{"effect": "harmonic", "order": 3, "channel": "sin"}]}""")
    val (c2, e2) = runCli("explain", good.toString, "--quiet", "--no-rtl", "--model", m)
    withClue(e2) { c2 shouldBe 0 }
  }
  "explain" should "say in one line that a recording does not fit the heap, with options that give more" in {
    val big = dir / "big.csv"
    runCli("simulate", "--out", big.toString, "--samples", "600000")._1 shouldBe 0
    val (code, _, err) = CliProcess.runWith(Seq("-Xmx40m"))("explain", big.toString, "--quiet", "--no-rtl")
    withClue(err) {
      code shouldBe 2
      err.trim shouldBe "moire: out of memory in a heap of 40 MB; give the JVM more (JAVA_OPTS=-Xmx8g moire ..., or moire -J-Xmx8g ...) or a shorter recording"
    }
  }
  bad("a --model that is not JSON", "not valid JSON", Seq(existing))(sim("--model", rec("nj.json", "not json")): _*)

  behavior of "calibrate"
  private val calOut = dir / "cal-out"
  it should "read a calibration file with a byte-order mark and CRLF line ends" in {
    val f = rec("calbom.csv", "\uFEFF" + ("# moire-calibration v1\n" + calRows).replace("\n", "\r\n"))
    val (code, err) = runCli("calibrate", "--input", f, "--out", calOut.toString)
    withClue(err) { code shouldBe 0 }
  }
  private def calib(args: String*): Seq[String] = Seq("calibrate", "--input", cal.toString, "--out", calOut.toString) ++ args
  bad("a missing input", "no such file")("calibrate", "--input", (dir / "none.csv").toString, "--out", calOut.toString)
  private val calNotes = mine("cal-notes", "calnotes.registers.txt", "my own notes\n")
  bad("a user's notes under the register listing's name", "holds text, and this command writes a moire-harmonic-registers file", Seq(calNotes))(
    "calibrate", "--input", rec("calnotes.csv", "# moire-calibration v1\n" + calRows), "--out", (dir / "cal-notes").toString)
  bad("a duplicated metadata key", "metadata key 'table' appears twice")(
    "calibrate", "--input", rec("caldup.csv", "# moire-calibration v1\n# table: a\n# table: b\n" + calRows), "--out", calOut.toString)
  bad("an error of NaN", "error_arcsec is NaN")("calibrate", "--input", rec("calnan.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n0,1\n10,NaN\n"))
  bad("an angle outside [0, 360]", "angle_deg 400.0 is outside [0, 360]")("calibrate", "--input", rec("cal400.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n400,1\n"))
  bad("a repeated angle", "angle 0.0 repeats line 3")("calibrate", "--input", rec("calrep.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n0,1\n0,2\n"))
  bad("--harmonics 0", "--harmonics (m) must be in 1..32, got 0")(calib("--harmonics", "0"): _*)
  bad("--max-order 100 on 36 points", "36 points cannot determine 100 harmonics")(calib("--max-order", "100"): _*)
  bad("--max-order 0", "--max-order must be at least 1, got 0")(calib("--max-order", "0"): _*)
  bad("--max-order -1 (not the default)", "--max-order must be at least 1 (or left out for the default), got -1")(calib("--max-order", "-1"): _*)
  bad("an error of 1e300 arcsec", "is beyond a whole turn")("calibrate", "--input", rec("calhuge.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n0,1e300\n10,1\n20,2\n"))
  bad("harmonics beyond the coefficient range, naming the file", "calbig.csv: c_k = ")("calibrate", "--input",
    rec("calbig.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n" + (0 until 360 by 10).map(a => s"$a,${1e5 * math.sin(math.toRadians(a))}").mkString("\n") + "\n"),
    "--out", calOut.toString)
  bad("--lines 1000", "--lines must be a power of two")(calib("--lines", "1000"): _*)
  bad("--subdivision 3", "--subdivision must be a power of two")(calib("--subdivision", "3"): _*)
  bad("an output folder that is a file", "is a file, not a folder", Seq(aFile))("calibrate", "--input", cal.toString, "--out", aFile.toString)

  behavior of "record (options, no board needed)"
  private val port = (dir / "no-such-port").toString
  private def recd(args: String*): Seq[String] = Seq("record", "--port", port, "--out", (dir / "r.csv").toString) ++ args
  bad("no --seconds and no --burst", "give --seconds S")(recd(): _*)
  bad("--seconds NaN", "--seconds must be in (0, 86400], got NaN")(recd("--seconds", "NaN"): _*)
  bad("--baud 5", "--baud must be in 300..12000000, got 5")(recd("--seconds", "1", "--baud", "5"): _*)
  bad("--adc-clock-hz Infinity", "--adc-clock-hz must be from 1000 to 200000000 Hz (an ADC clock a board runs), got Infinity")(recd("--seconds", "1", "--adc-clock-hz", "Infinity"): _*)
  bad("--listen-only without the board's figures", "--listen-only sends no commands")(recd("--seconds", "1", "--listen-only"): _*)
  bad("--timeout-ms 0", "--timeout-ms must be in 10..60000, got 0")(recd("--seconds", "1", "--timeout-ms", "0"): _*)
  bad("--burst 0", "--burst must be in 1..")(recd("--burst", "0"): _*)
  bad("an unknown burst trigger", "--trigger 'wobble'")(recd("--burst", "100", "--trigger", "wobble"): _*)
  bad("an output through a file (before the port is opened)", "is a file, not a folder", Seq(aFile))(
    "record", "--port", port, "--seconds", "1", "--out", (aFile / "r.csv").toString)
  bad("a serial port that does not exist", "no such serial port")(recd("--seconds", "1"): _*)
  bad("no --port", "Missing argument: --port")("record", "--seconds", "1", "--out", (dir / "r.csv").toString)
  // the parser stops at a word it does not know: the options after it are not missing, the unknown one is named alone
  bad("an unknown option before a required one", "Unknown argument: --fs (see --help)", Seq(dir / "s.csv"))(
    "simulate", "--fs", "0", "--out", (dir / "s.csv").toString)
  bad("an unknown option with its value", "Unknown argument: --target (see --help)")("design", "--target", "-1")

  behavior of "board-reg"
  private def reg(args: String*): Seq[String] = Seq("board-reg", "--port", port) ++ args
  bad("a write without a value", "must be NAME=VALUE")(reg("--write", "decimation"): _*)
  bad("a write to an unknown register", "register 'nosuch' is unknown")(reg("--write", "nosuch=1"): _*)
  bad("a write to a read-only register", "id is read-only")(reg("--write", "id=1"): _*)
  bad("a read of an unknown register", "register 'nosuch' is unknown")(reg("--read", "nosuch"): _*)
  bad("a missing coefficient file", "no such file")(reg("--coefficients", (dir / "none.json").toString): _*)
  bad("a coefficient entry that is no object", "registers[0]: expected an object")(
    reg("--coefficients", rec("badreg.json", """{"format": "moire-harmonic-coefficients v1", "registers": [5]}""")): _*)
  bad("--timeout-ms -4", "--timeout-ms must be in 10..60000, got -4")(reg("--timeout-ms", "-4"): _*)
  bad("a coefficient above the harmonic window (0xe0 is burst_control)", "window address 208 is outside 0..207")(
    reg("--coefficients", rec("highreg.txt", "00 00000001\nd0 00000001\n")): _*)
  bad("a coefficient address written twice", "window address 0 is written twice")(
    reg("--coefficients", rec("tworeg.txt", "00 00000001\n00 00000002\n")): _*)
  bad("a saved file with decimation 0", "registers.decimation must be in 1..16777216, got 0")(
    reg("--load", rec("dec0.json", """{"format": "moire-board-registers v1", "model": {"id": 1, "version": 1, "adc_clock_hz": 50000000,
      "adc_format": 0, "counts_per_period": 4096, "frame_records": 8}, "registers": {"decimation": 0}}""")): _*)

  behavior of "emit"
  private val emitOut = dir / "emit"
  bad("--angle-width -5", "--angle-width must be in 8..48 (or left out for the default), got -5")("emit", "--angle-width", "-5", "--out", emitOut.toString)
  bad("--frac-bits -7", "--frac-bits must be in 1..17")("emit", "--frac-bits", "-7", "--out", emitOut.toString)
  for (o <- Seq("--frac-bits", "--angle-width", "--angle-guard-bits"))
    bad(s"$o -1 (not the default)", s"$o must be in")("emit", o, "-1", "--out", emitOut.toString)
  for (o <- Seq("--cordic-width", "--phase-bits"))
    bad(s"emit-subdiv $o -1 (not the default)", s"$o must be a positive width")("emit-subdiv", o, "-1", "--out", emitOut.toString)
  bad("--iterations 99", "--iterations must be in 4..40, got 99")("emit", "--iterations", "99", "--out", emitOut.toString)
  bad("--width NaN", "--width: 'NaN' is not a valid int")("emit", "--width", "NaN", "--out", emitOut.toString)
  bad("an output folder that is a file (before elaboration)", "is a file, not a folder", Seq(aFile))("emit", "--out", aFile.toString)

  behavior of "board"
  private val boardOut = dir / "board"
  bad("--clock-hz 12345", "--clock-hz must be in 1000000..200000000, got 12345")("board", "de2-115", "--clock-hz", "12345", "--out", boardOut.toString)
  bad("an unknown --design", "--design: 'foo' is not a board design")("board", "ulx3s", "--design", "foo", "--out", boardOut.toString)
  bad("--decimation 0", "--decimation must be in 1..16777216, got 0")("board", "de2-115", "--decimation", "0", "--out", boardOut.toString)
  bad("--lines 1000 (compensated)", "--lines (fringe periods per turn) must be a power of two")(
    "board", "de2-115", "--design", "compensated", "--lines", "1000", "--out", boardOut.toString)
  bad("--harmonics 99 (compensated)", "--harmonics (m) must be in 1..32, got 99")(
    "board", "ulx3s", "--design", "compensated", "--harmonics", "99", "--out", boardOut.toString)
  bad("an output folder that is a file", "is a file, not a folder", Seq(aFile))("board", "de2-115", "--out", aFile.toString)
  bad("an unknown board", "board 'kv260' is unknown")("board", "kv260", "--out", boardOut.toString)

  behavior of "cost (fails before yosys runs)"
  bad("an unknown --design", "--design: 'nosuch' is not a design")("cost", "--design", "nosuch")
  bad("--angle-width -5", "--angle-width must be in 8..48")("cost", "--angle-width", "-5")
  bad("a --json path through a file", "is a file, not a folder", Seq(aFile))("cost", "--json", (aFile / "x.json").toString)
  bad("a sweep folder that is a file", "is a file, not a folder", Seq(aFile))("cost", "--sweep", "--out", aFile.toString)

  behavior of "timing (fails before any tool runs)"
  bad("an unknown --design", "--design: 'nosuch' is not a design")("timing", "--design", "nosuch")
  bad("--speeds 5", "--speeds: '5' is not an ECP5 speed grade")("timing", "--design", "cordic", "--speeds", "5")
  bad("--target-mhz NaN", "--target-mhz must be above 0 and below 1000 MHz, got NaN")("timing", "--design", "cordic", "--target-mhz", "NaN")
  bad("--target-mhz Infinity", "--target-mhz must be above 0 and below 1000 MHz, got Infinity")("timing", "--design", "cordic", "--target-mhz", "Infinity")
  bad("--target-mhz -3", "--target-mhz must be above 0 and below 1000 MHz, got -3.0")("timing", "--design", "cordic", "--target-mhz", "-3")
  bad("--target-mhz 1000", "--target-mhz must be above 0 and below 1000 MHz, got 1000.0")("timing", "--design", "cordic", "--target-mhz", "1000")
  bad("--target-mhz 0", "--target-mhz must be above 0 and below 1000 MHz, got 0.0")("timing", "--design", "cordic", "--target-mhz", "0")
  bad("a --json path through a file", "is a file, not a folder", Seq(aFile))("timing", "--design", "cordic", "--json", (aFile / "t.json").toString)
  bad("a --cache that is a file", "is a file, not a folder", Seq(aFile))("timing", "--design", "cordic", "--cache", aFile.toString)

  behavior of "replay"
  bad("an output that is its input", "is an input of this command", Seq(good))("replay", good.toString, "--out", good.toString)
  bad("a missing recording", "no such file")("replay", (dir / "none.csv").toString)
  bad("two's-complement codes read as offset binary", "the codes look twos-complement, not offset-binary as read", Seq(dir / "tc-replay-out.csv"))(
    "replay", rec("tc-replay.csv", head + "sin,cos\n" + pinRows(2000, _ & 4095)), "--out", (dir / "tc-replay-out.csv").toString)
  bad("an unknown --design", "--design: 'nosuch' is not a replayable design")("replay", good.toString, "--design", "nosuch")
  bad("--counts 3", "--counts (M) must be a power of two")("replay", good.toString, "--counts", "3")
  // it blamed --input-bits and --counts, which the user had not typed (another tool's fuzz sweep, F20)
  bad("a recording of 17-bit codes", "the recording's metadata adc_bits '17' is not one the subdivider takes (must be in 4..16, got 17); give --input-bits")(
    "replay", rec("b17-replay.csv", "# moire-recording v1\n# sample_rate_hz: 1000000\n# adc_bits: 17\nsin,cos\n" + rows(100)))
  bad("a recording whose counts_per_period is 1000", "the recording's metadata counts_per_period '1000' is not one the subdivider takes")(
    "replay", rec("m1000-replay.csv", head + "# counts_per_period: 1000\nsin,cos\n" + rows(100)))
  bad("--out=FILE onto a text file, before the run", "holds text, and this command writes a moire-replay file")(
    "replay", s"--out=${rec("notes-replay.txt", "my notes\n")}", good.toString)
  bad("an unknown option last", "Unknown argument: --bogus (see replay --help)")(
    "replay", good.toString, "--out", (dir / "bogus.csv").toString, "--quiet", "--bogus")
  bad("an unknown option with a value", "Unknown argument: --bogus")("replay", good.toString, "--bogus", "3")

  behavior of "the launcher"
  bad("--version with an argument", "--version takes no arguments, got 'extra'")("--version", "extra")
  bad("--help with an argument", "--help takes no arguments, got 'extra' (moire help COMMAND for a command's help)")("--help", "extra")
  bad("an output through a file", "is a file, not a folder", Seq(aFile))("replay", good.toString, "--out", (aFile / "x.csv").toString)

  // no fringe to explain: both inputs floating a few LSB about mid-scale (the fit's phase would follow the noise)
  private val rnd = new scala.util.Random(1)
  bad("a recording of floating inputs", "no fringe: the fitted amplitude")("explain", rec("floating.csv", head + "sin,cos\n" +
    (0 until 5000).map(_ => s"${2048 + rnd.nextInt(7) - 3},${2048 + rnd.nextInt(7) - 3}").mkString("\n") + "\n"), "--quiet", "--no-rtl")
  // a head that creeps over 0.3 of a period draws an arc: no ellipse to fit (its offsets came out 0.37 full scale)
  bad("a recording of a head creeping over part of a period", "too short an arc: the read head moved over less than one fringe period")("explain", rec("creep.csv", head + "sin,cos\n" +
    (0 until 20000).map { i => val a = 2 * math.Pi * (0.1 + 0.3 * i / 20000.0)
      s"${2048 + math.round(1640 * math.sin(a) + rnd.nextGaussian()).toInt},${2048 + math.round(1640 * math.cos(a) + rnd.nextGaussian()).toInt}" }.mkString("\n") + "\n"),
    "--quiet", "--no-rtl")
  // another kind of file is not written over: notes by a recording, a model's JSON by an HTML report, notes by JSON
  private val notes = dir / "notes.txt"
  os.write.over(notes, "my notes\n")
  private val modelJson = dir / "mine.json"
  os.write.over(modelJson, "{\"a\": 1}\n")
  bad("a recording over a text file", "holds text, and this command writes a moire recording", Seq(notes))(
    "simulate", "--out", notes.toString, "--samples", "1000")
  bad("an HTML report over a JSON file", "holds JSON, and this command writes an explain report (HTML)", Seq(modelJson))(
    "explain", "--quiet", "--no-rtl", "--html", modelJson.toString, good.toString)
  // text a user wrote is not moire's own text: a replay's CSV (`# moire-replay v1`) does not replace notes
  bad("a replay over a text file", "holds text, and this command writes a moire-replay file", Seq(notes))(
    "replay", good.toString, "--quiet", "--out", notes.toString)
  private val textAsJson = dir / "jnotes.json"
  os.write.over(textAsJson, "my notes\n")
  bad("a JSON report over a text file", "holds text, and this command writes an explain report (JSON)", Seq(textAsJson))(
    "explain", "--quiet", "--no-rtl", "--json-dir", dir.toString, rec("jnotes.csv", os.read(good)))
  // a channel on an effect that acts on both: it was recorded in the model and ignored
  bad("channel=sin on an effect that acts on both channels", "--effect drift: channel=sin does not apply")(
    "simulate", "--out", (dir / "ch.csv").toString, "--effect", "drift:offset_sin_per_s=0.1,channel=sin")
  bad("an eccentricity of five reading radii", "eccentricity_rel must be from 0 to 0.1")(
    "simulate", "--out", (dir / "ecc.csv").toString, "--lines-per-rev", "1000", "--effect", "eccentricity:eccentricity_rel=5")
  bad("an angle harmonic of order 0", "order must be a whole number from 1 to 100")(
    "simulate", "--out", (dir / "ah.csv").toString, "--lines-per-rev", "1000", "--effect", "angle_harmonic:order=0,amplitude_arcsec=5")
  bad("a fractional number of grating lines", "must be a whole number of grating lines")(
    "simulate", "--out", (dir / "lpr.csv").toString, "--lines-per-rev", "1.5")
  bad("a gain drifting through zero", "drift gain_sin_per_s = -1000000 takes the gain through zero")(
    "simulate", "--out", (dir / "dz.csv").toString, "--effect", "drift:gain_sin_per_s=-1e6")
  bad("a recording's name taken as --subdiv's value", "--subdiv takes the subdivider's emit-subdiv options as one quoted word")(
    "explain", "--subdiv", good.toString)
  bad("a metadata error named at its own line", "bits.csv:3: metadata adc_bits '0'")(
    "explain", rec("bits.csv", "# moire-recording v1\n# sample_rate_hz: 1000000\n# adc_bits: 0\n# source: x\nsin,cos\n" + rows(100)))
  bad("an empty entry in an effect's list", "--effect harmonic: an empty entry in 'order=3,,amplitude_rel=0.01'")(
    "simulate", "--out", (dir / "ee.csv").toString, "--effect", "harmonic:order=3,,amplitude_rel=0.01")
  bad("a sine's error of 5 full scale", "--max-error must be below half the output's range (1 full scale), which a constant output meets; got 5.0")(
    "design", "--function", "sin", "--max-error", "5")
  bad("an angle's error of 10 radians", "--max-error must be below half the output's range (pi radians), which a constant output meets; got 10.0")(
    "design", "--function", "atan2", "--max-error", "10")
  bad("an empty record --out", "an output file's name is empty")("record", "--port", "/dev/nonexistent-tty", "--seconds", "1", "--out", "")
  bad("an empty --cache", "--cache: the folder's name is empty")("timing", "--design", "counter", "--cache", "")
  bad("a speed grade given twice", "--speeds: 6 is given twice")("timing", "--design", "counter", "--speeds", "6,6")
  bad("a sweep's iteration count given twice", "--sweep-iterations: 8 is given twice")(
    "cost", "--sweep", "--sweep-iterations", "8,8", "--out", (dir / "sw").toString)
  // a head standing still off mid-scale (sin near its middle, cos near its bottom): no fringe, said as that, not as the
  // cos input unconnected
  bad("a recording of a head standing still", "no fringe: the signals stand still (sin at 388")("explain", rec("still.csv", head + "sin,cos\n" +
    (0 until 5000).map(_ => s"${2436 + rnd.nextInt(7) - 3},${395 + rnd.nextInt(5) - 2}").mkString("\n") + "\n"), "--quiet", "--no-rtl")
  // overdriven three times: 80 % of the samples at the end codes, the fringe seen only where it crosses zero; at 10
  // samples a period it slews by most of the range there, which is no sign of the other ADC format
  bad("a recording mostly at the end codes", "the sin channel is at the ADC's end codes on")("explain", rec("overdriven.csv", head + "sin,cos\n" +
    (0 until 5000).map { i => val a = 2 * math.Pi * (i + 0.5) / 10.0; def c(x: Double) = math.max(0, math.min(4095, 2048 + (3 * 2047 * x).round))
      s"${c(math.sin(a))},${c(math.cos(a))}" }.mkString("\n") + "\n"), "--quiet", "--no-rtl")

  // plain decimal is the digits 0-9: Java would read other scripts' digits as numbers
  bad("a code in full-width digits", "is not an integer ADC code")("explain", rec("wide.csv", head + "sin,cos\n" + rows(100) + "\uFF12\uFF10\uFF15\uFF10,3000\n" + rows(100)))
  bad("adc_bits in Arabic-Indic digits", "metadata adc_bits")("explain", rec("arabic.csv", "# moire-recording v1\n# sample_rate_hz: 1000000\n# adc_bits: \u0661\u0662\nsin,cos\n" + rows(200)))
  bad("metadata samples that is no number", "metadata samples 'abc' is not a whole number of rows")("explain", rec("nsamp.csv", head + "# samples: abc\nsin,cos\n" + rows(200)))

  // 77 records lost on the link: the rows after them are 77 samples later than their row numbers say
  // each was explained as if it were sound (another tool's fuzz sweep, F20)
  private def indexed(name: String, meta: String, index: Int => String) =
    rec(name, head + meta + "sin,cos,sample_index\n" + rows(2000).linesIterator.zipWithIndex.map { case (r, i) => s"$r,${index(i)}" }.mkString("\n") + "\n")
  bad("a recording of decimation 0", "metadata decimation '0' is not a whole number from 1")(
    "explain", "--quiet", "--no-rtl", indexed("idx-dec0.csv", "# decimation: 0\n", i => (100 * i).toString))
  bad("a recording whose decimation is not its index's step", "sample_index steps by 100 from row to row, and the metadata says decimation 7")(
    "explain", "--quiet", "--no-rtl", indexed("idx-dec7.csv", "# decimation: 7\n", i => (100 * i).toString))
  bad("a recording whose sample_index runs backwards", "sample_index steps from 400000 to 399900 (data rows 1 and 2)")(
    "explain", "--quiet", "--no-rtl", indexed("idx-back.csv", "", i => (400000 - 100 * i).toString))
  bad("a recording whose sample_index holds fractions", "sample_index 0.5 (data row 1) is no count of ADC samples")(
    "explain", "--quiet", "--no-rtl", indexed("idx-frac.csv", "", i => s"${i}.5"))
  bad("a recording whose sample_index skips records", "sample_index steps by 78 from 999 to 1077 (data row 1001)")("explain", rec("gap.csv",
    head + "sin,cos,sample_index\n" + rows(2000).linesIterator.zipWithIndex.collect { case (r, i) if i < 1000 || i >= 1077 => s"$r,$i" }.mkString("\n") + "\n"), "--quiet", "--no-rtl")

  // a stray word before valid options: the word is named, not the options after it
  bad("a stray word among emit's options", "Unexpected word 'extra'", Seq(dir / "o1"))("emit", "extra", "--out", (dir / "o1").toString)
  bad("a board named twice", "Unexpected word 'de2-115'", Seq(dir / "b1"))("board", "de2-115", "de2-115", "--out", (dir / "b1").toString)

  bad("record's burst trigger without --burst", "--trigger and --pre apply to a burst")("record", "--port", "/dev/null", "--out", (dir / "r.csv").toString,
    "--seconds", "1", "--trigger", "z")

  behavior of "cost and timing"
  // an option the command would ignore is refused: the figures would be for a configuration nobody asked for
  bad("a sweep width out of range", "--sweep-widths: 7 is not in 8..48")("cost", "--sweep", "--sweep-widths", "7")
  bad("sweep iterations of 0", "--sweep-iterations: 0 is not in 4..40")("cost", "--sweep", "--sweep-iterations", "0")
  bad("CORDIC options with another design", "apply to --design cordic only, not subdiv")("cost", "--design", "subdiv", "--iterations", "12")
  bad("sweep options without --sweep", "--spread applies to --sweep only")("cost", "--spread", "2")
  bad("a design with --sweep", "--design, --keep and the CORDIC options")("cost", "--sweep", "--design", "subdiv")
  bad("timing's CORDIC options with another design", "apply to --design cordic only, not quadcomp")("timing", "--design", "quadcomp", "--width", "12")

  behavior of "fuzzed inputs that passed (2026-11-30)"
  bad("a coarse_quantization of 5.5 bits", "--effect coarse_quantization: effective_bits must be a whole number from 4 to 24", Seq(existing))(
    sim("--samples", "1000", "--effect", "coarse_quantization:effective_bits=5.5"): _*)
  bad("a jitter of 1 ms at 10 MS/s", "jitter jitter_s must be at most a quarter of the sample period", Seq(existing))(
    sim("--samples", "1000", "--effect", "jitter:jitter_s=1e-3"): _*)
  bad("a skew longer than the record", "channel_skew |skew_s| must be below the record's length", Seq(existing))(
    sim("--samples", "2000", "--effect", "channel_skew:skew_s=1e-3"): _*)
  bad("a gain of 0", "--gain-sin must be above 0", Seq(existing))(sim("--samples", "1000", "--gain-sin", "0"): _*)
  bad("a phase error of 90 degree", "--phase-error-deg must be between -90 and 90 degree", Seq(existing))(sim("--samples", "1000", "--phase-error-deg", "90"): _*)
  bad("a model file with a key given twice", "dup.json: key 'order' is given twice in one object", Seq(existing))(
    sim("--model", rec("dup.json", """{"effects": [{"effect": "harmonic", "order": 3, "amplitude_rel": 0.01, "channel": "sin", "order": 5}]}""")): _*)
  bad("a model file with a top-level key given twice", "dup2.json: key 'amplitude' is given twice in one object", Seq(existing))(
    sim("--model", rec("dup2.json", """{"amplitude": 0.9, "amplitude": 0.5}""")): _*)
  bad("a flag column holding 2", "otr_sin is a flag: 0 or 1, got '2'")("explain", "--no-rtl", "--quiet",
    rec("flag2.csv", head + "sin,cos,otr_sin\n" + rows(2000).linesIterator.zipWithIndex.map { case (r, i) => s"$r,${if (i == 7) 2 else 0}" }.mkString("\n") + "\n"))
  bad("an unknown effect in a model file (named as the file's, not --effect's)", "noeff.json: 'nosuch' is not an effect; allowed:", Seq(existing))(
    sim("--model", rec("noeff.json", """{"effects": [{"effect": "nosuch"}]}""")): _*)
  bad("a board --harmonics for the subdiv design", "--harmonics applies to --design compensated only, not subdiv")(
    "board", "de2-115", "--out", (dir / "bd2").toString, "--harmonics", "8")
  bad("an emit-subdiv --asin-amplitude with atan2", "--asin-amplitude applies to --method asin-double only, not atan2")(
    "emit-subdiv", "--asin-amplitude", "0.5", "--out", (dir / "es").toString)
  bad("a board at 1 baud", "--baud must be in 300..12000000, got 1")("board", "de2-115", "--out", (dir / "bd").toString, "--baud", "1")
  bad("an empty --widths list", "--widths: '' is not an integer list")("bounds", "--widths", ",")
  bad("a --iterations list with a repeat", "--iterations: 8 is given twice")("bounds", "--iterations", "8,8")
  bad("a board-reg decimation of -1", "decimation must be in 1..16777216, got -1")("board-reg", "--port", "/dev/null", "--write", "decimation=-1")
  bad("a monitor --bind that is empty", "--bind: the address is empty")("monitor", "--simulate", "--bind", "")

  // options that do not apply are refused when given at all, at their default value too (the value was never the point)
  bad("a CORDIC option at its default with another design", "apply to --design cordic only, not counter")("cost", "--design", "counter", "--iterations", "16")
  bad("a sweep option at its default without --sweep", "--spread applies to --sweep only")("cost", "--spread", "4")
  bad("a burst trigger at its default without --burst", "--trigger and --pre apply to a burst")(recd("--seconds", "1", "--trigger", "now"): _*)
  bad("the same register written twice", "--write decimation is given 2 times ('decimation=5', 'decimation=6')")(
    "board-reg", "--port", "/dev/null", "--write", "decimation=5", "--write", "decimation=6")
  bad("counts per period that no board counts", "--counts-per-period must be a power of two from 4 to 65536")(recd("--seconds", "1", "--counts-per-period", "1000"): _*)
  bad("a number beyond a double's range", "--amplitude: '1e309' is beyond the range of numbers")(
    "simulate", "--out", (dir / "big.csv").toString, "--amplitude", "1e309")
  bad("a monitor replay with a board's link rate", "--baud applies to a board (--port DEV); a replay plays the file at its own rate")(
    "monitor", "--replay", good.toString, "--baud", "115200")
  bad("a simulated board with a decimation", "--decimation applies to a board (--port DEV)")("monitor", "--simulate", "--decimation", "100")
  // a name the file system takes, whose temporary name (.NAME.tmp-PID-THREAD) it does not: found before the work
  bad("an output name too long for its temporary file", "cannot be written (File name too long)")(
    "simulate", "--out", (dir / ("n" * 245 + ".csv")).toString)
  bad("an output name of 300 characters", "cannot be written (File name too long)")(
    "simulate", "--out", (dir / ("n" * 300 + ".csv")).toString)
  // an option without its value took the next option as its value ("--mode" as emit's folder)
  bad("emit --out followed by another option", "--out needs a value")("emit", "--out", "--mode", "sincos")
  bad("record --port followed by another option", "--port needs a value", Seq(dir / "nv.csv"))(
    "record", "--port", "--seconds", "1", "--out", (dir / "nv.csv").toString)
  bad("monitor --port followed by another option", "--port needs a value")("monitor", "--port", "--baud", "9600")
  bad("board --baud followed by another option", "--baud needs a value")("board", "de2-115", "--baud", "--decimation", "4", "--out", boardOut.toString)
  // each was taken (another tool's fuzz sweep, F20)
  bad("a simulated board of 1000 counts per period", "--counts-per-period must be a power of two from 4 to 65536")(
    "monitor", "--simulate", "--counts-per-period", "1000", "--out", (dir / "mon").toString)
  bad("a grating of 1.5 lines a turn", "--lines-per-rev counts a grating's lines on a turn: a whole number, got 1.5")(
    "monitor", "--simulate", "--lines-per-rev", "1.5", "--out", (dir / "mon").toString)
  bad("board ulx3s at 65 MHz with the default ADC clock", "--clock-hz 65000000: the default --adc-clock-hz 50000000 does not divide it")(
    "board", "ulx3s", "--clock-hz", "65000000", "--out", (dir / "bu").toString)
  private val samplesModel = dir / "samples-model.json"
  os.write.over(samplesModel, """{"samples": 3000, "noise_rms": 0.001}""")
  bad("a model file and an option that set the same thing", "sets noise_rms, and --noise was given too")(
    "simulate", "--out", (dir / "sm.csv").toString, "--model", samplesModel.toString, "--noise", "0.002")

  behavior of "explain-bench"
  bad("--samples with --recording", "with --recording the file's length is taken")("explain-bench", "--recording", good.toString, "--samples", "5")
  bad("--samples 0", "--samples must be in 10000..")("explain-bench", "--samples", "0")
  bad("--runs 0", "--runs must be in 1..10, got 0")("explain-bench", "--runs", "0")
  // the bench's recording is DIR/bench.csv: a file of that name that is no recording is the user's, not replaced
  private val benchDir = dir / "bench"
  os.makeDir.all(benchDir)
  os.write.over(benchDir / "bench.csv", "my notes\n")
  bad("a bench folder holding another bench.csv", "exists and is not a file this command writes", Seq(benchDir / "bench.csv"))(
    "explain-bench", "--samples", "10000", "--out", benchDir.toString)

  behavior of "outputs (never over an input, a link, a pipe or a device)"
  private val model = dir / "m.json"
  os.write.over(model, """{"effects": []}""")
  private val jdir = dir / "j"
  os.makeDir.all(jdir)
  private val jModel = jdir / "good.json"
  os.write.over(jModel, """{"effects": []}""")
  bad("an explain report that would replace the --model", "is an input of this command", Seq(jModel))(
    "explain", good.toString, "--quiet", "--no-rtl", "--json-dir", jdir.toString, "--model", jModel.toString)
  bad("an explain --html that is the recording", "is an input of this command", Seq(good))(
    "explain", good.toString, "--quiet", "--no-rtl", "--html", good.toString)
  bad("an explain --html that is the --model", "is an input of this command", Seq(model))(
    "explain", good.toString, "--quiet", "--no-rtl", "--html", model.toString, "--model", model.toString)
  private val hdir = dir / "h"
  os.makeDir.all(hdir)
  private val hInput = hdir / "good.html"
  os.write.over(hInput, "# moire-recording v1\n")
  bad("an explain --html-dir report that would replace an input", "is an input of this command", Seq(hInput))(
    "explain", good.toString, hInput.toString, "--quiet", "--no-rtl", "--html-dir", hdir.toString)
  private val pdir = dir / "p"
  os.makeDir.all(pdir)
  private val pInput = pdir / "good_residual_time.png" // a recording, oddly named, where a plot of good.csv would go
  os.write.over(pInput, head + "sin,cos\n" + rows(2000))
  bad("an explain --plots folder where a plot would replace an input", "--plots writes good_*.png", Seq(pInput))(
    "explain", good.toString, pInput.toString, "--quiet", "--no-rtl", "--plots", pdir.toString)
  // '-' is standard output to other tools: no file of that name is written in the working folder
  bad("a simulate --out of - (standard output)", "no output to standard output", Seq(os.pwd / "-"))("simulate", "--out", "-", "--samples", "100")
  bad("a replay --out of -", "no output to standard output", Seq(os.pwd / "-"))("replay", good.toString, "--out", "-")
  bad("an explain --html of -", "no output to standard output", Seq(os.pwd / "-"))("explain", good.toString, "--quiet", "--no-rtl", "--html", "-")
  bad("an explain --json-dir of -", "--json-dir: - names no folder", Seq(os.pwd / "-"))("explain", good.toString, "--quiet", "--no-rtl", "--json-dir", "-")
  bad("a simulate --out that ends with a slash (a folder)", "ends with /, so it names a folder", Seq(dir / "newdir"))(
    "simulate", "--out", (dir / "newdir").toString + "/", "--samples", "100")
  bad("an explain option given twice (the last would win)", "--plots is given 2 times")(
    "explain", good.toString, "--quiet", "--no-rtl", "--plots", (dir / "p1").toString, "--plots", (dir / "p2").toString)
  bad("an explain flag given twice", "--quiet is given 2 times")("explain", good.toString, "--quiet", "--no-rtl", "--quiet")
  bad("a replay option given twice", "--out is given more than once")("replay", good.toString, "--out", (dir / "r1.csv").toString, "--out", (dir / "r2.csv").toString)
  bad("a recording named twice", "given 2 times; name each recording once")("explain", good.toString, good.toString, "--quiet", "--no-rtl")
  // through a link the one file was explained twice, good.json and its link's JSON written
  private val goodSym = dir / "good-sym.csv"
  if (!os.exists(goodSym, followLinks = false)) os.symlink(goodSym, good)
  private val goodHard = dir / "good-hard.csv"
  if (!os.exists(goodHard, followLinks = false)) java.nio.file.Files.createLink(goodHard.toNIO, good.toNIO)
  for ((how, other) <- Seq("a symbolic link" -> goodSym, "a hard link" -> goodHard))
    bad(s"a recording named twice through $how", s"$good and $other are one file", Seq(dir / "twice" / "good.json", dir / "twice" / s"${other.baseName}.json"))(
      "explain", good.toString, other.toString, "--quiet", "--no-rtl", "--json-dir", (dir / "twice").toString)
  for (o <- Seq("--json-dir", "--plots", "--html-dir"))
    bad(s"an explain $o that is empty", s"$o: the folder's name is empty")("explain", good.toString, "--quiet", "--no-rtl", o, "")
  bad("an explain --html that is empty", "an output file's name is empty")("explain", good.toString, "--quiet", "--no-rtl", "--html", "")
  // an empty output folder would be the working folder, which the user did not name
  for (cmd <- Seq(Seq("emit"), Seq("emit-subdiv"), Seq("emit-datapath", "--design", "quadcomp"), Seq("emit-harmonic"), Seq("board", "de2-115"),
                  Seq("cost", "--sweep"), Seq("explain-bench", "--samples", "250000"), Seq("calibrate", "--input", good.toString)))
    bad(s"a ${cmd.head} --out that is empty", "--out: the folder's name is empty")(cmd ++ Seq("--out", ""): _*)
  bad("a cost --keep that is empty", "--keep: the folder's name is empty")("cost", "--keep", "")
  bad("a simulate --out that is its --model", "is an input of this command", Seq(model))(
    "simulate", "--model", model.toString, "--out", model.toString, "--samples", "100")
  private val portLink = dir / "ttyLink"
  if (!os.exists(portLink, followLinks = false)) os.symlink(portLink, os.Path("/dev/null"))
  bad("record --port A --out A (the port's link)", "is an input of this command", Seq(portLink))(
    "record", "--port", portLink.toString, "--out", portLink.toString, "--seconds", "1")
  private val link = dir / "link.csv"
  if (!os.exists(link, followLinks = false)) os.symlink(link, existing)
  bad("an --out that is a symbolic link", "is a symbolic link", Seq(existing))("simulate", "--out", link.toString, "--samples", "100")
  private val fifo = dir / "fifo"
  if (!os.exists(fifo, followLinks = false)) os.proc("mkfifo", fifo.toString).call()
  bad("an --out that is a named pipe", "is a named pipe (FIFO)")("simulate", "--out", fifo.toString, "--samples", "100")
  private val device = dir / "dev-null"
  private val isRoot = os.proc("id", "-u").call().out.trim() == "0"
  if (isRoot && !os.exists(device, followLinks = false)) os.proc("mknod", device.toString, "c", "1", "3").call()
  if (isRoot) bad("an --out that is a device node", "is a character device")("simulate", "--out", device.toString, "--samples", "100")
  else bad("an --out that is a device node", "is a character device")("simulate", "--out", "/dev/null", "--samples", "100")
  // a recording is data: a measured one is written over by no command, a simulated one only by a recording
  private val measured = dir / "measured.csv"
  os.write.over(measured, head + "# source: bench 3\nsin,cos\n" + rows(2000))
  private val simulated = dir / "simulated.csv"
  os.write.over(simulated, head + "# model: {}\n# source: moire simulate\nsin,cos\n" + rows(2000))
  bad("an explain --html over a measured recording", "is a measured recording (simulate did not write it", Seq(measured))(
    "explain", good.toString, "--quiet", "--no-rtl", "--html", measured.toString)
  bad("a simulate --out over a measured recording", "is a measured recording", Seq(measured))("simulate", "--out", measured.toString, "--samples", "100")
  bad("a replay --out over a measured recording", "is a measured recording", Seq(measured))("replay", good.toString, "--out", measured.toString)
  private val measuredBom = dir / "measured-bom.csv"
  os.write.over(measuredBom, "\uFEFF" + head + "sin,cos\n" + rows(2000))
  bad("an output over a measured recording with a byte-order mark", "is a measured recording", Seq(measuredBom))(
    "simulate", "--out", measuredBom.toString, "--samples", "100")
  bad("an explain --html over a simulated recording", "is a recording, and this command's output is not one", Seq(simulated))(
    "explain", good.toString, "--quiet", "--no-rtl", "--html", simulated.toString)
  bad("an output name with a line break", "an output name holds a control character (U+000A")("simulate", "--out", (dir / "a\nb.csv").toString, "--samples", "100")
  bad("a replay --out that is empty", "an output file's name is empty")("replay", good.toString, "--out", "")
  bad("an accuracy --json that is empty", "an output file's name is empty")("accuracy", "--json", "")
  // root may write into /proc by its permission bits, yet no file can be made there: said before the tables' 10 s run
  // (one line: no progress line of the run came before it)
  bad("an accuracy --json in /proc", "/proc: the folder")("accuracy", "--json", "/proc/moire-x.json")
  "simulate" should "write over a recording it wrote (its model line makes it again)" in {
    val f = dir / "again.csv"
    for (seed <- Seq("1", "2")) { val (code, err) = runCli("simulate", "--out", f.toString, "--samples", "100", "--seed", seed); withClue(err) { code shouldBe 0 } }
    os.read(f) should include("\"seed\":2")
  }
  "explain" should "say that a reference column that does not move does not move (not 'within NaN degree')" in {
    val f = rec("still.csv", head + "# lines_per_rev: 16384\nsin,cos,ref_deg\n" + rows(2000).linesIterator.map(_ + ",5").mkString("\n") + "\n")
    val d = dir / "stilljson"
    val (code, err) = runCli("explain", f, "--quiet", "--no-rtl", "--json-dir", d.toString)
    withClue(err) { code shouldBe 0 }
    val text = os.read(d / "still.json")
    text should include("ref_deg")
    text should include("it does not move (5 degree on every row)")
    text should not include "NaN degree"
  }
  "explain" should "name the outputs of a recording called .csv after it, not as hidden files" in {
    val d = dir / "dotcsv"; os.makeDir.all(d); os.copy.over(good, d / ".csv")
    val (code, err) = runCli("explain", (d / ".csv").toString, "--quiet", "--no-rtl", "--json-dir", d.toString)
    withClue(err) { code shouldBe 0 }
    os.exists(d / "csv.json") shouldBe true
    os.exists(d / ".json") shouldBe false
  }

  it should "keep the pipe, the link and the device what they were" in {
    os.isLink(link) shouldBe true
    os.read(existing) shouldBe "keep me\n"
    os.proc("test", "-p", fifo.toString).call(check = false).exitCode shouldBe 0
    if (isRoot) os.proc("test", "-c", device.toString).call(check = false).exitCode shouldBe 0
  }

  behavior of "inputs that are no file (each says what it is)"
  private val folderIn = dir / "a-folder"
  os.makeDir.all(folderIn)
  bad("explain of a folder", "is a folder, not a file")("explain", folderIn.toString)
  bad("explain of a named pipe", "is a named pipe (FIFO), not a file")("explain", fifo.toString)
  bad("explain of /dev/null", "is a character device, not a file")("explain", "/dev/null")
  bad("replay of a folder", "is a folder, not a file")("replay", folderIn.toString)
  bad("calibrate of a named pipe", "is a named pipe (FIFO), not a file")("calibrate", "--input", fifo.toString, "--out", calOut.toString)
  bad("a --model that is a folder", "is a folder, not a file")("explain", good.toString, "--model", folderIn.toString)
  bad("--coefficients /dev/null", "is a character device, not a file")("board-reg", "--port", port, "--coefficients", "/dev/null")
  bad("explain-bench --recording of a folder", "is a folder, not a file")("explain-bench", "--recording", folderIn.toString)
  bad("board-reg --load of a folder", "is a folder, not a file")("board-reg", "--port", port, "--load", folderIn.toString)
  bad("monitor --replay of a folder", "is a folder, not a file")("monitor", "--replay", folderIn.toString)
  // an option's value that reads --help is the option's, not a request for help that would do nothing and exit 0
  bad("--subdiv --help", "--subdiv")("explain", good.toString, "--subdiv", "--help")
  bad("--json-dir --help", "no such file")("explain", (dir / "missing.csv").toString, "--json-dir", "--help")
  // explain --model checks the whole file as simulate does (it fits only the effects), and bounds the terms it adds
  bad("a --model with an unknown key", "unknown key 'frobnicate'")("explain", good.toString, "--model", rec("m-key.json", """{"frobnicate": 1, "effects": []}"""))
  bad("a --model whose motion has a misspelled key", "motion: unknown key 'hz_'")("simulate", "--out", (dir / "mm.csv").toString,
    "--model", rec("m-motion.json", """{"motion": {"kind": "constant", "hz": 1000, "hz_": 2000}}"""))
  bad("a --model whose amplitude is text", "amplitude must be a number")("explain", good.toString, "--model", rec("m-amp.json", """{"amplitude": "x"}"""))
  bad("a --model of 76 harmonics", "explain --model fits at most 64")("explain", good.toString, "--model", rec("m-many.json",
    ujson.write(ujson.Obj("effects" -> ujson.Arr.from(for (k <- 2 until 40; ch <- Seq("sin", "cos")) yield
      ujson.Obj("effect" -> "harmonic", "order" -> k, "amplitude_rel" -> 1e-3, "channel" -> ch))))))
  // a channel that carries only noise: the other's phase fitted against it left "pickup at 80 kHz, 0.45 full scale"
  bad("a recording whose cos channel is only noise", "no fringe on the cos channel")("explain", "--no-rtl", "--quiet", rec("cos-dead.csv", head + "sin,cos\n" + {
    val r = new scala.util.Random(4)
    (0 until 6000).map { i => s"${2048 + (1500 * math.sin(2 * math.Pi * i / 150.0)).round},${2048 + (90 * r.nextGaussian()).round}" }.mkString("\n") + "\n"
  }))
  // the head moved over 1 % of a period: the cos channel barely changed, and it was "is the cos input connected?" (F20)
  "explain" should "refuse a recording over 1 % of a fringe period as too short an arc" in {
    val f = dir / "creep-1pc.csv"
    val (c0, e0) = runCli("simulate", "--samples", "1000", "--motion", "constant:100", "--out", f.toString)
    withClue(e0) { c0 shouldBe 0 }
    val (code, err) = runCli("explain", "--no-rtl", "--quiet", f.toString)
    withClue(err) { code shouldBe 2; err should include("too short an arc: the read head moved over less than one fringe period") }
  }
  "simulate --model" should "take --lines-per-rev and --effect beside a recording's model line (lines_per_rev null, effects [])" in {
    val m = rec("m-line.json", """{"samples": 2000, "lines_per_rev": null, "effects": []}""")
    val (c1, e1) = runCli("simulate", "--model", m, "--lines-per-rev", "1000", "--out", (dir / "m-line-l.csv").toString)
    withClue(e1) { c1 shouldBe 0 }
    moire.recording.Recording.read(dir / "m-line-l.csv").linesPerRev shouldBe Some(1000.0)
    val (c2, e2) = runCli("simulate", "--model", m, "--effect", "harmonic:order=3,amplitude_rel=0.01", "--out", (dir / "m-line-e.csv").toString)
    withClue(e2) { c2 shouldBe 0 }
    os.read(dir / "m-line-e.csv") should include("\"effect\":\"harmonic\"")
  }
  "explain --model" should "take one effect named many times as one term" in {
    val m = rec("m-same.json", ujson.write(ujson.Obj("effects" -> ujson.Arr.from(Seq.fill(5000)(ujson.Obj("effect" -> "harmonic", "order" -> 3, "amplitude_rel" -> 1e-3))))))
    val (code, err) = runCli("explain", good.toString, "--quiet", "--no-rtl", "--model", m)
    withClue(err) { code shouldBe 0 }
  }
  bad("monitor --replay of 10 rows", "monitor --replay (its bursts are explained) needs at least 64")(
    "monitor", "--replay", rec("ten-replay.csv", head + "sin,cos\n" + rows(10)), "--out", (dir / "mon").toString)
  // it played the file with 4 counts per period, a scale in neither the file nor the options (another tool's fuzz, N2)
  bad("monitor --replay of a file whose counts_per_period is 0", "metadata counts_per_period '0' is not a number above 0")(
    "monitor", "--replay", rec("m0-replay.csv", head + "# counts_per_period: 0\nsin,cos\n" + rows(100)), "--out", (dir / "mon").toString)
  bad("record --port of a folder", "is a folder, not a serial port")("record", "--port", folderIn.toString, "--seconds", "1", "--out", (dir / "r.csv").toString)
  bad("record --port ''", "--port is empty")("record", "--port", "", "--seconds", "1", "--out", (dir / "r.csv").toString)

  // it ran a variant's built-in extra configuration alone, exit 0 (another tool's fuzz sweep, F11)
  bad("a cost sweep whose --spread leaves no (n, b) of the grid", "--sweep: no (n, b) with b - 0 <= n <= b in these lists")(
    "cost", "--sweep", "--spread", "0", "--sweep-iterations", "8", "--sweep-widths", "30", "--out", (dir / "cs0").toString)
  bad("explain --subdiv with --no-rtl", "--subdiv sets the subdivider the RTL check runs, and --no-rtl leaves that check out")(
    "explain", good.toString, "--no-rtl", "--subdiv", "--counts 4096")
  "An error line" should "cut a value of thousands of characters (a 100 kB --effect was told back whole)" in {
    val (code, err) = runCli("simulate", "--samples", "100", "--out", (dir / "long.csv").toString, "--effect", "a" * 100000)
    withClue(err.take(500)) {
      code shouldBe 2
      err.length should be < 1000
      err should include("... (100002 characters)") // the value in its quotes
    }
  }

  behavior of "numbers (decimal only, the same everywhere)"
  bad("a sample rate of 1000000d (Java syntax)", "sample_rate_hz '1000000d' is not a sample rate")(
    "explain", rec("fsd.csv", "# moire-recording v1\n# sample_rate_hz: 1000000d\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("a sample rate of 0x1p20 (hexadecimal)", "sample_rate_hz '0x1p20' is not a sample rate")(
    "explain", rec("fshex.csv", "# moire-recording v1\n# sample_rate_hz: 0x1p20\n# adc_bits: 12\nsin,cos\n" + rows(100)))
  bad("an extra column of 2.5f", "ref_deg '2.5f' is not a finite number")("explain", rec("colf.csv", head + "sin,cos,ref_deg\n1,2,2.5f\n"))
  bad("--sample-rate-hz 1000000d", "'1000000d' is not a valid number", Seq(existing))(sim("--sample-rate-hz", "1000000d"): _*)
  bad("--noise 0x1p-10", "'0x1p-10' is not a valid number", Seq(existing))(sim("--noise", "0x1p-10"): _*)
  bad("a --motion speed of 2e4d", "--motion 'constant:2e4d'", Seq(existing))(sim("--motion", "constant:2e4d"): _*)
  bad("an effect parameter 0x10", "order '0x10' is not a finite number", Seq(existing))(sim("--effect", "harmonic:order=0x10"): _*)
  bad("explain --subdiv \"--counts 3\"", "--subdiv: --counts")("explain", good.toString, "--quiet", "--subdiv", "--counts 3")
  bad("explain --subdiv \"--bogus 1\"", "--subdiv: ")("explain", good.toString, "--quiet", "--subdiv", "--bogus 1")
  bad("calibrate --max-order -5", "--max-order must be at least 1 (or left out for the default), got -5")(calib("--max-order", "-5"): _*)
  bad("record --adc-clock-hz 1e12", "--adc-clock-hz must be from 1000 to 200000000 Hz")(recd("--seconds", "1", "--adc-clock-hz", "1e12"): _*)
  bad("record --adc-clock-hz 1.5", "--adc-clock-hz must be from 1000 to 200000000 Hz")(recd("--seconds", "1", "--adc-clock-hz", "1.5"): _*)
  bad("cost --sweep --sweep-widths ''", "--sweep-widths: give at least one integer")("cost", "--sweep", "--sweep-widths", "")
  bad("cost --sweep --sweep-iterations ' , '", "--sweep-iterations: give at least one integer")("cost", "--sweep", "--sweep-iterations", " , ")
  // an empty entry among others was dropped without a word (bounds refuses it)
  bad("cost --sweep --sweep-iterations 8,,12", "--sweep-iterations: '' is not an integer list like 8,12,16")(
    "cost", "--sweep", "--sweep-iterations", "8,,12", "--out", (dir / "sw2").toString)
  bad("timing --speeds 6,,8", "--speeds: '' is not an ECP5 speed grade")("timing", "--design", "cordic", "--speeds", "6,,8")

  behavior of "messages that say what is wrong"
  bad("a '#' line among the data rows", "a '#' line among the data rows")("explain", rec("hashrow.csv", head + "sin,cos\n" + rows(100) + "# paused here\n" + rows(100)))
  bad("# samples: 2000000000 in a 2000-row file", "metadata samples says '2000000000' but the file has 2000 data rows")(
    "explain", rec("bigsamples.csv", head + "# samples: 2000000000\nsin,cos\n" + rows(2000)))
  bad("board de2-115 --clock-hz 65000000 (the board's clock, not the ADC's)", "--clock-hz: the DE2-115 runs at 50000000 Hz")(
    "board", "de2-115", "--clock-hz", "65000000", "--out", boardOut.toString)
  bad("board ulx3s --clock-hz 66666666 (no exact PLL setting)", "--clock-hz: the ECP5 PLL cannot make exactly")(
    "board", "ulx3s", "--clock-hz", "66666666", "--out", boardOut.toString)
  bad("error_arcsec 1e400", "error_arcsec is 1e400: infinite")("calibrate", "--input", rec("calinf.csv", "# moire-calibration v1\nangle_deg,error_arcsec\n0,1\n10,1e400\n"))
  bad("one ccw row among cw rows", "direction ccw has 1 point (first on line 39)")(
    "calibrate", "--input", rec("calccw.csv", "# moire-calibration v1\nangle_deg,error_arcsec,direction\n" + (0 until 360 by 10).map { a =>
      val t = math.toRadians(a); f"$a,${2 * math.sin(t)}%.4f,cw" }.mkString("\n") + "\n10,0.3,ccw\n"), "--out", calOut.toString)
  private def binary(name: String, bytes: Array[Byte]): String = { os.write.over(dir / name, bytes); (dir / name).toString }
  bad("a UTF-16 recording (shown as bytes)", "UTF-16 text (save it as UTF-8); it starts with '\\xff\\xfe#\\x00")(
    "explain", binary("utf16.csv", Array(0xff, 0xfe).map(_.toByte) ++ (head + "sin,cos\n" + rows(10)).getBytes("UTF-16LE")))
  bad("a gzip file (shown as bytes)", "gzip-compressed data (unpack it first); it starts with '\\x1f\\x8b")("explain", binary("rec.csv.gz", {
    val b = new java.io.ByteArrayOutputStream; val z = new java.util.zip.GZIPOutputStream(b); z.write((head + "sin,cos\n" + rows(100)).getBytes); z.close(); b.toByteArray }))
  bad("a file of NUL bytes (shown as bytes)", "binary data (it holds NUL bytes), not text; it starts with '\\x00\\x00")("explain", binary("nul.csv", new Array[Byte](4096)))
  bad("control bytes on the first line", "got 'hello\\x01\\x07world'")("explain", rec("ctl.csv", "hello\u0001\u0007world\n"))
  bad("a calibration of NUL bytes", "binary data (it holds NUL bytes)")("calibrate", "--input", binary("calnul.csv", new Array[Byte](100)), "--out", calOut.toString)
  bad("one endless line (refused after 1 Mi characters, not read whole)", "a line longer than 1048576 characters")(
    "explain", binary("zeros.csv", Array.fill[Byte](3 << 20)('0'.toByte)))
  it should "refuse a 1 GB file of zeros quickly (the reader bounds a line's length)" in {
    val f = dir / "gigabyte.csv"
    val ch = java.nio.channels.FileChannel.open(f.toNIO, java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.WRITE)
    try { val z = java.nio.ByteBuffer.wrap(Array.fill[Byte](1 << 20)('0'.toByte)); for (_ <- 0 until 1024) { z.rewind(); ch.write(z) } } finally ch.close()
    val t0 = System.nanoTime()
    val (code, err) = runCli("explain", f.toString, "--quiet")
    val seconds = (System.nanoTime() - t0) / 1e9
    info(f"refused in $seconds%.2f s")
    os.remove(f)
    withClue(err) { code shouldBe 2; err should include("a line longer than 1048576 characters") }
  }

  behavior of "names and bytes with control characters (shown escaped, one line; no output named so)"
  /** As `bad`, and no control character but the line end reaches the terminal. */
  private def escaped(kind: String, expect: String, keep: Seq[os.Path] = Nil)(args: String*): Unit = {
    bad(kind, expect, keep)(args: _*)
    it should s"show no raw control character for $kind" in {
      val err = runCli(args: _*)._2
      withClue(err) { err.filter(c => c.isControl && c != '\n') shouldBe empty }
    }
  }
  escaped("a missing recording whose name holds a line break", "no\\x0asuch.csv: no such file")("explain", (dir / "no\nsuch.csv").toString)
  escaped("a missing recording whose name holds an escape sequence", "\\x1b[31mred.csv: no such file")("explain", (dir / "\u001b[31mred.csv").toString)
  it should "show a batch's error about a name with a line break on one line, escaped" in {
    val (code, err) = runCli("explain", good.toString, (dir / "no\nsuch.csv").toString, "--quiet", "--no-rtl")
    withClue(err) {
      code shouldBe 2
      err.linesIterator.filter(_.nonEmpty).toSeq should have size 2 // the file's error, then "1 of 2 files failed"
      err should include("no\\x0asuch.csv: no such file")
      err.filter(c => c.isControl && c != '\n') shouldBe empty
    }
  }
  escaped("an emit --mode with a line break", "sin\\x0acos")("emit", "--mode", "sin\ncos", "--out", (dir / "emitnl").toString)
  private val nlRec = rec("nl\nname.csv", head + "sin,cos\n" + rows(2000))
  escaped("a recording whose name holds a line break, with --json-dir (the JSON would be named so)",
    "nl\\x0aname.csv: its name holds a control character (U+000A", Seq(dir / "jnl" / "nl\nname.json"))("explain", nlRec, "--quiet", "--no-rtl", "--json-dir", (dir / "jnl").toString)
  escaped("a calibration whose name holds a line break (its outputs would be named so)", "its name holds a control character (U+000A",
    Seq(calOut / "c\nx.png"))("calibrate", "--input", rec("c\nx.csv", "# moire-calibration v1\n" + calRows), "--out", calOut.toString)
  escaped("a replay's default output named after a recording with a line break", "its name holds a control character (U+000A")("replay", nlRec)
  escaped("a binary board-reg --coefficients file (its bytes shown escaped)", "is binary data (it holds NUL bytes), not text")(
    "board-reg", "--port", "/dev/null", "--coefficients", binary("bin.dat", Array[Byte](1, 2, 27, '[', '2', 'J', 0, 7, 10, 13, -1, -128, 0x9b.toByte)))
  escaped("a board-reg --coefficients listing with an escape sequence", "expected 'addr data' in hex, got 'x\\x1b[2Jy'")(
    "board-reg", "--port", "/dev/null", "--coefficients", rec("esc.registers.txt", "x\u001b[2Jy\n"))

  // a monitor --port that can never be a serial port: it was tried every second and the monitor ran on
  bad("a monitor --port that is a plain file", "is a plain file, not a serial port")("monitor", "--port", aFile.toString, "--http-port", "0")
  bad("a monitor --port that is a folder", "is a folder, not a serial port")("monitor", "--port", dir.toString, "--http-port", "0")
  bad("an empty monitor --port", "--port is empty: name a serial port")("monitor", "--port", "", "--http-port", "0")

  // a name with a byte that is no UTF-8 arrives as U+FFFD: explain said "no such file", simulate wrote another name
  bad("a recording name with a byte that is not UTF-8", "holds bytes that are not UTF-8 (shown as \\ufffd)")("explain", (dir / "lat\uFFFD.csv").toString, "--quiet")
  bad("a simulate --out name with a byte that is not UTF-8", "holds bytes that are not UTF-8", Seq(dir / "caf\uFFFD.csv"))(
    "simulate", "--out", (dir / "caf\uFFFD.csv").toString, "--samples", "100")

  // a byte-order mark before a coefficient listing was part of its first address; and a message showed the mark unseen
  bad("a .registers.txt with a byte-order mark (was \"'<mark>0x10' is not a hex number\")", "no such serial port")(
    "board-reg", "--port", port, "--coefficients", rec("bom.registers.txt", "\uFEFF0x10 0x3\n"))
  bad("an emit --mode with a byte-order mark (shown escaped)", "--mode: '\\ufeffsincos' is not a mode")("emit", "--mode", "\uFEFFsincos")

  // other scripts' digits in a register value or address were read (Java's parseLong), where every other number refuses them
  bad("a board-reg --write value in Arabic-Indic digits", "value '\u0663' is not a u32")("board-reg", "--port", port, "--write", "decimation=\u0663")
  bad("a board-reg --read address in full-width digits", "register '\uFF14' is unknown")("board-reg", "--port", port, "--read", "\uFF14")

  "BadInputSpec" should s"cover at least 60 kinds of bad input (has $kinds)" in {
    info(s"$kinds kinds of bad input")
    kinds should be >= 60
  }
}
