package moire.board.de2115

import chisel3._
import chisel3.util.Cat
import chisel3.experimental.dataview._
import moire.board.{AdcEncoderPins, BoardCore, BoardParams, BoardReset, ClockSource}

/** DE2-115 top level (EP4CE115F29C7, CLOCK_50): clocking, reset, LEDs and digits around the shared
  * [[BoardCore]]. Reset: KEY[0] pressed, PLL not locked, or the first 31 clocks after configuration.
  * ADC clock pins: at 50 MHz the PLL's c1 (pll) or CLOCK_50 itself (logic); at lower rates the
  * core's divider register. Port names and balls: [[De2115Pins]].
  */
class De2115Top(val p: BoardParams) extends RawModule {
  require(p.clockHz == De2115.clockHz, s"clock-hz: the DE2-115 runs at ${De2115.clockHz} Hz (CLOCK_50), got ${p.clockHz}")
  override def desiredName: String = De2115.topName(p)
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
  private val reset = withClock(sysClk)(BoardReset(!pins.KEY(0), locked))
  moire.emit.Unused("keys", pins.KEY(3, 1)) // KEY[3:1] are spare buttons
  private val core = withClockAndReset(sysClk, reset) { Module(new BoardCore(p)) }
  core.io.pins <> pins.viewAsSupertype(new AdcEncoderPins)
  pins.UART_TXD := core.io.txd
  core.io.rxd := pins.UART_RXD
  if (p.adcDivide == 1) {
    pins.SIN_CLK := adcClk50.asBool
    pins.COS_CLK := adcClk50.asBool
  }

  private val s = core.io.status
  pins.LEDG := Cat(s.fifoOverflow, s.dirUp, s.overRange, s.present)
  pins.LEDR := Cat(s.heartbeat, 0.U(13.W), s.cmdError, s.enabled, s.stepFault, s.overspeed)
  withClockAndReset(sysClk, reset) {
    for ((h, i) <- pins.hex.zipWithIndex) h := RegNext(SevenSeg(s.position(4 * i + 3, 4 * i)), "h7f".U(7.W))
  }
}
