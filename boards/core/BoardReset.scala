package moire.board

import chisel3._

/** The reset of a board top on the clock in scope: the reset button, the PLL not locked, or the
  * first 31 clocks after configuration; synchronized over two registers.
  */
object BoardReset {
  def apply(pressed: Bool, locked: Bool): Bool = {
    val por = Reg(UInt(5.W))          // powers up 0 on the FPGA and in the (unrandomized) simulation
    val porDone = por.andR
    when(!porDone) { por := por + 1.U }
    RegNext(RegNext(pressed || !locked || !porDone))
  }
}
