package moire.explain.effects

/** The registry: every effect of the catalogue, in the order explain proposes them. Adding an effect is one file and
  * one line here; `simulate --effect`, explain, `EffectSpec.parse`, `--help` and docs/explain.md's table read it.
  */
object Effects {
  val all: Seq[Effect] = Seq(
    Harmonic, Drift, Warmup, ContrastAlongTravel, AmplitudeModulation, Eccentricity, AngleHarmonic, AdcNonlinearity,
    Crosstalk, Interference, ChannelSkew, Bandwidth, Jitter, PhaseNoise, IntensityNoise, AdcBitFault, Clipping, CoarseQuantization,
    HarmonicOrder, Reversal)

  val byName: Map[String, Effect] = all.map(e => e.name -> e).toMap
  def apply(name: String): Option[Effect] = byName.get(name)
  val names: Seq[String] = all.map(_.name)
  val signals: Seq[Effect] = all.filterNot(_.calibration)

  /** One line per effect for `--help`. */
  def help: String = all.map(e => s"  ${e.name}: ${e.params.map(_.name).mkString(", ")}").mkString("\n")

  /** docs/explain.md's catalogue table (a test checks the page holds exactly this). */
  def markdownTable: String = {
    val head = "| effect | parameters | what it is | where it shows |\n|---|---|---|---|"
    val rows = all.map { e =>
      val ps = e.params.map(p => s"`${p.name}` (${(Seq(p.unit).filter(_.nonEmpty) :+ p.range).mkString(", ")})").mkString(", ")
      s"| `${e.name}`${if (e.calibration) " (calibration)" else ""} | $ps | ${e.what.replace("|", "/")} | ${e.shows} |"
    }
    (head +: rows).mkString("\n")
  }
}
