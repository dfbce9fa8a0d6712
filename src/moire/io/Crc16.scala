package moire.io

import chisel3._
import chisel3.util._

/** CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, xorout 0): the stream v1 checksum. */
object Crc16 {
  val init: Int = 0xFFFF

  /** Scala reference: the CRC after one more byte. */
  def update(crc: Int, byte: Int): Int = {
    var c = crc ^ ((byte & 0xFF) << 8)
    for (_ <- 0 until 8) c = if ((c & 0x8000) != 0) ((c << 1) ^ 0x1021) & 0xFFFF else (c << 1) & 0xFFFF
    c
  }
  def of(bytes: Seq[Int]): Int = bytes.foldLeft(init)(update)

  /** Hardware: the CRC after one more byte (eight unrolled shift steps, combinational). */
  def next(crc: UInt, byte: UInt): UInt = {
    var c = crc ^ Cat(byte(7, 0), 0.U(8.W))
    for (_ <- 0 until 8) c = Mux(c(15), (c(14, 0) ## 0.U(1.W)) ^ 0x1021.U(16.W), c(14, 0) ## 0.U(1.W))
    c(15, 0)
  }
}
