package moire.board.de2115

import moire.chain.CorrectedSubdivParams
import moire.protocol.{Registers, StreamV1}
import moire.signal.AdcFormat
import moire.subdiv.SubdivParams

/** The datapath inside the board. */
sealed abstract class BoardDesign(val name: String)
object BoardDesign {
  /** ADC front end + subdivider (moire.subdiv.SubdivAdc). */
  case object Subdiv extends BoardDesign("subdiv")
  /** ADC front end + adaptive corrector + subdivider (moire.chain.CorrectedSubdivider). */
  case object Corrected extends BoardDesign("corrected")
  val all: Seq[BoardDesign] = Seq(Subdiv, Corrected)
  def parse(s: String): Either[String, BoardDesign] =
    all.find(_.name == s).toRight(s"--design: '$s' is not a board design; allowed: ${all.map(_.name).mkString(", ")}")
}

/** How the AD9226 clock is made. */
sealed abstract class ClockSource(val name: String)
object ClockSource {
  /** altpll BlackBox (boards/resources/de2-115/De2115Pll.v): system and ADC clock from one PLL, same phase. */
  case object Pll extends ClockSource("pll")
  /** No PLL: the system clock is CLOCK_50; the ADC clock is CLOCK_50 forwarded (50 MHz) or a divider
    * register (lower rates). Used for simulation; also builds in Quartus.
    */
  case object Logic extends ClockSource("logic")
  val all: Seq[ClockSource] = Seq(Pll, Logic)
  def parse(s: String): Either[String, ClockSource] =
    all.find(_.name == s).toRight(s"--clock-source: '$s' is unknown; allowed: ${all.map(_.name).mkString(", ")}")
}

/** Parameters of the DE2-115 board wrapper ([[De2115Top]]).
  *
  * @param design        datapath: subdiv or corrected
  * @param subdiv        subdivider parameters (design subdiv; its inputBits must be 12, the AD9226)
  * @param corrected     corrector chain parameters (design corrected; its format is replaced by `adcFormat`)
  * @param adcClockHz    AD9226 sample clock: 50 MHz / k, k in 1..1000 (default 50 MHz)
  * @param adcFormat     how the ADC modules are strapped (offset binary on the common modules)
  * @param decimation    default of register 0x04: one record every D samples, 1..2^24
  * @param baud          UART rate, 8N1 (default 115200)
  * @param frameRecords  n, records per frame, 1..255 (default 8)
  * @param fifoDepth     record FIFO entries, at least n
  * @param glitchFilter  encoder inputs: clocks an input must be stable to be taken, 1..65536
  * @param clockSource   pll (hardware) or logic (simulation fallback)
  */
final case class BoardParams(
  design: BoardDesign = BoardDesign.Subdiv,
  subdiv: SubdivParams = SubdivParams(),
  corrected: CorrectedSubdivParams = CorrectedSubdivParams(),
  adcClockHz: Int = 50000000,
  adcFormat: AdcFormat = AdcFormat.OffsetBinary,
  decimation: Int = 62500,
  baud: Int = 115200,
  frameRecords: Int = 8,
  fifoDepth: Int = 256,
  glitchFilter: Int = 16,
  clockSource: ClockSource = ClockSource.Pll
) {
  /** The system clock: CLOCK_50. */
  val clockHz: Int = 50000000
  require(adcClockHz > 0 && clockHz % adcClockHz == 0 && clockHz / adcClockHz <= 1000,
    s"adc-clock-hz must be 50 MHz divided by an integer 1..1000, got $adcClockHz")
  /** System clocks per ADC clock. */
  val adcDivide: Int = clockHz / adcClockHz
  require(decimation >= 1 && decimation <= Registers.MaxDecimation, s"decimation must be in 1..${Registers.MaxDecimation}, got $decimation")
  require(frameRecords >= 1 && frameRecords <= StreamV1.MaxFrameRecords,
    s"frame-records must be in 1..${StreamV1.MaxFrameRecords}, got $frameRecords")
  require(fifoDepth >= frameRecords && fifoDepth <= 65536, s"fifo-depth must be in $frameRecords..65536 (at least frame-records), got $fifoDepth")
  require(glitchFilter >= 1 && glitchFilter <= 65536, s"glitch-filter must be in 1..65536, got $glitchFilter")
  /** Clocks per UART bit (checks the rate error). */
  val baudDivisor: Int = moire.io.UartDivisor(clockHz, baud)
  require(subdiv.inputBits == 12, s"the AD9226 has 12 bits: subdiv input-bits must be 12, got ${subdiv.inputBits}")
  require(corrected.adapt.inputBits == 12, s"the AD9226 has 12 bits: corrector input bits must be 12, got ${corrected.adapt.inputBits}")

  val correctedParams: CorrectedSubdivParams = corrected.copy(format = adcFormat)
  /** The subdivider that makes the position (its counts M, position width). */
  val datapathSubdiv: SubdivParams = if (design == BoardDesign.Subdiv) subdiv else correctedParams.subdiv
  /** Clocks from the captured ADC word (input register) to the datapath output. */
  val datapathLatency: Int = if (design == BoardDesign.Subdiv) 1 + subdiv.latency else correctedParams.latency
  /** AD9226 pipeline: a sample's word appears on the pins 7 ADC clocks after the edge that took it. */
  val adcPipeline: Int = 7
  /** Records per second at the default decimation. */
  def recordRate: Double = adcClockHz.toDouble / decimation
  /** Largest record rate the UART carries: (8 + 12 n + 2) bytes of 10 bits per n records. */
  def uartRecordRate: Double = baud / 10.0 * frameRecords / (10 + 12 * frameRecords)

  def projectName: String = "moire_de2_115"
  def topName: String = s"De2115_${design.name}_${if (adcFormat == AdcFormat.OffsetBinary) "ob" else "tc"}_adc${adcClockHz / 1000}k_${clockSource.name}"
}
