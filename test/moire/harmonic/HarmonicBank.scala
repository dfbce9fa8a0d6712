package moire.harmonic

import moire.calibration._

import chisel3._
import chisel3.util._

/** Several compensators side by side, so one simulator build checks a whole sweep. */
class HarmonicBank(val ps: Seq[HarmonicParams]) extends Module {
  val io = IO(new Bundle {
    val reg = Input(MixedVec(ps.map(p => new HarmonicRegPort(p))))
    val in = Input(MixedVec(ps.map(p => Valid(UInt(p.countBits.W)))))
    val out = Output(MixedVec(ps.map(p => Valid(new HarmonicResult(p)))))
  })
  val latencies: Seq[Int] = ps.zipWithIndex.map { case (p, i) =>
    val c = Module(new HarmonicCompensator(p))
    c.io.reg := io.reg(i)
    c.io.in := io.in(i)
    io.out(i) := c.io.out
    c.latency
  }
}
