package moire.board.ulx3s

import chisel3._
import moire.board.AdcEncoderPins

/** The ULX3S top-level ports other than clk_25mhz; names are those of [[Ulx3sPins]]. */
class Ulx3sPorts extends AdcEncoderPins {
  /** 1 = on. */
  val led = Output(UInt(8.W))
  /** btn[0] PWRn (0 = pressed); btn[1..6] FIRE1, FIRE2, UP, DOWN, LEFT, RIGHT (1 = pressed). */
  val btn = Input(UInt(7.W))
  /** Serial data to the host (the FTDI's RXD). */
  val ftdi_rxd = Output(Bool())
  /** Serial data from the host (the FTDI's TXD). */
  val ftdi_txd = Input(Bool())
}
