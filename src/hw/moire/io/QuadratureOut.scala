package moire.io

import chisel3._
import chisel3.util._

/** A/B/Z outputs that follow a position one count at a time, edges at least `minEdgeClocks` apart, so a
  * downstream quadrature counter never sees a skipped phase; Z is high while the followed position is a
  * multiple of 2^zBits. Starts at the first valid position.
  */
class QuadratureOut(val width: Int, val zBits: Int, val minEdgeClocks: Int = 1) extends Module {
  require(width >= 2 && zBits >= 2 && zBits <= width && minEdgeClocks >= 1)
  override def desiredName: String = s"QuadratureOut_w${width}_z${zBits}_e$minEdgeClocks"
  val io = IO(new Bundle {
    val in = Flipped(Valid(SInt(width.W)))
    val a = Output(Bool())
    val b = Output(Bool())
    val z = Output(Bool())
    /** Counts still to be output (signed). */
    val backlog = Output(SInt(width.W))
  })
  private val started = RegInit(false.B)
  private val target = RegInit(0.S(width.W))
  private val pos = RegInit(0.S(width.W))
  private val holdOff = RegInit(0.U(log2Ceil(minEdgeClocks + 1).W))
  // pos + 1 and pos - 1 kept beside it, and pending =/= 0 as an equality: a step is the subtract's sign bit
  // choosing a register, not an add after a compare
  private val posUp = RegInit(1.S(width.W))
  private val posDn = RegInit(-1.S(width.W))
  private def wrap(v: SInt): SInt = v(width - 1, 0).asSInt
  private val pending = wrap(target - pos)
  moire.emit.Unused("pending", pending) // a step reads only its sign bit; a board may leave backlog open
  when(io.in.valid) { target := io.in.bits }
  when(!started) {
    when(io.in.valid) { pos := io.in.bits; posUp := wrap(io.in.bits + 1.S); posDn := wrap(io.in.bits - 1.S); started := true.B }
  }.elsewhen(holdOff === 0.U && target =/= pos) {
    val up = !pending(width - 1)
    pos := Mux(up, posUp, posDn)
    posUp := Mux(up, wrap(posUp + 1.S), pos)
    posDn := Mux(up, pos, wrap(posDn - 1.S))
    holdOff := (minEdgeClocks - 1).U
  }.elsewhen(holdOff =/= 0.U) { holdOff := holdOff - 1.U }
  private val q = pos(1, 0)
  io.a := q === 1.U || q === 2.U
  io.b := q(1)
  io.z := started && pos(zBits - 1, 0) === 0.U
  io.backlog := Mux(started, pending, 0.S)
}
