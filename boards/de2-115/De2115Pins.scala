package moire.board.de2115

/** One FPGA pin: the top-level port bit (as Quartus names it), the ball and the I/O standard. */
final case class Pin(port: String, ball: String, ioStandard: String)

/** The ONE place holding the DE2-115 pin mapping (used by the .qsf writer).
  * Board pins: the reference sheet section 2 (Terasic); AD9226 and encoder: its section 4
  * SUGGESTED mapping (two AD9226 on JP5, encoder on EX_IO). UART by ball: TXD G9 out, RXD G12 in.
  */
object De2115Pins {
  val lvttl = "3.3-V LVTTL"
  val v25 = "2.5 V"
  private def bus(name: String, balls: String, std: Int => String): Seq[Pin] =
    balls.split(' ').toSeq.zipWithIndex.map { case (b, i) => Pin(s"$name[$i]", b, std(i)) }

  val clock: Seq[Pin] = Seq(Pin("CLOCK_50", "Y2", lvttl))
  val key: Seq[Pin] = bus("KEY", "M23 M21 N21 R24", _ => v25)
  val ledr: Seq[Pin] = bus("LEDR", "G19 F19 E19 F21 F18 E18 J19 H19 J17 G17 J15 H16 J16 H17 F15 G15 G16 H15", _ => v25)
  val ledg: Seq[Pin] = bus("LEDG", "E21 E22 E25 E24 H21 G20 G22 G21 F17", _ => v25)
  val hex: Seq[Pin] = Seq(
    bus("HEX0", "G18 F22 E17 L26 L25 J22 H22", _ => v25),
    bus("HEX1", "M24 Y22 W21 W22 W25 U23 U24", _ => v25),
    bus("HEX2", "AA25 AA26 Y25 W26 Y26 W27 W28", _ => v25),
    bus("HEX3", "V21 U21 AB20 AA21 AD24 AF23 Y19", i => if (i <= 1) v25 else lvttl),
    bus("HEX4", "AB19 AA19 AG21 AH21 AE19 AF19 AE18", _ => lvttl),
    bus("HEX5", "AD18 AC18 AB18 AH19 AG19 AF18 AH18", _ => lvttl),
    bus("HEX6", "AA17 AB16 AA16 AB17 AB15 AA15 AC17", _ => lvttl),
    bus("HEX7", "AD17 AE17 AG17 AH17 AF17 AG18 AA14", _ => lvttl)).flatten
  val uart: Seq[Pin] = Seq(Pin("UART_TXD", "G9", lvttl), Pin("UART_RXD", "G12", lvttl))
  /** AD9226 channels on JP5: D[0..11], CLK, OTR (GPIO 0-13 and 16-29). */
  val adc: Seq[Pin] = Seq(
    bus("SIN_D", "AB22 AC15 AB21 Y17 AC21 Y16 AD21 AE16 AD15 AC19 AF16 AD19", _ => lvttl),
    Seq(Pin("SIN_CLK", "AE15", lvttl), Pin("SIN_OTR", "AF15", lvttl)),
    bus("COS_D", "AF25 AC22 AE22 AF21 AF22 AD22 AG25 AD25 AH25 AG22 AE24 AH22", _ => lvttl),
    Seq(Pin("COS_CLK", "AE25", lvttl), Pin("COS_OTR", "AF26", lvttl))).flatten
  /** Quadrature encoder on EX_IO 0-5. */
  val encoder: Seq[Pin] = Seq(
    Pin("ENC_A_IN", "J10", lvttl), Pin("ENC_B_IN", "J14", lvttl), Pin("ENC_Z_IN", "H13", lvttl),
    Pin("ENC_A_OUT", "H14", lvttl), Pin("ENC_B_OUT", "F14", lvttl), Pin("ENC_Z_OUT", "E10", lvttl))

  val all: Seq[Pin] = clock ++ key ++ ledr ++ ledg ++ hex ++ uart ++ adc ++ encoder
  require(all.map(_.port).distinct.size == all.size, "a port appears twice in the pin table")
  require(all.map(_.ball).distinct.size == all.size, "a ball appears twice in the pin table")
}
