package moire.board.de2115

import chisel3._
import moire.board.AdcEncoderPins

/** The DE2-115 top-level ports other than CLOCK_50; names are those of [[De2115Pins]]. */
class De2115Ports extends AdcEncoderPins {
  val KEY = Input(UInt(4.W))
  val LEDR = Output(UInt(18.W))
  val LEDG = Output(UInt(9.W))
  val HEX0 = Output(UInt(7.W))
  val HEX1 = Output(UInt(7.W))
  val HEX2 = Output(UInt(7.W))
  val HEX3 = Output(UInt(7.W))
  val HEX4 = Output(UInt(7.W))
  val HEX5 = Output(UInt(7.W))
  val HEX6 = Output(UInt(7.W))
  val HEX7 = Output(UInt(7.W))
  val UART_TXD = Output(Bool())
  val UART_RXD = Input(Bool())
  def hex: Seq[UInt] = Seq(HEX0, HEX1, HEX2, HEX3, HEX4, HEX5, HEX6, HEX7)
}

/** Seven-segment patterns, segment 0 = a ... 6 = g; the DE2-115 digits light a segment on 0. */
object SevenSeg {
  val lit: Seq[Int] = Seq(0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71)
  /** Active-low segments of a hex digit (Scala, for tests). */
  def activeLow(nibble: Int): Int = ~lit(nibble & 0xF) & 0x7F
  def apply(nibble: UInt): UInt = VecInit(lit.map(v => (~v & 0x7F).U(7.W)))(nibble)
}
