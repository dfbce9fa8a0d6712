package moire.explain.effects

import moire.explain._

/** Offsets and amplitudes changing with the position along the travel (beam walk, scale contamination). */
object ContrastAlongTravel extends Effect {
  val name = "contrast_along_travel"
  val params = Seq(Param("offset_sin_per_period", "full scale/period", "any"), Param("offset_cos_per_period", "full scale/period", "any"),
    Param("gain_sin_per_period", "1/period", "any"), Param("gain_cos_per_period", "1/period", "any"))
  val what = "offsets (full scale) and gains (relative) changing linearly with the position along the travel (beam walk, scale contamination), per fringe period from the start"
  val shows = "against position"
  override def example: Example = Example(EffectSpec(name, Map("gain_sin_per_period" -> 2e-5, "offset_cos_per_period" -> 1e-5)), "oscillate:400:300")
  val domain: Domain = Domain.Time
  override val plot: PlotKind = PlotKind.Position

  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Contrast)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] = Seq(() => c.linear(Term.Contrast).map(_._1).toSeq)
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    val names = params.map(_.name)
    val span = { val x = e.travel; x.max - x.min }
    (names.zip(b).toMap + ("travel_periods" -> span), names.zip(sd).toMap + ("travel_periods" -> 0.0), "against position: offset and amplitude", "both")
  }
  override def lookAlikes(f: Finding, e: SignalEngine): Seq[String] = TimeOrTravel.lookAlikes(e, Warmup.name + " or " + Drift.name)

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String = {
    def g(k: String) = Effect.g(p, k)
    val l = g("travel_periods")
    f"contrast changes along the travel: amplitudes ${100 * g("gain_sin_per_period") * l}%.3g / ${100 * g("gain_cos_per_period") * l}%.3g %%, offsets ${g("offset_sin_per_period") * l}%.3g / ${g("offset_cos_per_period") * l}%.3g full scale over the ${l}%.0f periods travelled (sin/cos)"
  }
}
