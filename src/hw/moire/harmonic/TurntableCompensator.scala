package moire.harmonic

import chisel3._
import moire.io.{QuadratureCounter, QuadratureParams}
import chisel3.util._

/** A/B read-head pulses in, compensated angle out: [[QuadratureCounter]] feeding [[HarmonicCompensator]]
  * (seed 001 fig. 3: angle generation and f(theta) compensation). One result per clock; `latency`
  * clocks from an A/B edge at the pins to the result of the new count. Formats in [[HarmonicParams]].
  */
class TurntableCompensator(val p: HarmonicParams, syncStages: Int = 2) extends Module with moire.emit.Latency {
  val q: QuadratureParams = QuadratureParams(p.countBits, syncStages)
  override def desiredName: String = s"Turntable_${p.moduleName.stripPrefix("HarmonicComp_")}_s$syncStages"
  val io = IO(new Bundle {
    val a = Input(Bool())
    val b = Input(Bool())
    val reg = Input(new HarmonicRegPort(p))
    val out = Valid(new HarmonicResult(p))
    /** The raw count, `q.latency` clocks after the pins. */
    val count = Output(UInt(p.countBits.W))
    /** A skipped quadrature phase (two edges in one clock): the count may be off by two. */
    val error = Output(Bool())
  })
  private val counter = Module(new QuadratureCounter(q))
  private val comp = Module(new HarmonicCompensator(p))
  counter.io.a := io.a
  counter.io.b := io.b
  comp.io.reg := io.reg
  comp.io.in := counter.io.out
  io.out := comp.io.out
  io.count := counter.io.out.bits
  io.error := counter.io.error
  val latency: Int = q.latency + p.latency
}
