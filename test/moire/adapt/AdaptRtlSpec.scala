package moire.adapt

import chisel3._
import chiseltest._
import moire.cordic.SimSupport
import moire.signal._
import org.scalatest.flatspec.AnyFlatSpec

/** RTL against the clock-accurate model, bit for bit, over a sweep of parameters, with valid gaps,
  * direction reversals and fast adaptation so that every loop (offsets, gains, phase, table, PLL)
  * moves during the run.
  */
class AdaptRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** Treadle (no Verilator) is slow on this design: a short run of two configurations there. */
  val cycles: Int = if (SimSupport.hasVerilator) 12000 else 600

  /** Fast loops: they converge within a few thousand samples. */
  val fast = AdaptParams(offsetRate = 1, gainRate = 1, phaseRate = 2, windowBits = 6, harmonicRate = 3,
    pllKp = 4, pllKv = 9, pllKf = 6, lockBits = 4, minSpeedShift = 6, lockShift = 3)
  val sweep: Seq[AdaptParams] = Seq(
    fast,
    fast.copy(inputBits = 10, outputBits = 14, harmonicEntries = 16, interpBits = 4, cordicIterations = 12, angleBits = 16, tableBits = 18),
    fast.copy(inputBits = 14, outputBits = 18, mulFrac = 2, harmonicEntries = 0, gainBits = 26, phaseBits = 16),
    fast.copy(harmonicEntries = 128, tableBits = 20, fineGuard = 6, meanShift = 2, periodBits = 10, initialAmplitude = 0.5),
    AdaptParams()).take(if (SimSupport.hasVerilator) 5 else 2)

  /** Signal for configuration k: imperfect, 2 MHz-ish fringes, reversing for odd k; valid low 1 in 8 for k >= 2. */
  def stimulus(p: AdaptParams, k: Int): Seq[(Option[(Long, Long)], (Boolean, Boolean))] = {
    val adc = Adc(p.inputBits, AdcFormat.TwosComplement)
    val sp = SignalParams(amplitude = 0.85, offsetSin = 0.03, offsetCos = -0.01, gainCos = 0.95, phaseErrorDeg = -4,
      harmonics = Seq(Harmonic(2, 0.02), Harmonic(3, 0.01, 30)), noiseRms = adc.lsb, seed = k)
    val motion = if (k % 2 == 1) Motion.Oscillate(60, 3000) else Motion.Constant(1.9e6 * (if (k == 2) -1 else 1))
    val s = SignalSim.generate(sp, motion, adc, 50e6, cycles)
    val rnd = new scala.util.Random(k)
    (0 until cycles).map { i =>
      val otr = (rnd.nextInt(50) == 0, rnd.nextInt(50) == 0)
      (if (k >= 2 && rnd.nextInt(8) == 0) None else Some((s.sinSigned(i).toLong, s.cosSigned(i).toLong)), otr)
    }
  }

  "AdaptiveCorrector RTL" should s"equal the model bit for bit over ${sweep.size} configurations (${SimSupport.backendName})" in {
    val stim = sweep.zipWithIndex.map { case (p, k) => stimulus(p, k) }
    val models = sweep.map(new AdaptModel(_))
    test(new AdaptBank(sweep)).withAnnotations(SimSupport.backend) { dut =>
      assert(dut.latencies == sweep.map(_.latency))
      var checked = 0
      for (t <- 0 until cycles + sweep.map(_.latency).max) {
        for (k <- sweep.indices) {
          val (in, otr) = if (t < cycles) stim(k)(t) else (None, (false, false))
          dut.io.in(k).valid.poke(in.isDefined.B)
          val (s, c) = in.getOrElse((0L, 0L))
          dut.io.in(k).bits.sin.poke(s.S)
          dut.io.in(k).bits.cos.poke(c.S)
          dut.io.in(k).bits.otrSin.poke(otr._1.B)
          dut.io.in(k).bits.otrCos.poke(otr._2.B)
        }
        for (k <- sweep.indices) {
          val e = if (t < cycles) models(k).step(stim(k)(t)._1, stim(k)(t)._2) else models(k).step(None)
          val o = dut.io.out(k)
          dut.io.out(k).valid.expect(e.isDefined.B, s"${sweep(k).moduleName} valid at cycle $t")
          e.foreach { w =>
            val got = AdaptOut(o.bits.sin.peekInt().toLong, o.bits.cos.peekInt().toLong,
              o.bits.otrSin.peekBoolean(), o.bits.otrCos.peekBoolean())
            assert(got == w, s"${sweep(k).moduleName} cycle $t: rtl $got, model $w")
            checked += 1
          }
        }
        dut.clock.step()
      }
      // The run must have moved every loop, or it checked little.
      for ((m, k) <- models.zipWithIndex.take(4)) {
        assert(m.periods > 5, s"config $k: only ${m.periods} estimator updates")
        if (sweep(k).harmonicEntries > 0 && k != 1) assert(m.table.exists(_ != 0), s"config $k: the table never moved")
      }
      assert(checked > cycles)
    }
  }
}
