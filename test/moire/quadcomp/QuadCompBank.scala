package moire.quadcomp

import chisel3._
import chisel3.util._

/** Several compensators side by side, so one simulator build checks a whole sweep. */
class QuadCompBank(val ps: Seq[QuadCompParams]) extends Module {
  val io = IO(new Bundle {
    val in = Input(MixedVec(ps.map(p => Valid(new QuadCompIn(p)))))
    val gainSin = Input(MixedVec(ps.map(p => UInt(p.gainBits.W))))
    val gainCos = Input(MixedVec(ps.map(p => UInt(p.gainBits.W))))
    val out = Output(MixedVec(ps.map(p => Valid(new QuadCompOut(p)))))
    val diff = Output(MixedVec(ps.map(p => Valid(SInt(p.angleBits.W)))))
  })
  val latencies: Seq[Int] = ps.zipWithIndex.map { case (p, i) =>
    val c = Module(new QuadComp(p))
    c.io.in := io.in(i)
    c.io.gainSin := io.gainSin(i)
    c.io.gainCos := io.gainCos(i)
    io.out(i) := c.io.out
    io.diff(i) := c.io.diff
    c.latency
  }
}
