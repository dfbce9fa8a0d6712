package moire.replay

import moire.explain.BoardCheck

import moire.cordic.SimSupport
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import moire.subdiv.{SubdivModel, SubdivSample}
import org.scalatest.flatspec.AnyFlatSpec

/** explain's comparison of board outputs with the RTL: the patterns, and end to end on synthetic recordings. */
class BoardCheckSpec extends AnyFlatSpec {
  import ReplaySupport._
  init()

  private val rnd = new scala.util.Random(5)
  private val rtl: Array[Long] = { var p = 0L; Array.fill(20000) { p += rnd.nextInt(7) - 3; p } }
  private def classify(rec: Array[Long]) = BoardCheck.classify(rec, rtl, 32, 1024, i => 1000L + i)

  "classify" should "report no difference for an unaltered position" in {
    assert(classify(rtl.clone()).pattern == "none")
  }

  it should "name a constant offset and say when it is whole periods" in {
    val c = classify(rtl.map(_ + 3 * 1024))
    assert(c.pattern == "constant_offset" && c.params("offset_periods") == 3 && c.first.contains(1000L))
    assert(c.summary.contains("3 whole periods"), c.summary)
    val c2 = classify(rtl.map(_ - 5))
    assert(c2.pattern == "constant_offset" && c2.params("offset_counts") == -5 && c2.summary.contains("not a whole number"))
  }

  it should "name sporadic bit errors and the bits" in {
    val rows = Seq(700, 4100, 9000, 15000)
    val rec = rtl.clone()
    rows.zip(Seq(3, 17, 3, 9)).foreach { case (r, b) => rec(r) ^= 1L << b }
    val c = classify(rec)
    assert(c.pattern == "sporadic_bit_errors" && c.first.contains(1700L), c)
    assert(c.params("bit_3_flips") == 2 && c.params("bit_17_flips") == 1 && c.params("bit_9_flips") == 1 && c.params("error_samples") == 4)
    assert(c.summary.contains("3 (2x)"), c.summary)
  }

  it should "name a growing difference as drift" in {
    val c = classify(rtl.zipWithIndex.map { case (p, i) => p + (i - 5000).max(0) / 500 })
    assert(c.pattern == "drift" && c.first.contains(1000L + 5500) && c.params("slope_counts_per_sample") > 0, c)
  }

  it should "name a few count slips as steps" in {
    val c = classify(rtl.zipWithIndex.map { case (p, i) => p + (if (i > 12000) 4 else 0) })
    assert(c.pattern == "step" && c.first.contains(1000L + 12001), c)
  }

  /** A recording as the board would write it: codes, and the positions of the bit-accurate model. */
  private def boardRecording(alter: (Array[Long]) => Array[Long]) = {
    val d = configs.head
    val s = SignalSim.generate(SignalParams(amplitude = 0.85, noiseRms = 0.001, seed = 3), Motion.Oscillate(6, 1500), Adc(d.inputBits, d.format), 10e6, 6000)
    val m = new SubdivModel(d.p)
    val pos = (0 until s.length).map(i => m.process(SubdivSample(s.sinSigned(i), s.cosSigned(i))).position).toArray
    recording(s, Map("counts_per_period" -> d.p.counts.toString), Map("position" -> alter(pos).map(_.toDouble)))
  }

  "the board check" should "find nothing when the board agrees with the RTL, and name an altered position" in {
    SimSupport.requireTool(this, "verilator")
    val (none, notes) = BoardCheck.run("same.csv", boardRecording(identity), firstOpts, _ => ())
    assert(none.isEmpty && notes.exists(_.contains("equals the RTL on all 6000 samples")), notes)
    val (f, _) = BoardCheck.run("offset.csv", boardRecording(_.map(_ + 8)), firstOpts, _ => ())
    assert(f.map(_.effect).contains("board_position_constant_offset") && f.get.params("offset_periods") == 2, f)
    val (g, _) = BoardCheck.run("flip.csv", boardRecording { p => val q = p.clone(); q(3000) ^= 1L << 6; q }, firstOpts, _ => ())
    assert(g.map(_.effect).contains("board_position_sporadic_bit_errors") && g.get.params("first_mismatch_sample") == 3000, g)
    val (h, _) = BoardCheck.run("drift.csv", boardRecording(_.zipWithIndex.map { case (p, i) => p + i / 300 }), firstOpts, _ => ())
    assert(h.map(_.effect).contains("board_position_drift") && h.get.params("first_mismatch_sample") == 300, h)
  }

  it should "compare each file of an explain batch with the RTL, the files side by side" in {
    SimSupport.requireTool(this, "verilator")
    val dir = os.temp.dir()
    moire.recording.Recording.write(dir / "same.csv", boardRecording(identity))
    moire.recording.Recording.write(dir / "offset.csv", boardRecording(_.map(_ + 8)))
    moire.explain.ExplainCmd.explain(Seq("same.csv", "offset.csv").map(f => (dir / f).toString), Some((dir / "json").toString), None, None,
      quiet = true, rtl = Some(firstOpts))
    def json(stem: String) = ujson.read(os.read(dir / "json" / s"$stem.json"))
    assert(json("same")("notes").arr.exists(_.str.contains("equals the RTL on all 6000 samples")), json("same")("notes"))
    assert(json("offset")("findings").arr.exists(_("effect").str == "board_position_constant_offset"), json("offset")("findings"))
  }

  it should "say why a decimated recording is not compared" in {
    val r = boardRecording(identity)
    val (f, notes) = BoardCheck.run("dec.csv", r.copy(meta = r.meta + ("decimation" -> "8")), firstOpts, _ => ())
    assert(f.isEmpty && notes == Seq("board outputs not compared: dec.csv: the recording is decimated (decimation 8): " +
      "the RTL needs every ADC sample, so it cannot be replayed exactly"), notes)
  }

  it should "say why --subdiv --counts other than the recording's counts_per_period is not compared" in {
    val r = boardRecording(identity)
    val (f, notes) = BoardCheck.run("c.csv", r.copy(meta = r.meta + ("counts_per_period" -> "1024")), Seq("--counts", "4096"), _ => ())
    assert(f.isEmpty && notes.size == 1 && notes.head.startsWith("board outputs not compared: --subdiv gives --counts 4096, but the recording's " +
      "counts_per_period is 1024"), notes)
  }
}
