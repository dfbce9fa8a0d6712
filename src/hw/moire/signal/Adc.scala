package moire.signal

/** How an ADC writes its codes. AD9226: offset binary (0 V = 0x800) or two's complement (MSB inverted). */
sealed abstract class AdcFormat(val name: String)
object AdcFormat {
  case object OffsetBinary extends AdcFormat("offset-binary")
  case object TwosComplement extends AdcFormat("twos-complement")
  val all: Seq[AdcFormat] = Seq(OffsetBinary, TwosComplement)
  def parse(s: String): Either[String, AdcFormat] =
    moire.choice.Choice(all, s, s"ADC format '$s' is unknown")(_.name)
}

/** One ADC sample: the code as the ADC drives its pins, and the out-of-range flag (AD9226 OTR). */
final case class AdcSample(code: Int, otr: Boolean)

/** An ideal `bits`-bit ADC with input range [-1, 1) full scale (AD9226: +-VREF).
  * Below -1 it gives the lowest code, at or above 1 - 1 LSB the highest, with OTR set outside [-1, 1).
  */
final case class Adc(bits: Int = 12, format: AdcFormat = AdcFormat.OffsetBinary) {
  require(bits >= 4 && bits <= 24, s"ADC bits must be within 4..24, got $bits")
  val half: Int = 1 << (bits - 1)
  val lsb: Double = 1.0 / half

  /** Signed code in -half .. half-1 (two's complement value) of the analog value v (full scale 1). */
  def signedCode(v: Double): AdcSample = {
    val c = math.floor(v * half + 0.5)
    val otr = v < -1.0 || v >= 1.0
    AdcSample(math.max(-half, math.min(half - 1, c)).toInt, otr)
  }

  /** Code as driven on the pins in this ADC's format (unsigned bit pattern, `bits` wide). */
  def pins(signed: Int): Int = format match {
    case AdcFormat.OffsetBinary   => signed + half
    case AdcFormat.TwosComplement => signed & ((1 << bits) - 1)
  }

  /** The signed value of a pin pattern (inverse of `pins`). */
  def fromPins(code: Int): Int = {
    require(code >= 0 && code < (1 << bits), s"ADC code $code is outside 0..${(1 << bits) - 1}")
    format match {
      case AdcFormat.OffsetBinary   => code - half
      case AdcFormat.TwosComplement => if (code >= half) code - (1 << bits) else code
    }
  }

  def sample(v: Double): AdcSample = { val s = signedCode(v); s.copy(code = pins(s.code)) }
}
