package moire.replay

import moire.cli.CliProcess
import moire.cordic.SimSupport
import moire.recording.Recording
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import moire.subdiv.{SubdivModel, SubdivSample}
import org.scalatest.flatspec.AnyFlatSpec

/** `replay`, `explain` with a position column, and replay's messages for recordings it cannot replay. */
class ReplayCliSpec extends AnyFlatSpec {
  import ReplaySupport._
  init()
  private val jvm = Seq(s"-Dmoire.replay.cache=$cache")
  private val dir = os.temp.dir(prefix = "moire-replay-cli")
  private val d = configs.head
  private val s = SignalSim.generate(SignalParams(amplitude = 0.85, noiseRms = 0.001, seed = 9), Motion.Oscillate(5, 2000), Adc(d.inputBits, d.format), 10e6, 5000)
  private val modelPos = { val m = new SubdivModel(d.p); (0 until s.length).map(i => m.process(SubdivSample(s.sinSigned(i), s.cosSigned(i))).position) }
  private val meta = Map("counts_per_period" -> "4")
  private def write(name: String, r: Recording): String = { val f = dir / name; Recording.write(f, r); f.toString }

  "replay" should "write the outputs aligned to the input samples, check them, and reuse its build" in {
    SimSupport.requireTool(this, "verilator")
    val in = write("rec.csv", recording(s, meta))
    val out = dir / "out.csv"
    val (code, so, se) = CliProcess.runWith(jvm)("replay", in, "--out", out.toString, "--backlog-limit", "4")
    assert(code == 0, se)
    assert(so.contains("model check: all 5000 checked rows equal the bit-accurate model"), so)
    val lines = os.read.lines(out)
    assert(lines.head == OutputCsv.Magic && lines.contains(s"# latency: ${d.latency}"))
    val rows = lines.dropWhile(_.startsWith("#")).tail.map(_.split(","))
    assert(rows.map(_(0).toInt) == (0 until 5000) && rows.map(_(1).toLong) == modelPos)
    val (code2, _, se2) = CliProcess.runWith(jvm)("replay", in, "--out", out.toString, "--backlog-limit", "4")
    assert(code2 == 0 && se2.contains("cached build"), se2)
  }

  it should "refuse decimated and gappy recordings, a wrong ADC width and unknown designs with one line, exit 2" in {
    val dec = write("dec.csv", recording(s, meta + ("decimation" -> "4")))
    val ix = Array.tabulate(s.length)(i => (100 + i + (if (i >= 2000) 3 else 0)).toDouble)
    val gap = write("gap.csv", recording(s, meta, Map("sample_index" -> ix)))
    val ok = write("ok.csv", recording(s, meta))
    val cases = Seq(
      Seq(dec) -> "the recording is decimated (decimation 4): the RTL needs every ADC sample, so it cannot be replayed exactly",
      Seq(gap) -> "sample_index jumps from 2099 to 2103 (data row 2001): records are missing, so the RTL cannot be replayed exactly",
      Seq(ok, "--input-bits", "10") -> "the recording has 12-bit ADC codes, the design reads 10 bits (--input-bits)",
      Seq(ok, "--design", "fir") -> "--design: 'fir' is not a replayable design; allowed: subdiv, corrected",
      Seq(ok, "--counts", "5") -> "--counts (M) must be a power of two in 4..65536, got 5",
      Seq(ok, "--design", "corrected", "--iterations", "99") -> "--iterations applies to --design subdiv only: the corrected chain takes --counts, --adc-format",
      Seq(ok, "--design", "corrected", "--input-bits", "10") -> "--input-bits: the corrected chain reads 12-bit codes only",
      Seq(ok, "--check-rows", "x") -> "--check-rows: 'x' is not a whole number from 1 to 2147483647",
      Seq((dir / "none.csv").toString) -> "no such file")
    for ((args, msg) <- cases) {
      val (code, _, err) = CliProcess.runWith(jvm)("replay" +: args: _*)
      assert(code == 2 && err.trim.linesIterator.size == 1 && err.contains(msg), s"$args: $code $err")
    }
  }

  it should "run the corrected chain at the recording's counts per period (M), not at its default" in {
    for (m <- Seq(4, 4096)) assert(ReplayDesign("corrected", ReplayCmd.config(Nil, Map("counts_per_period" -> m.toString))).out.counts == m)
    assert(ReplayDesign("corrected", ReplayCmd.config(Seq("--counts", "256"), Map("counts_per_period" -> "4096"))).out.counts == 256)
  }

  "explain" should "report a board position that differs from the RTL as a finding" in {
    SimSupport.requireTool(this, "verilator")
    val f = write("board.csv", recording(s, meta, Map("position" -> modelPos.map(p => (p + 12).toDouble).toArray)))
    val json = dir / "json"
    val (code, so, se) = CliProcess.runWith(jvm)("explain", f, "--json-dir", json.toString, "--subdiv", "--backlog-limit 4")
    assert(code == 0, se)
    assert(so.contains("finding board_position_constant_offset (from sample 0)") && so.contains("3 whole periods of M = 4"), so)
    val fs = ujson.read(os.read(json / "board.json"))("findings").arr
    val b = fs.find(_("effect").str == "board_position_constant_offset").get
    assert(b("params")("offset_counts").num == 12 && b("delta_bic").isNull)
  }
}
