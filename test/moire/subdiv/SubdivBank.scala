package moire.subdiv

import chisel3._
import chisel3.util._
import moire.signal.AdcFormat

/** Several board-facing subdividers side by side, so one simulator build checks a whole sweep. */
class SubdivBank(val cs: Seq[(SubdivParams, AdcFormat)]) extends Module {
  val io = IO(new Bundle {
    val in = Input(MixedVec(cs.map(c => Valid(new AdcPins(c._1.inputBits)))))
    val clear = Input(Vec(cs.size, Bool()))
    val out = Output(MixedVec(cs.map(c => Valid(new SubdivOut(c._1)))))
    val a = Output(Vec(cs.size, Bool()))
    val b = Output(Vec(cs.size, Bool()))
    val z = Output(Vec(cs.size, Bool()))
    val status = Output(MixedVec(cs.map(c => new SubdivStatus(c._1))))
  })
  val latencies: Seq[Int] = cs.zipWithIndex.map { case ((p, f), i) =>
    val s = Module(new SubdivAdc(p, f))
    s.io.in := io.in(i)
    s.io.clearStatus := io.clear(i)
    io.out(i) := s.io.out
    io.a(i) := s.io.a; io.b(i) := s.io.b; io.z(i) := s.io.z
    io.status(i) := s.io.status
    s.latency
  }
}
