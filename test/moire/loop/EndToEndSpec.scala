package moire.loop

import moire.board.{BoardParams, ClockSource}
import moire.emit.{Emit, Target}
import moire.explain.{ExplainSupport, Progress, Report, SignalExplain}
import moire.recording.Recording
import moire.replay.VerilatorBuild
import moire.signal.{Adc, AdcFormat}
import moire.stream.PtyPair
import org.scalatest.flatspec.AnyFlatSpec

/** physics -> ADC -> board -> UART -> recorder -> explain, end to end. An independent bench ([[BenchHead]], its
  * own formulas) with a concealed effect makes the analog signals and the reference encoder; a behavioural
  * AD9226 pipeline (7 clocks, offset binary) and the whole board top run in Verilator
  * (test/resources/moire/loop/board_loop.cpp around [[LoopTop]]); the board's UART goes through a socat pty
  * pair into `moire record --burst --trigger z` (Main.run in this JVM; the reference encoder's Z starts
  * every burst at the same point of the motion); explain reads the file and must name the effect
  * and recover its parameter within 20 %, with the reference column, and find nothing on the clean run.
  */
/** One run: the bench, what explain must find, a fault on the sin data lines. */
final case class LoopCase(name: String, head: BenchHead, check: Report => Option[String], sinPins: Int => Int = identity)

class EndToEndSpec extends AnyFlatSpec {
  val burst = 4096
  val stimulusSamples: Int = 1 << 20

  /** The findings of `effect`, none when explain named anything else as well (a false finding fails the case). */
  private def find(r: Report, effect: String) = if (r.findings.forall(_.effect == effect)) r.findings else Nil
  private def near(x: Double, truth: Double) = ExplainSupport.within(x, truth, 0.2)
  private val stuckBit = 7
  def clean(h: BenchHead): LoopCase = LoopCase("clean", h, r => if (r.findings.isEmpty) None else Some("findings on the clean run"))
  def skew(h: BenchHead): LoopCase = LoopCase("skew 5 ns", h.copy(skewS = 5e-9, seed = 12), r =>
    if (find(r, "channel_skew").exists(f => near(f.params("skew_s"), 5e-9))) None else Some("channel_skew 5 ns not recovered"))
  def harmonic(h: BenchHead): LoopCase = LoopCase("3rd harmonic 1 %", h.copy(harmonic = 0.01, seed = 13), r =>
    if (find(r, "harmonic").exists(f => f.params.get("order").contains(3.0) && near(math.abs(f.params("amplitude_rel")), 0.01))) None
    else Some("harmonic 3 at 1 % not recovered"))
  def stuck(h: BenchHead): LoopCase = LoopCase(s"sin bit $stuckBit stuck at 0", h.copy(seed = 14), r =>
    if (find(r, "adc_bit_fault").exists(f => f.channel == "sin" && f.params.get("bit").contains(stuckBit.toDouble) &&
      f.params.get("stuck_at").contains(0.0))) None else Some(s"sin bit $stuckBit stuck at 0 not named"), sinPins = _ & ~(1 << stuckBit))

  /** Stimulus file for the harness and the pin codes it holds (sin, cos with OTR at bit 12). */
  def stimulus(k: LoopCase, file: os.Path): (Array[Int], Array[Int]) = {
    val adc = Adc(12, AdcFormat.OffsetBinary)
    val n = stimulusSamples
    val sin = new Array[Int](n); val cos = new Array[Int](n)
    val bb = java.nio.ByteBuffer.allocate(4 + 5 * n).order(java.nio.ByteOrder.LITTLE_ENDIAN)
    bb.putInt(n)
    for (i <- 0 until n) {
      val x = k.head.analog(i)
      val s = adc.sample(x.sin); val c = adc.sample(x.cos)
      sin(i) = k.sinPins(s.code) | (if (s.otr) 1 << 12 else 0); cos(i) = c.code | (if (c.otr) 1 << 12 else 0)
      val count = k.head.refCount(i / k.head.fs)
      val (a, b) = moire.io.Quadrature.levels(count)
      val z = k.head.refZ(count)
      bb.putShort(sin(i).toShort).putShort(cos(i).toShort).put(((if (a) 1 else 0) | (if (b) 2 else 0) | (if (z) 4 else 0)).toByte)
    }
    os.write(file, bb.array())
    (sin, cos)
  }

  /** Builds the board's loop harness (cached), then runs each case on a fresh pty pair; returns the failures. */
  def loop(board: String, p: BoardParams, cases: Seq[LoopCase]): Seq[String] = {
    val verilog = Emit.elaborate(new LoopTop(board, p), Target.Verilog)._2
    val source = new String(getClass.getResourceAsStream("/moire/loop/board_loop.cpp").readAllBytes(), "UTF-8")
    val h = VerilatorBuild.harness(verilog, "LoopTop", source = source)
    info(f"$board loop harness: ${if (h.cached) "cached" else f"built in ${h.buildSeconds}%.0f s"}")
    cases.flatMap { k =>
      PtyPair { pty =>
        val stim = pty.dir / "stim.bin"
        val (sin, cos) = stimulus(k, stim)
        val log = pty.dir / "harness.log"
        val sim = os.proc(h.exe, stim, pty.board, p.baudDivisor.toString, "200000000").spawn(stderr = log)
        val out = pty.dir / "rec.csv"
        val t0 = System.nanoTime()
        val code = try moire.cli.Main.run(Array("record", "--port", pty.host.toString, "--burst", burst.toString, "--pre", "256", "--trigger", "z",
          "--out", out.toString, "--ref-counts-per-period", k.head.refPerPeriod.toString, "--seconds", "60", "--quiet"))
        finally { sim.destroy(); sim.waitFor(5000) }
        val wall = (System.nanoTime() - t0) / 1e9
        assert(code == 0, s"$board ${k.name}: record --burst exit code $code; harness: ${os.read(log)}")
        val rec = Recording.read(out)
        assert(rec.length == burst && rec.sampleRateHz == p.adcClockHz.toDouble && rec.extra.contains("ref_counts") &&
          rec.meta.get("ref_counts_per_period").contains(k.head.refPerPeriod.toString), s"$board ${k.name}: recording ${rec.meta}")
        // the file's codes are the ADC pins' of consecutive samples, sample for sample (the board's sample index
        // starts after its reset: d ADC edges after the harness's first)
        val idx = rec.extra("sample_index")
        def same(d: Int, i: Int) = { val s = ((idx(i).toLong + d) % stimulusSamples).toInt; rec.sin(i) == (sin(s) & 0xFFF) && rec.cos(i) == (cos(s) & 0xFFF) }
        val d = (0 until 2000).find(d => (0 until 64).forall(same(d, _)))
          .getOrElse(fail(s"$board ${k.name}: the burst's first codes are not the stimulus at any offset"))
        for (i <- 0 until burst) assert(same(d, i), s"$board ${k.name}: sample $i (index ${idx(i)}, offset $d)")
        assert(idx.sliding(2).forall(w => w(1) - w(0) == 1.0), s"$board ${k.name}: sample_index not consecutive")
        val report = SignalExplain.run(out.toString, rec, Nil, Progress.none).report
        info(f"$board ${k.name}: record --burst $wall%.1f s (${os.read(log).trim.linesIterator.toSeq.lastOption.getOrElse("")}); " +
          s"explain: ${Some(ExplainSupport.describe(report)).filter(_.nonEmpty).getOrElse("no findings")}")
        k.check(report).map(f => s"$board ${k.name}: $f (found: ${ExplainSupport.describe(report)}; unexplained: " +
          report.unexplained.map(u => s"${u.where}: ${u.summary}").mkString("; ") + s"; notes: ${report.notes.mkString("; ")}; not tested: " +
          report.untested.mkString("; ") + ")")
      }
    }
  }

  "The DE2-115 board in the loop" should "carry each concealed effect from the bench through record --burst to explain" in {
    // ADC at the system clock (k = 1), UART at clock / 4 for the simulation, a 4096-sample burst RAM
    val p = BoardParams(adcClockHz = 50000000, baud = 12500000, glitchFilter = 2, decimation = 1 << 16,
      clockSource = ClockSource.Logic, burstSamples = burst)
    // 250,000 fringe periods/s (a homodyne interferometer's 0.16 um fringe at 40 mm/s), speed +-50 % at 2 kHz
    val h = BenchHead(50e6, speed = 250e3, wobbleHz = 2e3)
    val failures = loop("de2-115", p, Seq(clean(h), skew(h), harmonic(h), stuck(h)))
    assert(failures.isEmpty, failures.mkString("; "))
  }

  "The ULX3S board in the loop" should "carry a concealed harmonic to explain and nothing on a clean run (the shorter version)" in {
    val p = BoardParams(clockHz = 25000000, adcClockHz = 25000000, baud = 6250000, glitchFilter = 2, decimation = 1 << 16,
      clockSource = ClockSource.Logic, burstSamples = burst)
    val h = BenchHead(25e6, speed = 125e3, wobbleHz = 1e3)
    val failures = loop("ulx3s", p, Seq(clean(h), harmonic(h)))
    assert(failures.isEmpty, failures.mkString("; "))
  }
}
