package moire.explain

/** What a signal recording could not test (issue 12, Build 5): a clean report then means "looked and found
  * nothing" only for the effects not listed here.
  */
object Coverage {
  /** The reference columns a recording may carry. */
  val ReferenceColumns: Seq[String] = moire.recording.Reference.Columns

  def untested(e: SignalEngine, fMin: Double, fMax: Double): Seq[String] = {
    val seconds = e.n / e.fs
    val rec = e.rec
    val refs = ReferenceColumns.filter(rec.extra.contains)
    Seq(
      Some(f"interference below ${effects.Interference.MinCycles / seconds}%.4g Hz: the ${seconds}%.4g s record holds fewer than ${effects.Interference.MinCycles}%.0f cycles of it"),
      if (Identifiable.oneSpeed(fMin, fMax))
        Some(f"channel skew, bandwidth and crosstalk: the fringe frequency spans only ${fMin}%.4g .. ${fMax}%.4g Hz; a skew there is a phase error, a low-pass or crosstalk a change of the amplitudes and phase")
      else None,
      if (rec.linesPerRev.isEmpty && !refs.exists(_ != "position"))
        Some("amplitude modulation and eccentricity with the mechanical angle: no lines_per_rev and no reference column")
      else None,
      if (e.reference.isDefined) Identifiable.referenceNoise(e, fMin, fMax)
      else if (Identifiable.motionConfounded(e)) Some(Identifiable.untested(e))
      else Some(s"effects confounded with non-uniform motion (a harmonic of the mechanical angle, eccentricity): not identifiable " +
        s"without a reference column (${ReferenceColumns.mkString(", ")}); the motion is fitted from the signals" +
        e.referenceRefused.map(r => s"; the reference: $r").getOrElse(""))
    ).flatten
  }
}
