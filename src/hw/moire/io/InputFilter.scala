package moire.io

import chisel3._
import chisel3.util._

/** Two-flop synchronizer for an asynchronous input; latency 2 clocks. `init` is the level after reset. */
object Synchronizer {
  def apply(x: Bool, init: Boolean, name: String): Bool = {
    val s0 = RegNext(x, init.B).suggestName(s"${name}_sync0")
    val s1 = RegNext(s0, init.B).suggestName(s"${name}_sync1")
    s1
  }
}

/** Glitch filter: the output takes the input's level once the input has been stable for `length`
  * consecutive clocks; shorter pulses are ignored. Latency `length` clocks. Input must be synchronous.
  */
class GlitchFilter(val length: Int, val init: Boolean = false) extends Module {
  require(length >= 1 && length <= 65536, s"glitch-filter length must be in 1..65536, got $length")
  override def desiredName: String = s"GlitchFilter_l$length"
  val io = IO(new Bundle {
    val in = Input(Bool())
    val out = Output(Bool())
  })
  val latency: Int = length
  private val out = RegInit(init.B)
  private val cnt = RegInit(0.U(log2Ceil(length + 1).W))
  when(io.in === out) {
    cnt := 0.U
  }.elsewhen(cnt === (length - 1).U) {
    out := io.in
    cnt := 0.U
  }.otherwise { cnt := cnt + 1.U }
  io.out := out
}

object GlitchFilter {
  /** Synchronizer then filter. */
  def apply(x: Bool, length: Int, init: Boolean, name: String): Bool = {
    val f = Module(new GlitchFilter(length, init)).suggestName(s"${name}_filter")
    f.io.in := Synchronizer(x, init, name)
    f.io.out
  }
}
