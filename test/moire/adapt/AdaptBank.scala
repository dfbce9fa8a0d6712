package moire.adapt

import chisel3._
import chisel3.util._

/** Several correctors side by side, so one simulator build checks a whole parameter sweep. */
class AdaptBank(val ps: Seq[AdaptParams]) extends Module {
  val io = IO(new Bundle {
    val in = Input(MixedVec(ps.map(p => Valid(new AdaptSample(p.inputBits)))))
    val out = Output(MixedVec(ps.map(p => Valid(new AdaptSample(p.outputBits)))))
  })
  val latencies: Seq[Int] = ps.zipWithIndex.map { case (p, i) =>
    val c = Module(new AdaptiveCorrector(p))
    c.io.in := io.in(i)
    io.out(i) := c.io.out
    c.latency
  }
}
