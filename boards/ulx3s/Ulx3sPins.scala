package moire.board.ulx3s

/** One FPGA pin of the ULX3S: the top-level port bit, the site, and its IOBUF settings (all LVCMOS33).
  * @param pull  PULLMODE (UP, DOWN, NONE)
  * @param drive DRIVE in mA, outputs and the header's pins (as the board's constraint file sets them)
  */
final case class LpfPin(port: String, site: String, pull: String, drive: Option[Int]) {
  def ioType: String = "LVCMOS33"
}

/** The ONE place holding the ULX3S pin mapping (used by the .lpf writer).
  * Board pins: the reference sheet section 2 (emard/ulx3s ulx3s_v20.lpf); AD9226 and encoder on the
  * GPIO headers: its section 3 SUGGESTED mapping (pairs 0-9 and 18-24, clear of the ESP32 and the
  * on-board ADC). The header pins keep the board file's PULLMODE=UP DRIVE=4, except the ADC data and
  * OTR inputs (PULLMODE=NONE). Buttons pull towards released (btn[0] PWRn up, the others down).
  */
object Ulx3sPins {
  /** GPIO header pairs i = 0..27: gp[i] and gn[i] sites. */
  val gp: IndexedSeq[String] = "B11 A10 A9 B9 A7 C8 C6 A6 A4 A2 C4 F4 G3 H4 U18 N17 N16 L16 H18 F17 D18 C18 B15 B17 C16 D14 B13 D13".split(' ').toIndexedSeq
  val gn: IndexedSeq[String] = "C11 A11 B10 C10 A8 B8 C7 B6 A5 B1 B4 E3 F3 G5 U17 P16 M17 L17 H17 G18 E17 D17 C15 C17 D16 E14 C13 E13".split(' ').toIndexedSeq
  /** Pairs shared with the ESP32 (11-13) and the on-board MAX11123 (14-17): kept free. */
  val reserved: Set[Int] = (11 to 17).toSet

  private def bus(name: String, sites: Seq[String], pull: String, drive: Option[Int]): Seq[LpfPin] =
    sites.zipWithIndex.map { case (s, i) => LpfPin(s"$name[$i]", s, pull, drive) }
  /** gp[i] gn[i] gp[i+1] ... for pairs from..from+5: the 12 data bits of one AD9226. */
  private def pairs(from: Int): Seq[String] = (from until from + 6).flatMap(i => Seq(gp(i), gn(i)))
  private def header(port: String, site: String, pull: String = "UP") = LpfPin(port, site, pull, Some(4))

  val clock: Seq[LpfPin] = Seq(LpfPin("clk_25mhz", "G2", "NONE", None))
  val led: Seq[LpfPin] = bus("led", "B2 C2 C1 D2 D1 E2 E1 H3".split(' ').toSeq, "NONE", Some(4))
  val btn: Seq[LpfPin] = bus("btn", "D6 R1 T1 R18 V1 U1 H16".split(' ').toSeq, "DOWN", None)
    .map(b => if (b.port == "btn[0]") b.copy(pull = "UP") else b)
  /** FTDI serial port; names from the FTDI's side: ftdi_rxd is the FPGA's output. */
  val uart: Seq[LpfPin] = Seq(LpfPin("ftdi_rxd", "L4", "UP", Some(4)), LpfPin("ftdi_txd", "M1", "UP", None))
  val adc: Seq[LpfPin] = Seq(
    bus("SIN_D", pairs(0), "NONE", None), Seq(LpfPin("SIN_OTR", gp(6), "NONE", None), header("SIN_CLK", gn(6))),
    bus("COS_D", pairs(18), "NONE", None), Seq(LpfPin("COS_OTR", gp(24), "NONE", None), header("COS_CLK", gn(24)))).flatten
  val encoder: Seq[LpfPin] = Seq(
    header("ENC_A_IN", gp(7)), header("ENC_B_IN", gn(7)), header("ENC_Z_IN", gp(8)),
    header("ENC_A_OUT", gn(8)), header("ENC_B_OUT", gp(9)), header("ENC_Z_OUT", gn(9)))

  val all: Seq[LpfPin] = clock ++ led ++ btn ++ uart ++ adc ++ encoder
  require(all.map(_.port).distinct.size == all.size, "a port appears twice in the pin table")
  require(all.map(_.site).distinct.size == all.size, "a site appears twice in the pin table")
  require(reserved.forall(i => !all.exists(p => p.site == gp(i) || p.site == gn(i))), "a pin of the ESP32 or the on-board ADC is used")
}
