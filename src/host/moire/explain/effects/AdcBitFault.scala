package moire.explain.effects

import moire.explain._

/** An ADC data line stuck at 0 or 1, or wired-AND with another line. */
object AdcBitFault extends Effect {
  val name = "adc_bit_fault"
  val params = Seq(Param("bit", "", "0..bits-1"), Param("stuck_at", "", "0 or 1"), Param("bridged_to", "", "0..bits-1, not bit"))
  val what = "data line stuck at 0/1, or wired-AND with another bit (channel=sin|cos)"
  override val perChannel = true
  val shows = "code histogram"
  override val claims: Seq[String] = Seq("code histogram")
  override def example: Example = Example(EffectSpec(name, Map("bit" -> 3, "stuck_at" -> 1), "cos"))
  val domain: Domain = Domain.Codes
  override val plot: PlotKind = PlotKind.Level
  override val confoundedWithMotion = false

  override val needs: Seq[String] = Seq("stuck_at", "bridged_to")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "bit", 0, 23, "a whole number from 0 to 23 (and below the ADC's bits)", whole = true)
      .orElse(Effect.within(e, "stuck_at", 0, 1, "0 or 1", whole = true))
      .orElse(Effect.within(e, "bridged_to", 0, 23, "a whole number from 0 to 23 (and below the ADC's bits)", whole = true))
      .orElse(if (e.params.contains("stuck_at") && e.params.contains("bridged_to")) Some("give stuck_at or bridged_to, not both") else None)
      .orElse(if (e.params.contains("bridged_to") && e.params.get("bridged_to") == e.params.get("bit")) Some("bridged_to must be another bit than bit") else None)
  override def validate(e: EffectSpec, m: PhysicsModel): Unit = {
    val b = e.p("bit"); if (!(b >= 0 && b < m.adc.bits)) throw new ExplainError(s"$name bit must be in 0..${m.adc.bits - 1}")
    if (e.channel == "both") throw new ExplainError(s"$name needs channel=sin or channel=cos")
    val o = e.p("bridged_to"); if (o >= m.adc.bits) throw new ExplainError(s"$name bridged_to must be in 0..${m.adc.bits - 1}")
  }
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec =
    sp.copy(faults = sp.faults :+ Fault(if (e.channel == "cos") 1 else 0, e.p("bit", 0).toInt,
      if (e.p("stuck_at").isNaN) -1 else e.p("stuck_at").toInt, if (e.p("bridged_to").isNaN) -1 else e.p("bridged_to").toInt))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.faults())

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val analog = false
    private val sin = specs.filter(_.channel == "sin"); private val cos = specs.filter(_.channel != "sin")
    override def pins(code0: Int, isSin: Boolean): Int = {
      var code = code0
      (if (isSin) sin else cos).foreach(e => code = fault(code, e))
      code
    }
  }

  /** A bit fault applied to a pin code: stuck_at 0/1, or wired-AND with bit `bridged_to`. */
  def fault(code: Int, e: EffectSpec): Int = {
    val b = e.p("bit").toInt; val m = 1 << b
    if (!e.p("stuck_at").isNaN) { if (e.p("stuck_at") >= 0.5) code | m else code & ~m }
    else if (!e.p("bridged_to").isNaN) {
      val o = e.p("bridged_to").toInt; val both = ((code >> b) & (code >> o) & 1) != 0
      if (both) code | m | (1 << o) else code & ~m & ~(1 << o)
    } else code
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    if (p.contains("stuck_at")) f"$channel ADC data line ${Effect.g(p, "bit").toInt} stuck at ${Effect.g(p, "stuck_at").toInt}"
    else f"$channel ADC data lines ${Effect.g(p, "bit").toInt} and ${Effect.g(p, "bridged_to").toInt} bridged (wired AND)"
}
