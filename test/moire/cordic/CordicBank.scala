package moire.cordic

import chisel3._
import chisel3.util._

/** Several CORDIC instances side by side, so one simulator build checks a whole sweep. */
class CordicBank(val ps: Seq[CordicParams]) extends Module {
  val io = IO(new Bundle {
    val in = Input(MixedVec(ps.map(p => Valid(new CordicIn(p)))))
    val out = Output(MixedVec(ps.map(p => Valid(new CordicOut(p)))))
  })
  val latencies: Seq[Int] = ps.zipWithIndex.map { case (p, i) =>
    val c = Module(new Cordic(p))
    c.io.in := io.in(i)
    io.out(i) := c.io.out
    c.latency
  }
}
