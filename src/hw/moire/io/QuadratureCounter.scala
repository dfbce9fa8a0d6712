package moire.io

import chisel3._
import chisel3.util._

/** Parameters of the A/B quadrature up/down counter.
  * @param countBits counter width; it wraps modulo 2^countBits (one turn when that equals lines * subdivision)
  * @param syncStages flip-flops on each asynchronous input (2 or more)
  */
case class QuadratureParams(countBits: Int = 24, syncStages: Int = 2) {
  require(countBits >= 2 && countBits <= 32, s"count-bits must be in 2..32, got $countBits")
  require(syncStages >= 2 && syncStages <= 4, s"sync-stages must be in 2..4, got $syncStages")
  /** Clocks from an A/B edge at the pins to the count: synchronizer plus the counter register. */
  val latency: Int = syncStages + 1
  def moduleName: String = s"QuadCounter_c${countBits}_s$syncStages"
}

/** The quadrature phase 0..3 of (A, B): 00 -> 10 -> 11 -> 01 counts up (A leads B). */
object Quadrature {
  def phase(a: Boolean, b: Boolean): Int = (if (b) 2 else 0) | (if (a ^ b) 1 else 0)
  /** A/B levels of a position (up counting order). */
  def levels(pos: Long): (Boolean, Boolean) = Math.floorMod(pos, 4L).toInt match {
    case 0 => (false, false)
    case 1 => (true, false)
    case 2 => (true, true)
    case _ => (false, true)
  }
}

/** Quadrature up/down counter for the turntable read head's A/B pulses (seed 001 fig. 3, angle
  * generation). Inputs go through `syncStages` flip-flops; each valid edge moves the count by one;
  * a jump of two phases in one clock (both lines changed: motion too fast or noise) keeps the count
  * and pulses `error`. `out.valid` is high every clock after reset (the count as a Valid stream for
  * [[HarmonicCompensator]]). Latency `p.latency` clocks from pin to count.
  */
class QuadratureCounter(val p: QuadratureParams) extends Module with moire.emit.Latency {
  override def desiredName: String = p.moduleName
  val io = IO(new Bundle {
    val a = Input(Bool())
    val b = Input(Bool())
    val out = Valid(UInt(p.countBits.W))
    val error = Output(Bool())
  })
  val latency: Int = p.latency
  private def sync(x: Bool, name: String): Bool = {
    val s = ShiftRegister(x, p.syncStages, false.B, true.B)
    s.suggestName(name)
    s
  }
  private val a = sync(io.a, "a_sync")
  private val b = sync(io.b, "b_sync")
  private val phase = Cat(b, a ^ b)
  private val last = RegNext(phase, 0.U(2.W))
  private val primed = ShiftRegister(true.B, p.syncStages + 1, false.B, true.B)
  private val delta = phase - last
  private val count = RegInit(0.U(p.countBits.W))
  private val err = RegInit(false.B)
  err := false.B
  when(primed) {
    switch(delta) {
      is(1.U) { count := count + 1.U }
      is(3.U) { count := count - 1.U }
      is(2.U) { err := true.B }
    }
  }
  io.out.bits := count
  io.out.valid := primed
  io.error := err
}
