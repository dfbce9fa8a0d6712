package moire.harmonic

import moire.calibration._

import chisel3._
import moire.io._
import chiseltest._
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec

/** Counter plus compensator: the read head moves both ways; each output equals the model at the count. */
class TurntableCompensatorSpec extends AnyFlatSpec with ChiselScalatestTester {
  val p: HarmonicParams = HarmonicParams(lines = 64, subdivision = 16, harmonics = 2, iterations = 12, dataBits = 14, coefWidth = 32, coefFrac = 16)

  "TurntableCompensator" should s"compensate the count it accumulates from A/B pulses (${SimSupport.backendName})" in {
    val slots = Seq(HarmonicSlot.of(p, 1, -11.1, -53.47), HarmonicSlot.of(p, 3, 3000.0, 20.0))
    val model = new HarmonicModel(p)
    val rnd = new scala.util.Random(7)
    val start = 5L
    val pos = Iterator.iterate(start)(x => x + rnd.nextInt(3) - 1).take(800).flatMap(x => Seq.fill(1 + rnd.nextInt(2))(x)).toIndexedSeq
    test(new TurntableCompensator(p)).withAnnotations(SimSupport.backend) { dut =>
      val (a0, b0) = Quadrature.levels(start)
      dut.io.a.poke(a0.B); dut.io.b.poke(b0.B)
      for ((addr, data) <- CoefficientFile.writes(p, slots)) {
        dut.io.reg.we.poke(true.B); dut.io.reg.addr.poke(addr.U); dut.io.reg.data.poke(data.U)
        dut.clock.step()
      }
      dut.io.reg.we.poke(false.B)
      dut.clock.step(dut.latency + 2)
      val mask = (1L << p.countBits) - 1
      var checked = 0
      for ((x, t) <- pos.zipWithIndex) {
        val (a, b) = Quadrature.levels(x)
        dut.io.a.poke(a.B); dut.io.b.poke(b.B)
        if (t >= dut.latency) {
          val theta = (pos(t - dut.latency) - start) & mask
          val e = model(theta, slots)
          dut.io.out.valid.expect(true.B)
          dut.io.out.bits.theta.expect(e.out.U, s"clock $t count $theta")
          dut.io.out.bits.f.expect(e.f.S)
          checked += 1
        }
        dut.clock.step()
      }
      assert(checked > 700)
    }
  }
}
