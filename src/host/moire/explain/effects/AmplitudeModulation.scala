package moire.explain.effects

import moire.explain._

/** The amplitude following the mechanical angle once per turn (eccentric disk, air gap). */
object AmplitudeModulation extends Effect {
  val name = "amplitude_modulation"
  val params = Seq(Param("depth", "relative", "0..1"), Param("phase_deg", "degree", "-180..180"))
  override val needs: Seq[String] = Seq("depth")
  override def check(e: EffectSpec): Option[String] = Effect.within(e, "depth", 0, 1, "from 0 to 1")
  val what = "amplitude * (1 + depth cos(mechanical angle + phase)); needs lines_per_rev"
  val shows = "against mechanical angle"
  override def example: Example = Example(EffectSpec(name, Map("depth" -> 0.005)), "constant:100000", Some(100.0))
  val domain: Domain = Domain.Periodic
  override def cycles(e: SignalEngine): Double = e.periodsPerTurn.orElse(e.rec.linesPerRev).fold(0.0)(e.travelPeriods / _)
  override val plot: PlotKind = PlotKind.MechanicalAngle

  override def validate(e: EffectSpec, m: PhysicsModel): Unit =
    if (m.linesPerRev.isEmpty) throw new ExplainError(s"$name needs lines_per_rev (--lines-per-rev)")
  override def backward(sp: ModelSpec, e: EffectSpec): ModelSpec = sp.copy(terms = sp.terms :+ Term.Am)
  override def searches(c: Candidates): Seq[() => Seq[Cand]] =
    if (c.engine.rec.linesPerRev.isDefined || c.mechanical) Seq(() => c.linear(Term.Am).map(_._1).toSeq) else Nil
  override def describe(t: Term, b: Array[Double], sd: Array[Double], e: SignalEngine): Effect.Described = {
    val (a, sa) = Effect.amp(b(0), b(1), sd(0), sd(1)); val (ph, sph) = Effect.deg(b(0), -b(1), a, sa)
    (Map("depth" -> a, "phase_deg" -> ph), Map("depth" -> sa, "phase_deg" -> sph), "against mechanical angle: amplitude", "both")
  }

  override def forward(specs: Seq[EffectSpec], m: PhysicsModel, p: moire.signal.SignalParams): Forward = new Forward {
    private val depth = specs.map(_.p("depth", 0.0)).toArray; private val phase = specs.map(_.p("phase_deg", 0.0)).toArray
    private val l = m.linesPerRev.get
    override def gain(v0: Double, a: At): Double = {
      var v = v0; var i = 0
      while (i < depth.length) { v *= 1 + depth(i) * math.cos(2 * math.Pi * a.ph / l + math.toRadians(phase(i))); i += 1 }
      v
    }
  }

  def summary(p: Map[String, Double], channel: String, fMin: Double, fMax: Double): String =
    f"amplitude follows the mechanical angle: ${100 * Effect.g(p, "depth")}%.2f %% modulation once per revolution"
}
