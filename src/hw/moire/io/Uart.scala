package moire.io

import chisel3._
import chisel3.util._

/** Baud-rate divisor: clock cycles per bit, rounded; the rate error must stay within 2 %. */
object UartDivisor {
  def apply(clockHz: Long, baud: Long): Int = {
    require(baud > 0 && baud <= clockHz / 4, s"baud must be in 1..${clockHz / 4} for a $clockHz Hz clock, got $baud")
    val d = math.round(clockHz.toDouble / baud).toInt
    val err = math.abs(clockHz.toDouble / d - baud) / baud
    require(err <= 0.02, f"baud $baud is ${err * 100}%.1f %% off with a $clockHz Hz clock (divisor $d); at most 2 %% allowed")
    d
  }
}

/** UART transmitter, 8N1, `divisor` clocks per bit. Line idles high. Takes a byte when ready. */
class UartTx(val divisor: Int) extends Module {
  require(divisor >= 4, s"divisor must be >= 4, got $divisor")
  override def desiredName: String = s"UartTx_d$divisor"
  val io = IO(new Bundle {
    val in = Flipped(Decoupled(UInt(8.W)))
    val txd = Output(Bool())
  })
  private val shift = RegInit(0x3FF.U(10.W))
  private val bits = RegInit(0.U(4.W))
  private val timer = RegInit(0.U(log2Ceil(divisor + 1).W))
  io.in.ready := bits === 0.U
  when(io.in.fire) {
    shift := Cat(1.U(1.W), io.in.bits, 0.U(1.W))
    bits := 10.U
    timer := (divisor - 1).U
  }.elsewhen(bits =/= 0.U) {
    when(timer === 0.U) {
      shift := Cat(1.U(1.W), shift(9, 1))
      bits := bits - 1.U
      timer := (divisor - 1).U
    }.otherwise { timer := timer - 1.U }
  }
  io.txd := RegNext(Mux(bits === 0.U, true.B, shift(0)), true.B)
}

/** UART receiver, 8N1, `divisor` clocks per bit; `rxd` must already be synchronized. A start bit is
  * confirmed at its middle, data bits are sampled at their middles, a byte with a low stop bit is
  * dropped and pulses `frameError`. Latency: the byte is valid one clock after the middle of the stop bit.
  */
class UartRx(val divisor: Int) extends Module {
  require(divisor >= 4, s"divisor must be >= 4, got $divisor")
  override def desiredName: String = s"UartRx_d$divisor"
  val io = IO(new Bundle {
    val rxd = Input(Bool())
    val out = Valid(UInt(8.W))
    val frameError = Output(Bool())
  })
  private val busy = RegInit(false.B)
  private val timer = RegInit(0.U(log2Ceil(divisor + 1).W))
  private val bit = RegInit(0.U(4.W))
  private val data = RegInit(0.U(8.W))
  private val outV = RegInit(false.B)
  private val ferr = RegInit(false.B)
  outV := false.B
  ferr := false.B
  when(!busy) {
    when(!io.rxd) { busy := true.B; timer := (divisor / 2 - 1).U; bit := 0.U }
  }.elsewhen(timer =/= 0.U) {
    timer := timer - 1.U
  }.otherwise {
    timer := (divisor - 1).U
    when(bit === 0.U) {
      when(io.rxd) { busy := false.B }.otherwise { bit := 1.U }
    }.elsewhen(bit <= 8.U) {
      data := Cat(io.rxd, data(7, 1))
      bit := bit + 1.U
    }.otherwise {
      busy := false.B
      outV := io.rxd
      ferr := !io.rxd
    }
  }
  io.out.valid := outV
  io.out.bits := data
  io.frameError := ferr
}
