package moire.board.de2115

import chisel3._
import chisel3.util.HasBlackBoxResource

/** Cyclone IV E altpll (boards/resources/de2-115/De2115Pll.v): inclk0 50 MHz; c0 = system clock
  * 50 MHz, c1 = AD9226 clock 50 MHz, both at phase 0 (c0 compensated).
  */
class De2115Pll extends BlackBox with HasBlackBoxResource {
  override def desiredName: String = "De2115Pll"
  val io = IO(new Bundle {
    val inclk0 = Input(Clock())
    val areset = Input(Bool())
    val c0 = Output(Clock())
    val c1 = Output(Clock())
    val locked = Output(Bool())
  })
  addResource("/de2-115/De2115Pll.v")
}
