package moire.chain

import chisel3._
import chiseltest._
import moire.adapt.AdaptParams
import moire.cordic.SimSupport
import moire.signal._
import moire.subdiv.{PhaseMethod, SubdivParams, SubdivResult}
import org.scalatest.flatspec.AnyFlatSpec

/** The corrector chained in front of the subdivider: RTL = model every clock, and the chain's
  * position error on imperfect signals against the exact phase.
  */
class CorrectedSubdivSpec extends AnyFlatSpec with ChiselScalatestTester {
  val fast = AdaptParams(offsetRate = 1, gainRate = 1, phaseRate = 2, windowBits = 6, harmonicRate = 3,
    pllKp = 4, pllKv = 9, pllKf = 6, lockBits = 4, minSpeedShift = 6, lockShift = 3)
  val configs: Seq[CorrectedSubdivParams] = Seq(
    CorrectedSubdivParams(fast, SubdivParams(inputBits = 16, counts = 4096, asinAmplitude = math.sqrt(0.5))),
    CorrectedSubdivParams(fast.copy(outputBits = 14, harmonicEntries = 16, tableBits = 18),
      SubdivParams(inputBits = 14, method = PhaseMethod.AsinDouble, counts = 256, asinAmplitude = math.sqrt(0.5)),
      AdcFormat.TwosComplement))
  val imperfect = SignalParams(amplitude = 0.85, offsetSin = 0.02, offsetCos = -0.02, gainCos = 0.97, phaseErrorDeg = 5,
    harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01)), noiseRms = 0.5 / 2048)

  "CorrectedSubdivider RTL" should s"equal the chained models every clock (${SimSupport.backendName})" in {
    val cycles = if (SimSupport.hasVerilator) 16000 else 800
    val stims = configs.zipWithIndex.map { case (p, k) =>
      val adc = Adc(p.adapt.inputBits, p.format)
      val s = SignalSim.generate(imperfect.copy(seed = k + 3), Motion.Oscillate(40, 2000), adc, 50e6, cycles)
      val rnd = new scala.util.Random(k)
      (0 until cycles).map(i => (rnd.nextInt(10) != 0, AdcPinCodes(s.sin(i), s.cos(i), rnd.nextInt(200) == 0, false),
        rnd.nextInt(500) == 0))
    }
    val models = configs.map(new CorrectedSubdivModel(_))
    test(new CorrectedBank(configs)).withAnnotations(SimSupport.backend) { dut =>
      assert(dut.latencies == configs.map(_.latency))
      var checked = 0
      for (t <- 0 until cycles + configs.map(_.latency).max; k <- configs.indices) {
        val (v, pins, clear) = if (t < cycles) stims(k)(t) else (false, AdcPinCodes(0, 0), false)
        val in = dut.io.in(k)
        in.valid.poke(v.B); in.bits.sin.poke(pins.sin.U); in.bits.cos.poke(pins.cos.U)
        in.bits.otrSin.poke(pins.otrSin.B); in.bits.otrCos.poke(pins.otrCos.B)
        dut.io.clear(k).poke(clear.B)
        val e = models(k).clock(v, pins, clear)
        val o = dut.io.out(k)
        assert(o.valid.peekBoolean() == e.valid, s"config $k cycle $t valid")
        if (e.valid) {
          val got = SubdivResult(o.bits.position.peekInt().toLong, o.bits.periods.peekInt().toLong, o.bits.m.peekInt().toLong,
            o.bits.phase.peekInt().toLong, o.bits.present.peekBoolean(), o.bits.overRange.peekBoolean(), o.bits.stepFault.peekBoolean())
          assert(got == e.out, s"config $k cycle $t")
          checked += 1
        }
        assert(dut.io.a(k).peekBoolean() == e.a && dut.io.b(k).peekBoolean() == e.b && dut.io.z(k).peekBoolean() == e.z,
          s"config $k cycle $t A/B/Z")
        if (k == configs.size - 1) dut.clock.step()
      }
      assert(checked > cycles)
      assert(models.forall(_.adapt.periods > 5), "the corrector never updated its estimates")
    }
  }

  "The corrected chain" should "subdivide imperfect signals far better than the plain subdivider" in {
    val r = CorrectedSubdivAccuracy.run(CorrectedSubdivParams(), imperfect, 500e3, samples = 300000)
    info(f"M=4096 at 500 kHz: corrected ${r.corrected}%.3f counts, plain ${r.plain}%.3f counts")
    assert(r.plain > 5 * r.bound, "the imperfections must matter without correction")
    assert(r.corrected < r.bound, f"corrected error ${r.corrected}%.3f counts above ${r.bound}%.3f")
  }
}

/** Several chains side by side, so one simulator build checks a sweep. */
class CorrectedBank(val cs: Seq[CorrectedSubdivParams]) extends Module {
  import chisel3.util._
  import moire.subdiv.{AdcPins, SubdivOut}
  val io = IO(new Bundle {
    val in = Input(MixedVec(cs.map(c => Valid(new AdcPins(c.adapt.inputBits)))))
    val clear = Input(Vec(cs.size, Bool()))
    val out = Output(MixedVec(cs.map(c => Valid(new SubdivOut(c.subdiv)))))
    val a = Output(Vec(cs.size, Bool()))
    val b = Output(Vec(cs.size, Bool()))
    val z = Output(Vec(cs.size, Bool()))
  })
  val latencies: Seq[Int] = cs.zipWithIndex.map { case (p, i) =>
    val m = Module(new CorrectedSubdivider(p))
    m.io.in := io.in(i); m.io.clearStatus := io.clear(i)
    io.out(i) := m.io.out; io.a(i) := m.io.a; io.b(i) := m.io.b; io.z(i) := m.io.z
    m.latency
  }
}
