package moire.explain.effects

import moire.explain._

/** Amplifier saturation below the ADC's range: a pile-up of samples at one code. */
object Clipping extends Effect {
  val name = "clipping"
  val params = Seq(Param("high_fs", "full scale", "-1..1, above low_fs"), Param("low_fs", "full scale", "-1..1"))
  val what = "amplifier saturation levels in full-scale units (channel=sin|cos|both)"
  override val perChannel = true
  val shows = "pile-up at one code"
  override val claims: Seq[String] = Seq("code histogram")
  override def example: Example = Example(EffectSpec(name, Map("high_fs" -> 0.8), "sin"))
  val domain: Domain = Domain.Codes
  override val plot: PlotKind = PlotKind.Level
  override val confoundedWithMotion = false
  override val direct = true

  override val needs: Seq[String] = Seq("high_fs", "low_fs")
  override def check(e: EffectSpec): Option[String] =
    Effect.within(e, "high_fs", -1, 1, "from -1 to 1 full scale").orElse(Effect.within(e, "low_fs", -1, 1, "from -1 to 1 full scale"))
      .orElse(for (h <- e.params.get("high_fs"); l <- e.params.get("low_fs") if h <= l)
        yield s"high_fs (${Effect.show(h)}) must be above low_fs (${Effect.show(l)})")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec =
    sp.copy(clips = sp.clips :+ Clip(if (e.channel == "cos") 1 else 0, e.p("low_fs", Double.NegativeInfinity), e.p("high_fs", Double.PositiveInfinity)))
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.clips())

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    override val analog = false
    private val sin = Forward.on(specs, isSin = true); private val cos = Forward.on(specs, isSin = false)
    override def frontEnd(v0: Double, isSin: Boolean): Double = {
      var v = v0
      (if (isSin) sin else cos).foreach { e => v = math.min(e.p("high_fs", 2.0), math.max(e.p("low_fs", -2.0), v)) }
      v
    }
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    s"$channel channel saturates" + p.map { case (k, v) => f" ${k.stripSuffix("_fs")} at $v%.4f FS" }.mkString(",")
}
