package moire.explain.effects

import moire.explain._

/** A narrower converter in a wider code format: the low bits never change. Read off the codes, not searched. */
object CoarseQuantization extends Effect {
  val name = "coarse_quantization"
  val params = Seq(Param("effective_bits", "bits", "4..adc_bits"))
  val what = "the codes use only the top effective_bits of the ADC word (a narrower converter in a wider format)"
  val shows = "code histogram"
  override def example: Example = Example(EffectSpec(name, Map("effective_bits" -> 10)))
  val domain: Domain = Domain.Codes
  override val plot: PlotKind = PlotKind.None
  override val confoundedWithMotion = false
  override val searched = false

  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "effective_bits", 4, 24, "a whole number from 4 to 24 (and at most the ADC's bits)", whole = true)
  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (!(e.p("effective_bits") >= 4 && e.p("effective_bits") <= m.adc.bits))
      throw new ExplainError(s"$name effective_bits must be in 4..${m.adc.bits}")

  /** The finding of a record whose low bits never change (none when all bits are used). */
  def finding(e: SignalEngine): Seq[Finding] = if (e.coarseBits == 0) Nil else {
    val p = Map("effective_bits" -> (e.rec.adc.bits - e.coarseBits).toDouble, "format_bits" -> e.rec.adc.bits.toDouble, "step_lsb" -> (1 << e.coarseBits).toDouble)
    Seq(Finding(name, "both", summary(p, "both", 0, 0), p, p.map { case (k, _) => k -> 0.0 }, Double.NaN, e.rms, e.rms,
      s"code histogram: the low ${e.coarseBits} bits never change on either channel"))
  }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val analog = false
    private val adc = m.adc
    override val quantizer: Option[Double => Int] =
      specs.map(_.p("effective_bits", adc.bits.toDouble).toInt).headOption.filter(_ < adc.bits).map { eb =>
        val coarse = moire.signal.Adc(eb)
        (v: Double) => adc.pins(math.max(-adc.half, coarse.signedCode(v).code << (adc.bits - eb)))
      }
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"the codes use only ${Effect.g(p, "effective_bits").toInt} of the ${Effect.g(p, "format_bits").toInt} bits: quantization steps of ${Effect.g(p, "step_lsb").toInt} LSB, whose error is not white noise"
}
