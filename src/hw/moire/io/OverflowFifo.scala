package moire.io

import chisel3._
import chisel3.util._

/** FIFO for a stream that cannot wait: a word offered while the FIFO is full is dropped and
  * counted (`dropped` pulses), never lost silently. `count` = words held. Latency 1 clock; storage in a synchronous-read memory (FPGA block RAM).
  */
class OverflowFifo(val width: Int, val depth: Int) extends Module {
  require(width >= 1, s"width must be >= 1, got $width")
  require(depth >= 1 && depth <= 65536, s"FIFO depth must be in 1..65536, got $depth")
  override def desiredName: String = s"OverflowFifo_w${width}_d$depth"
  val io = IO(new Bundle {
    val in = Flipped(Valid(UInt(width.W)))
    val out = Decoupled(UInt(width.W))
    val count = Output(UInt(log2Ceil(depth + 1).W))
    val dropped = Output(Bool())
  })
  private val q = Module(new Queue(UInt(width.W), depth, useSyncReadMem = true))
  q.io.enq.valid := io.in.valid
  q.io.enq.bits := io.in.bits
  io.out <> q.io.deq
  io.count := q.io.count
  io.dropped := io.in.valid && !q.io.enq.ready
}
