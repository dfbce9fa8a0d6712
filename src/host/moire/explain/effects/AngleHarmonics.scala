package moire.explain.effects

import moire.explain._

/** The read angle's error as harmonic m of the mechanical angle (needs a reference naming turns to be fitted). */
abstract class AngleHarmonics(order: Int) extends Effect {
  val domain: Domain = Domain.Periodic
  override def cycles(e: SignalEngine): Double = e.periodsPerTurn.fold(0.0)(e.travelPeriods / _)
  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (m.linesPerRev.isEmpty) throw new ExplainError(s"$name needs lines_per_rev (--lines-per-rev)")
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    if (c.mechanical) Seq(() => c.linear(Term.AngleHarm(order)).map(_._1).toSeq) else Nil
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    // b(0) cos + b(1) sin of m x the mechanical angle, in fringe periods = A sin(m angle + phase)
    val (a, sa) = Effect.amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = Effect.deg(b(1), b(0), a, sa)
    val p = e.periodsPerTurn.getOrElse(Double.NaN); val arcsec = 1296000 / p
    val common = Map("phase_deg" -> ph, "phase_error_deg" -> 360 * a, "angle_error_arcsec" -> arcsec * a)
    val cu = Map("phase_deg" -> sph, "phase_error_deg" -> 360 * sa, "angle_error_arcsec" -> arcsec * sa)
    own(common, cu, a, sa, p)
  }
  def own(common: Map[String, Double], cu: Map[String, Double], a: Double, sa: Double, periodsPerTurn: Double): Effect.Described
}
