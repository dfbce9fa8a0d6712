package moire.board

import chisel3._

/** The AD9226 pair and the encoder I/O: the pins every board gives the core, named as in the pin
  * tables of both boards (boards/de2-115/De2115Pins.scala, boards/ulx3s/Ulx3sPins.scala).
  */
class AdcEncoderPins extends Bundle {
  val SIN_D = Input(UInt(12.W))
  val SIN_OTR = Input(Bool())
  val SIN_CLK = Output(Bool())
  val COS_D = Input(UInt(12.W))
  val COS_OTR = Input(Bool())
  val COS_CLK = Output(Bool())
  val ENC_A_IN = Input(Bool())
  val ENC_B_IN = Input(Bool())
  val ENC_Z_IN = Input(Bool())
  val ENC_A_OUT = Output(Bool())
  val ENC_B_OUT = Output(Bool())
  val ENC_Z_OUT = Output(Bool())
}

/** What a harness shows on its LEDs and displays; sticky flags clear with control bit 1. */
class CoreStatus extends Bundle {
  /** Signal present (live). */
  val present = Bool()
  /** Over range (live) or an OTR seen (sticky). */
  val overRange = Bool()
  /** Last movement upwards. */
  val dirUp = Bool()
  /** The record FIFO overflowed (sticky). */
  val fifoOverflow = Bool()
  val overspeed = Bool()
  val stepFault = Bool()
  /** Streaming on (control bit 0). */
  val enabled = Bool()
  /** A command was refused or a reply lost since reset. */
  val cmdError = Bool()
  /** Toggles every 2^24 clocks. */
  val heartbeat = Bool()
  /** The live position (register 0x07). */
  val position = UInt(32.W)
}

/** Ports of [[BoardCore]]: the pins, the UART lines (8N1, stream v1), the status. */
class CoreIO extends Bundle {
  val pins = new AdcEncoderPins
  /** Serial data to the host. */
  val txd = Output(Bool())
  /** Serial data from the host (asynchronous; synchronized in the core). */
  val rxd = Input(Bool())
  val status = Output(new CoreStatus)
}
