package moire.harmonic

import moire.calibration._

import chisel3._
import chiseltest._
import moire.cordic.SimSupport
import moire.cordic.PaperBounds
import org.scalatest.flatspec.AnyFlatSpec

/** RTL against the bit-accurate model, bit for bit, over a sweep of configurations, and seed 001
  * sec. 4.1 (eq. 19, 10,000 angles, n = 16, b = 18) measured on the RTL outputs.
  */
class HarmonicRtlSpec extends AnyFlatSpec with ChiselScalatestTester {
  /** One configuration of the sweep: its params, coefficients and input angles. */
  case class Case(p: HarmonicParams, slots: Seq[HarmonicSlot], thetas: Seq[Long])

  val count: Int = if (SimSupport.hasVerilator) 1500 else 200

  def randomCase(p: HarmonicParams, seed: Int): Case = {
    val rnd = new scala.util.Random(seed)
    val lo = -(1L << (p.coefWidth - 1))
    val slots = Seq.tabulate(p.harmonics) { j =>
      val c = if (j == 0) lo else lo + (rnd.nextLong() >>> 1) % (1L << p.coefWidth) // full-scale negative once
      HarmonicSlot(if (j == 0) p.maxOrder else rnd.nextInt(p.maxOrder + 1), c, rnd.nextLong() >>> (64 - p.countBits))
    }
    val turn = 1L << p.countBits
    val edges = Seq(0L, 1L, turn - 1, turn / 2, turn / 4, 3 * turn / 4)
    Case(p, slots, edges ++ Seq.fill(count)(rnd.nextLong() >>> (64 - p.countBits)))
  }

  val eq19 = Case(HarmonicReproduce.paperParams, HarmonicReproduce.eq19Slots(HarmonicReproduce.paperParams),
    HarmonicReproduce.angles(HarmonicReproduce.paperParams))
  val sweep: Seq[Case] = Seq(
    eq19,
    randomCase(HarmonicParams(), 1),
    randomCase(HarmonicParams(lines = 16, subdivision = 64, harmonics = 1, iterations = 10, dataBits = 12,
      coefWidth = 16, coefFrac = 8, maxOrder = 7, outFrac = 4, kFrac = 12), 2),
    randomCase(HarmonicParams(lines = 4096, subdivision = 256, harmonics = 3, iterations = 12, dataBits = 14,
      coefWidth = 24, coefFrac = 12, maxOrder = 31, outFrac = 0, pipelineEvery = 3), 3),
    randomCase(HarmonicParams(lines = 1 << 20, subdivision = 4096, harmonics = 6, iterations = 20, dataBits = 22,
      coefWidth = 32, coefFrac = 16, maxOrder = 1000, outFrac = 20, kFrac = 32), 4))

  /** Register writes (address, data) that load the slots, with junk first: every register written with
    * all ones, unused addresses (field 3, slots beyond m) written with all ones, then the real words.
    */
  def writes(p: HarmonicParams, slots: Seq[HarmonicSlot]): Seq[(Int, Long)] = {
    val ones = (1L << p.regWidth) - 1
    val junk = (0 until (1 << p.addrBits)).map(_ -> ones)
    val unused = (0 until (1 << p.addrBits)).filter(a => a % 4 == 3 || a / 4 >= p.harmonics).map(_ -> 0x5a5a5a5aL)
    junk ++ CoefficientFile.writes(p, slots) ++ unused
  }

  "HarmonicCompensator RTL" should s"equal the model bit for bit over the sweep and meet P_max on eq. 19 (${SimSupport.backendName})" in {
    val models = sweep.map(c => new HarmonicModel(c.p))
    test(new HarmonicBank(sweep.map(_.p))).withAnnotations(SimSupport.backend) { dut =>
      // load coefficients
      val ws = sweep.map(c => writes(c.p, c.slots))
      for (t <- 0 until ws.map(_.size).max) {
        for (k <- sweep.indices) {
          val live = t < ws(k).size
          dut.io.reg(k).we.poke(live.B)
          dut.io.reg(k).addr.poke((if (live) ws(k)(t)._1 else 0).U)
          dut.io.reg(k).data.poke((if (live) ws(k)(t)._2 else 0L).U)
          dut.io.in(k).valid.poke(false.B)
        }
        dut.clock.step()
      }
      for (k <- sweep.indices) dut.io.reg(k).we.poke(false.B)
      val lat = dut.latencies
      assert(lat == sweep.map(_.p.latency))
      var worst = 0.0
      val cycles = sweep.map(_.thetas.size).max + lat.max + 1
      for (t <- 0 until cycles) {
        for (k <- sweep.indices) {
          val v = sweep(k).thetas
          val live = t < v.size
          dut.io.in(k).valid.poke(live.B)
          dut.io.in(k).bits.poke((if (live) v(t) else 0L).U)
        }
        for (k <- sweep.indices) {
          val c = sweep(k)
          val src = t - lat(k)
          val expectValid = src >= 0 && src < c.thetas.size
          dut.io.out(k).valid.expect(expectValid.B, s"${c.p.moduleName} valid at cycle $t")
          if (expectValid) {
            val theta = c.thetas(src)
            val e = models(k)(theta, c.slots)
            val got = HarmonicOut(dut.io.out(k).bits.f.peekInt().toLong, dut.io.out(k).bits.theta.peekInt().toLong)
            assert(got == e, s"${c.p.moduleName} theta $theta: rtl $got, model $e")
            if (k == 0) worst = math.max(worst, HarmonicReproduce.error(c.p, models(k), theta, got.out))
          }
        }
        dut.clock.step()
      }
      val sumC = PaperBounds.seed001Eq19.map(c => math.abs(c._2)).sum
      val pmax = math.min(PaperBounds.seed001Pmax(16, 18, sumC), 1.19e-3) // eq. 16, and the paper's printed value
      info(f"eq. 19 over 10,000 angles: RTL max error $worst%.4e arcsec (P_max $pmax%.4e, paper 9.36e-4)")
      assert(worst > 0 && worst < pmax, f"max error $worst%.4e arcsec, P_max $pmax%.4e")
    }
  }
}
