package moire.explain.effects

import moire.explain._

/** Sampling-clock jitter: noise growing with the signal's slope, common to both channels. */
object Jitter extends Effect {
  val name = "jitter"
  val params = Seq(Param("jitter_s", "s rms", ">= 0"))
  val what = "sampling clock jitter, seconds rms, common to both channels"
  val shows = "noise against signal slope"
  override def example: Example = Example(EffectSpec(name, Map("jitter_s" -> 300e-12)), "ramp:50000:250000:0.01")
  val domain: Domain = Domain.Speed
  override val plot: PlotKind = PlotKind.Slope

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(jitter = true)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.jitter().toSeq)
  override def refresh(f: Finding, e: SignalEngine): Finding = f.copy(params = f.params + ("jitter_s" -> math.sqrt(e.noise.jitter2)))
  override def unsupported(c: Cand, e: SignalEngine, fMin: Double, fMax: Double): Option[String] = Identifiable.referenceNoise(e, fMin, fMax)
  override def size(c: Cand, e: SignalEngine): Double = {
    // the noise it adds at the fastest speed, beside the white noise (rms, full scale)
    val j = c.params.getOrElse("jitter_s", 0.0); val w = c.params.getOrElse("white_noise_fs", 0.0)
    val s = 2 * math.Pi * e.fMax * math.max(e.ampS, e.ampC) * j / math.sqrt(2)
    math.sqrt(w * w + s * s) - w
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"sampling clock jitter ${Effect.g(p, "jitter_s") * 1e12}%.1f ps rms: noise grows with the signal slope, beside ${Effect.g(p, "white_noise_fs")}%.3g full scale white noise"
}
