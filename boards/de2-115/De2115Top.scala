package moire.board.de2115

import chisel3._

/** DE2-115 top level (EP4CE115F29C7, CLOCK_50): clocking and reset around [[BoardCore]].
  * Reset: KEY[0] pressed, PLL not locked, or the first 31 clocks after configuration; synchronized.
  * ADC clock pins: at 50 MHz the PLL's c1 (pll) or CLOCK_50 itself (logic); at lower rates the
  * core's divider register. Port names and balls: [[De2115Pins]].
  */
class De2115Top(val p: BoardParams) extends RawModule {
  override def desiredName: String = p.topName
  val CLOCK_50 = IO(Input(Clock()))
  val pins = FlatIO(new De2115Ports)

  private val (sysClk, adcClk50, locked) = p.clockSource match {
    case ClockSource.Pll =>
      val pll = Module(new De2115Pll)
      pll.io.inclk0 := CLOCK_50
      pll.io.areset := false.B
      (pll.io.c0, pll.io.c1, pll.io.locked)
    case ClockSource.Logic => (CLOCK_50, CLOCK_50, true.B)
  }
  private val reset = withClock(sysClk) {
    val por = Reg(UInt(5.W))          // powers up 0 on the FPGA and in the (unrandomized) simulation
    val porDone = por.andR
    when(!porDone) { por := por + 1.U }
    val raw = !pins.KEY(0) || !locked || !porDone
    RegNext(RegNext(raw))
  }
  private val core = withClockAndReset(sysClk, reset) { Module(new BoardCore(p)) }
  core.io <> pins
  if (p.adcDivide == 1) {
    pins.SIN_CLK := adcClk50.asBool
    pins.COS_CLK := adcClk50.asBool
  }
}
