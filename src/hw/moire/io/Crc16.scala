package moire.io

import chisel3._
import chisel3.util._

/** CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, xorout 0) in hardware: the stream v1
  * checksum. The Scala reference is moire.stream.Crc16.
  */
object Crc16 {
  val init: Int = moire.stream.Crc16.Init

  /** Hardware: the CRC after one more byte (eight unrolled shift steps, combinational). */
  def next(crc: UInt, byte: UInt): UInt = {
    var c = crc ^ Cat(byte(7, 0), 0.U(8.W))
    for (_ <- 0 until 8) c = Mux(c(15), (c(14, 0) ## 0.U(1.W)) ^ 0x1021.U(16.W), c(14, 0) ## 0.U(1.W))
    c(15, 0)
  }
}
