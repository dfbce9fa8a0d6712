package moire.harmonic

import moire.calibration._

import chisel3._
import moire.io._
import chiseltest._
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec

/** The counter follows a random walk of the read head (both directions, wrap-around) and flags skipped phases. */
class QuadratureCounterSpec extends AnyFlatSpec with ChiselScalatestTester {
  for (p <- Seq(QuadratureParams(countBits = 6), QuadratureParams(countBits = 24, syncStages = 3))) {
    s"${p.moduleName}" should s"count every A/B edge in both directions and wrap modulo 2^${p.countBits} (${SimSupport.backendName})" in {
      val rnd = new scala.util.Random(p.countBits)
      // Position per clock: holds for 1..3 clocks, then moves by one either way; starts below zero to wrap.
      val start = -3L
      val pos = Iterator.iterate(start)(x => x + (if (rnd.nextBoolean()) 1 else -1))
        .take(3000).flatMap(x => Seq.fill(1 + rnd.nextInt(3))(x)).toIndexedSeq
      test(new QuadratureCounter(p)).withAnnotations(SimSupport.backend) { dut =>
        val (a0, b0) = Quadrature.levels(start)
        dut.io.a.poke(a0.B); dut.io.b.poke(b0.B)
        dut.clock.step(p.latency + 2)
        val mask = (1L << p.countBits) - 1
        for ((x, t) <- pos.zipWithIndex) {
          val (a, b) = Quadrature.levels(x)
          dut.io.a.poke(a.B); dut.io.b.poke(b.B)
          if (t >= p.latency) {
            dut.io.out.valid.expect(true.B)
            dut.io.out.bits.expect(((pos(t - p.latency) - start) & mask).U, s"clock $t")
            dut.io.error.expect(false.B)
          }
          dut.clock.step()
        }
        // a jump of two phases in one clock keeps the count and flags it
        val last = pos.last
        dut.clock.step(p.latency)
        val before = dut.io.out.bits.peekInt()
        val (a2, b2) = Quadrature.levels(last + 2)
        dut.io.a.poke(a2.B); dut.io.b.poke(b2.B)
        dut.clock.step(p.latency)
        dut.io.error.expect(true.B)
        dut.io.out.bits.expect(before.U)
        dut.clock.step()
        dut.io.error.expect(false.B)
      }
    }
  }
}
