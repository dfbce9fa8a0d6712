package moire.board

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
  /** ADC front end + subdivider + turntable harmonic compensation of the position (moire.harmonic.HarmonicCompensator):
    * records and A/B/Z carry theta - f(theta); coefficients by `board-reg --coefficients`.
    */
  case object Compensated extends BoardDesign("compensated")
  val all: Seq[BoardDesign] = Seq(Subdiv, Corrected, Compensated)
  def parse(s: String): Either[String, BoardDesign] =
    moire.choice.Choice(all, s, s"--design: '$s' is not a board design")(_.name)
}

/** How the AD9226 clock is made. */
sealed abstract class ClockSource(val name: String)
object ClockSource {
  /** The board's PLL (DE2-115 altpll, ULX3S EHXPLLL): system and ADC clock from one PLL, same phase. */
  case object Pll extends ClockSource("pll")
  /** No PLL: the system clock is the board's oscillator pin; the ADC clock is that pin forwarded
    * (k = 1) or a divider register (k > 1). Used for simulation; also builds.
    */
  case object Logic extends ClockSource("logic")
  val all: Seq[ClockSource] = Seq(Pll, Logic)
  def parse(s: String): Either[String, ClockSource] =
    moire.choice.Choice(all, s, s"--clock-source: '$s' is unknown")(_.name)
}

/** Parameters of a board: the core ([[BoardCore]]) and its harness (DE2-115 or ULX3S top).
  *
  * @param design        datapath: subdiv or corrected
  * @param subdiv        subdivider parameters (design subdiv; its inputBits must be 12, the AD9226)
  * @param corrected     corrector chain parameters (design corrected; its format is replaced by `adcFormat`)
  * @param adcClockHz    AD9226 sample clock: clockHz / k, k in 1..1000 (default 50 MHz)
  * @param adcFormat     how the ADC modules are strapped (offset binary on the common modules)
  * @param decimation    default of register 0x04: one record every D samples, 1..2^24
  * @param baud          UART rate, 8N1 (default 115200)
  * @param frameRecords  n, records per frame, 1..255 (default 8)
  * @param fifoDepth     record FIFO entries, at least n
  * @param glitchFilter  encoder inputs: clocks an input must be stable to be taken, 1..65536
  * @param harmonic      compensator of design compensated (its subdivision is set to the subdivider's M)
  * @param burstSamples  burst capture depth N (block RAM: 29 bits per sample; 65,536 = 116 DP16KD or 232 M9K)
  * @param clockSource   pll (hardware) or logic (simulation fallback)
  * @param clockHz       system clock (DE2-115: 50 MHz only; ULX3S: what its PLL makes from 25 MHz,
  *                      or 25 MHz with clock source logic)
  */
final case class BoardParams(
  design: BoardDesign = BoardDesign.Subdiv,
  subdiv: SubdivParams = SubdivParams(),
  corrected: CorrectedSubdivParams = CorrectedSubdivParams(),
  adcClockHz: Int = 50000000,
  adcFormat: AdcFormat = AdcFormat.OffsetBinary,
  decimation: Int = 100000,
  baud: Int = 115200,
  frameRecords: Int = 8,
  fifoDepth: Int = 256,
  glitchFilter: Int = 16,
  clockSource: ClockSource = ClockSource.Pll,
  clockHz: Int = 50000000,
  burstSamples: Int = 65536,
  harmonic: moire.harmonic.HarmonicParams = moire.harmonic.HarmonicParams()
) {
  require(clockHz >= 1000000 && clockHz <= 200000000, s"clock-hz must be in 1000000..200000000, got $clockHz")
  require(adcClockHz > 0 && clockHz % adcClockHz == 0 && clockHz / adcClockHz <= 1000,
    s"adc-clock-hz must be ${Mhz(clockHz)} MHz divided by an integer 1..1000, got $adcClockHz")
  /** System clocks per ADC clock. */
  val adcDivide: Int = clockHz / adcClockHz
  require(decimation >= 1 && decimation <= Registers.MaxDecimation, s"decimation must be in 1..${Registers.MaxDecimation}, got $decimation")
  require(frameRecords >= 1 && frameRecords <= StreamV1.MaxFrameRecords,
    s"frame-records must be in 1..${StreamV1.MaxFrameRecords}, got $frameRecords")
  require(fifoDepth >= frameRecords && fifoDepth <= 65536, s"fifo-depth must be in $frameRecords..65536 (at least frame-records), got $fifoDepth")
  require(glitchFilter >= 1 && glitchFilter <= 65536, s"glitch-filter must be in 1..65536, got $glitchFilter")
  /** The burst capture's parameters (checks the depth). */
  val burst: moire.io.BurstParams = moire.io.BurstParams(burstSamples)
  /** Clocks per UART bit (checks the rate error). */
  val baudDivisor: Int = moire.io.UartDivisor(clockHz, baud)
  require(subdiv.inputBits == 12, s"the AD9226 has 12 bits: subdiv input-bits must be 12, got ${subdiv.inputBits}")
  require(corrected.adapt.inputBits == 12, s"the AD9226 has 12 bits: corrector input bits must be 12, got ${corrected.adapt.inputBits}")

  val correctedParams: CorrectedSubdivParams = corrected.copy(format = adcFormat)
  /** The subdivider that makes the position (its counts M, position width). */
  val datapathSubdiv: SubdivParams = if (design == BoardDesign.Subdiv) subdiv else correctedParams.subdiv
  /** The compensator of design compensated: one turn = `harmonic.lines` fringe periods of M counts. */
  val harmonicParams: moire.harmonic.HarmonicParams = harmonic.copy(subdivision = subdiv.counts)
  /** Clocks from the captured ADC word (input register) to the datapath output. */
  val datapathLatency: Int = design match {
    case BoardDesign.Subdiv => moire.subdiv.SubdivAdc.latency(subdiv)
    case BoardDesign.Corrected => correctedParams.latency
    case BoardDesign.Compensated => moire.subdiv.SubdivAdc.latency(subdiv) + harmonicParams.latency + BoardParams.compensatedOutRegs
  }
  /** AD9226 pipeline: a sample's word appears on the pins 7 ADC clocks after the edge that took it. */
  val adcPipeline: Int = 7
  /** Records per second at the default decimation. */
  def recordRate: Double = adcClockHz.toDouble / decimation
  /** Largest record rate the UART carries: (8 + 16 n + 2) bytes of 10 bits per n records (frame type 0x05). */
  def uartRecordRate: Double = baud / 10.0 * frameRecords / StreamV1.refRecordFrameBytes(frameRecords)

  /** Names the configuration in a top's name: design, ADC format, clocks, clock source. */
  def tag: String = s"${design.name}_${if (adcFormat == AdcFormat.OffsetBinary) "ob" else "tc"}" +
    (if (clockHz != 50000000) s"_clk${clockHz / 1000}k" else "") + s"_adc${adcClockHz / 1000}k_${clockSource.name}"
  def formatName: String = if (adcFormat == AdcFormat.OffsetBinary) "offset binary" else "two's complement"
}

object BoardParams {
  /** Design compensated: registers after theta - f(theta) (rounding and subtraction in a clock of their own). */
  val compensatedOutRegs: Int = 1
}

/** A frequency in MHz as few digits as it needs: 50, 12.5. */
object Mhz {
  def apply(hz: Double): String = BigDecimal(hz / 1e6).bigDecimal.stripTrailingZeros.toPlainString
}
