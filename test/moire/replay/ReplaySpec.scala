package moire.replay

import moire.cordic.SimSupport
import moire.signal.{Adc, Motion, SignalParams, SignalSim}
import org.scalatest.flatspec.AnyFlatSpec

/** Replay through the Verilated RTL against the bit-accurate model, the cache and the windowed check. */
class ReplaySpec extends AnyFlatSpec {
  import ReplaySupport._
  init()

  "replay" should "equal the clock-level model bit for bit on every row over a sweep of 3 configurations" in {
    SimSupport.requireTool(this, "verilator")
    for ((d, k) <- configs.zipWithIndex) {
      val pins = stimulus(Adc(d.inputBits, d.format), 8, 21L + k)
      val n = pins.length
      val out = Replay.run(harness(d), d, pins)
      assert(out.length == n)
      val check = ModelCheck.run(d, pins, out, head = n)
      assert(check.ok, s"${d.topName}: ${check.text}")
      assert(check.rows == n)
      // The stimulus reaches the cases that matter: absent signal, over-range, step faults, both directions, Z.
      def any(bit: Int, v: Boolean) = (0 until n).exists(i => out.flag(i, bit) == v)
      assert(any(Replay.Present, false) && any(Replay.OverRange, true) && any(Replay.StepFault, true), d.topName)
      // Z marks count 0 mod M of the A/B output, which steps one count per clock: reachable here for small M.
      if (d.out.counts <= 256) assert(any(Replay.Z, true) && any(Replay.A, true) && any(Replay.B, true), d.topName)
      assert(out.position.min < -d.out.counts && out.position.max > d.out.counts, d.topName)
      // A single flipped bit is found, at its row.
      val bad = out.copy(position = out.position.clone())
      bad.position(n / 2) ^= 1L << (d.out.positionWidth - 1)
      val c2 = ModelCheck.run(d, pins, bad, head = n)
      assert(c2.firstMismatch.map(_._1).contains(n / 2) && c2.firstMismatch.get._2.startsWith("position"), c2.text)
    }
  }

  it should "check long runs in windows with the period counter seeded from the row before" in {
    SimSupport.requireTool(this, "verilator")
    val d = configs(1)
    val s = SignalSim.generate(SignalParams(amplitude = 0.8, noiseRms = 0.002), Motion.Oscillate(300, 5000), Adc(d.inputBits, d.format), 50e6, 250000)
    val pins = PinStream(s.sin, s.cos, s.otrSin, s.otrCos)
    val out = Replay.run(harness(d), d, pins)
    val check = ModelCheck.run(d, pins, out, head = 20000, windows = 10, window = 2000)
    assert(check.ok, check.text)
    assert(check.windows == 10 && check.rows == 20000 + 10 * 2000)
    val r = 20000 + (250000 - 20000 - 2000) * 4 / 9 + 100 // inside the fifth window
    val bad = out.copy(phase = out.phase.clone())
    bad.phase(r) ^= 1L
    assert(ModelCheck.run(d, pins, bad, head = 20000, windows = 10, window = 2000).firstMismatch.map(_._1).contains(r))
  }

  "the build cache" should "reuse a build for the same Verilog and rebuild for different Verilog" in {
    SimSupport.requireTool(this, "verilator")
    val d = configs.head
    val v = d.verilog()
    val h1 = VerilatorBuild.harness(v, d.topName, cache)
    val h2 = VerilatorBuild.harness(v, d.topName, cache)
    assert(h2.cached && h2.dir == h1.dir && os.isFile(h2.exe))
    assert(VerilatorBuild.key(v) != VerilatorBuild.key(v + "\n// changed\n"))
    assert(VerilatorBuild.key(v) == VerilatorBuild.key(d.verilog()), "emitting twice gives the same Verilog")
  }
}

/** The second design: ADC front end + adaptive corrector + subdivider. */
class ReplayCorrectedSpec extends AnyFlatSpec {
  ReplaySupport.init()

  "replay of the corrected chain" should "equal its clock-level model on every row" in {
    SimSupport.requireTool(this, "verilator")
    val d = ReplayDesign("corrected", moire.options.SubdivConfig())
    val s = SignalSim.generate(moire.subdiv.SubdivAccuracy.imperfect.copy(noiseRms = 0.001), Motion.Oscillate(40, 4000), Adc(d.inputBits, d.format), 50e6, 30000)
    val pins = PinStream(s.sin, s.cos, s.otrSin, s.otrCos)
    val out = Replay.run(ReplaySupport.harness(d), d, pins)
    val check = ModelCheck.run(d, pins, out, head = pins.length)
    assert(check.ok && check.rows == pins.length, check.text)
    assert(out.position.max - out.position.min > 10 * d.out.counts)
  }
}
