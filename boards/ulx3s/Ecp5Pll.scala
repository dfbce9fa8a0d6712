package moire.board.ulx3s

import chisel3._
import chisel3.experimental.IntParam
import chisel3.util.HasBlackBoxResource
import moire.board.Mhz

/** Dividers of an ECP5 EHXPLLL with feedback from CLKOP: f_out = f_in * fbDiv / refDiv and
  * f_vco = f_out * outDiv. CLKOS uses the same divider and phase as CLKOP, so both outputs are one
  * clock (system and AD9226) with the same phase.
  */
final case class Ecp5PllParams(inHz: Long, refDiv: Int, fbDiv: Int, outDiv: Int) {
  def pfdHz: Double = inHz.toDouble / refDiv
  def outHz: Double = pfdHz * fbDiv
  def vcoHz: Double = outHz * outDiv
  /** Coarse phase of a 0-degree output: DIV - 1 (Lattice's setting; emard's ecp5pll.sv gives the same). */
  def cphase: Int = outDiv - 1
  override def toString: String =
    s"EHXPLLL ${Mhz(inHz.toDouble)} MHz / CLKI_DIV $refDiv * CLKFB_DIV $fbDiv = ${Mhz(outHz)} MHz, VCO ${Mhz(vcoHz)} MHz (CLKOP_DIV $outDiv)"
}

/** The divider search of Project Trellis' `ecppll`, in exact integer arithmetic and for exact
  * frequencies only (the UART divisor and the ADC clock register need the exact system clock):
  * PFD 3.125..400 MHz, VCO 400..800 MHz, CLKI_DIV 1..128, CLKFB_DIV 1..80, CLKOP_DIV 1..128; among the
  * exact settings the VCO nearest 600 MHz, the first in (CLKI_DIV, CLKFB_DIV, CLKOP_DIV) order on a tie.
  * 25 -> 50 MHz: CLKI_DIV 1, CLKFB_DIV 2, CLKOP_DIV 12, VCO 600 MHz.
  */
object Ecp5Pll {
  val pfdMinHz = 3125000L; val pfdMaxHz = 400000000L
  val vcoMinHz = 400000000L; val vcoMaxHz = 800000000L

  def solve(inHz: Long, outHz: Long): Either[String, Ecp5PllParams] = {
    val exact = for {
      r <- 1 to 128 if inHz >= pfdMinHz * r && inHz <= pfdMaxHz * r
      f <- 1 to 80 if inHz * f == outHz * r
      o <- 1 to 128 if outHz * o >= vcoMinHz && outHz * o <= vcoMaxHz
    } yield Ecp5PllParams(inHz, r, f, o)
    exact.sortBy(q => math.abs(outHz * q.outDiv - 600000000L)).headOption // stable: the first on a tie
      .toRight(s"the ECP5 PLL cannot make exactly ${Mhz(outHz.toDouble)} MHz from ${Mhz(inHz.toDouble)} MHz " +
        s"(f_in * CLKFB_DIV / CLKI_DIV with CLKFB_DIV <= 80, VCO 400..800 MHz); e.g. 50, 62.5, 65, 75 or 100 MHz")
  }
}

/** EHXPLLL wrapper (boards/resources/ulx3s/Ulx3sPll.v) with the dividers of `q`: CLKOP = system
  * clock (feedback), CLKOS = AD9226 clock, same frequency and phase.
  */
class Ulx3sPll(val q: Ecp5PllParams) extends BlackBox(Map(
  "CLKI_DIV" -> IntParam(q.refDiv), "CLKFB_DIV" -> IntParam(q.fbDiv),
  "CLKOP_DIV" -> IntParam(q.outDiv), "CLKOP_CPHASE" -> IntParam(q.cphase))) with HasBlackBoxResource {
  override def desiredName: String = "Ulx3sPll"
  val io = IO(new Bundle {
    val clkin = Input(Clock())
    val clkSys = Output(Clock())
    val clkAdc = Output(Clock())
    val locked = Output(Bool())
  })
  addResource("/ulx3s/Ulx3sPll.v")
}
