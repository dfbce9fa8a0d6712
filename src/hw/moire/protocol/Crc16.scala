package moire.protocol

import chisel3._
import chisel3.util.Cat

/** CRC-16/CCITT-FALSE, the stream v1 checksum: poly 0x1021, init 0xFFFF, no reflection, xorout 0
  * (check value 0x29B1 for "123456789"). `step`/`of` are the Scala reference, `next` the hardware.
  */
object Crc16 {
  val Init: Int = 0xFFFF
  val Poly: Int = 0x1021

  /** The CRC register after one more byte. */
  def step(crc: Int, b: Int): Int = {
    var c = crc ^ ((b & 0xFF) << 8)
    var i = 0
    while (i < 8) { c = if ((c & 0x8000) != 0) (c << 1) ^ Poly else c << 1; i += 1 }
    c & 0xFFFF
  }

  /** CRC of `len` bytes of `bytes` from `off`. */
  def of(bytes: Array[Byte], off: Int, len: Int): Int = {
    var c = Init; var i = off
    while (i < off + len) { c = step(c, bytes(i)); i += 1 }
    c
  }

  def of(bytes: Array[Byte]): Int = of(bytes, 0, bytes.length)

  /** Hardware: the CRC after one more byte (eight unrolled shift steps, combinational), as `step`. */
  def next(crc: UInt, byte: UInt): UInt = {
    var c = crc ^ Cat(byte(7, 0), 0.U(8.W))
    for (_ <- 0 until 8) c = Mux(c(15), (c(14, 0) ## 0.U(1.W)) ^ Poly.U(16.W), c(14, 0) ## 0.U(1.W))
    c(15, 0)
  }
}
