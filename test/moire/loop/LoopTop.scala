package moire.loop

import chisel3._
import chisel3.util.Cat
import moire.board.{AdcEncoderPins, BoardParams}
import moire.board.de2115.De2115Top
import moire.board.ulx3s.Ulx3sTop

/** A board top with plain port names for the loop harness (test/resources/moire/loop/board_loop.cpp):
  * the same ADC, encoder and UART pins on either board; `reset_btn` 1 holds the board's reset button.
  */
class LoopTop(val board: String, val p: BoardParams) extends RawModule {
  override def desiredName: String = "LoopTop"
  val clk = IO(Input(Clock()))
  val reset_btn = IO(Input(Bool()))
  val sin_d = IO(Input(UInt(12.W)))
  val sin_otr = IO(Input(Bool()))
  val cos_d = IO(Input(UInt(12.W)))
  val cos_otr = IO(Input(Bool()))
  val adc_clk = IO(Output(Bool()))
  val enc_a = IO(Input(Bool()))
  val enc_b = IO(Input(Bool()))
  val enc_z = IO(Input(Bool()))
  val uart_in = IO(Input(Bool()))
  val uart_out = IO(Output(Bool()))

  private def adc(pins: AdcEncoderPins): Unit = {
    pins.SIN_D := sin_d; pins.SIN_OTR := sin_otr; pins.COS_D := cos_d; pins.COS_OTR := cos_otr
    pins.ENC_A_IN := enc_a; pins.ENC_B_IN := enc_b; pins.ENC_Z_IN := enc_z
    adc_clk := pins.SIN_CLK
  }
  board match {
    case "de2-115" =>
      val t = Module(new De2115Top(p))
      t.CLOCK_50 := clk
      adc(t.pins)
      t.pins.KEY := Cat(7.U(3.W), !reset_btn)
      t.pins.UART_RXD := uart_in
      uart_out := t.pins.UART_TXD
    case "ulx3s" =>
      val t = Module(new Ulx3sTop(p))
      t.clk_25mhz := clk
      adc(t.pins)
      t.pins.btn := Cat(0.U(5.W), reset_btn, 1.U(1.W)) // btn[0] PWRn released, btn[1] FIRE1 = reset
      t.pins.ftdi_txd := uart_in
      uart_out := t.pins.ftdi_rxd
    case other => throw new IllegalArgumentException(s"LoopTop: unknown board $other")
  }
}
