package moire.board.ulx3s

import chisel3._
import chisel3.experimental.dataview._
import chisel3.util.Cat
import moire.board.{AdcEncoderPins, BoardCore, BoardParams, BoardReset, ClockSource}

/** ULX3S top level (LFE5U-85F, 25 MHz oscillator): clocking, reset and LEDs around the shared
  * [[BoardCore]]. Clocks: pll = an EHXPLLL makes the system clock and the AD9226 clock (same
  * frequency and phase) from clk_25mhz; logic = clk_25mhz is the system clock (clockHz 25 MHz).
  * Reset: FIRE1 (btn[1]) pressed, PLL not locked, or the first 31 clocks after configuration.
  * LEDs 0..7: present, over range or OTR (sticky), direction up, FIFO overflow (sticky), overspeed,
  * step fault, command error, heartbeat. Port names and sites: [[Ulx3sPins]].
  */
class Ulx3sTop(val p: BoardParams) extends RawModule {
  override def desiredName: String = Ulx3s.topName(p)
  val clk_25mhz = IO(Input(Clock()))
  val pins = FlatIO(new Ulx3sPorts)

  private val (sysClk, adcClkFull, locked) = p.clockSource match {
    case ClockSource.Pll =>
      val pll = Module(new Ulx3sPll(Ulx3s.pll(p)))
      pll.io.clkin := clk_25mhz
      (pll.io.clkSys, pll.io.clkAdc, pll.io.locked)
    case ClockSource.Logic =>
      require(p.clockHz == Ulx3s.oscillatorHz,
        s"clock-hz: with clock source logic the ULX3S runs on its ${Ulx3s.oscillatorHz} Hz oscillator, got ${p.clockHz}")
      (clk_25mhz, clk_25mhz, true.B)
  }
  private val reset = withClock(sysClk)(BoardReset(pins.btn(1), locked))
  moire.emit.Unused("buttons", pins.btn(6, 2), pins.btn(0)) // btn[0] (PWR) and btn[6:2] are spare
  private val core = withClockAndReset(sysClk, reset) { Module(new BoardCore(p)) }
  core.io.pins <> pins.viewAsSupertype(new AdcEncoderPins)
  pins.ftdi_rxd := core.io.txd
  core.io.rxd := pins.ftdi_txd
  if (p.adcDivide == 1) {
    pins.SIN_CLK := adcClkFull.asBool
    pins.COS_CLK := adcClkFull.asBool
  }
  private val s = core.io.status
  pins.led := Cat(s.heartbeat, s.cmdError, s.stepFault, s.overspeed, s.fifoOverflow, s.dirUp, s.overRange, s.present)
}
