package moire.explain

/** Physical plausibility of a candidate for the recording it was fitted to (issue 12, "no stories"):
  * an interference line must complete at least `MinCycles` cycles in the record, and sampling-clock
  * jitter must be well below the sample period. `why` is None when plausible, else the reason.
  */
object Plausible {
  val MinCycles = 10.0
  /** Largest credible jitter, as a fraction of the sample period. */
  val MaxJitterOfPeriod = 0.01

  def why(c: Cand, fs: Double, n: Int): Option[String] = {
    val seconds = n / fs
    c.effect match {
      case "interference" =>
        c.params.get("frequency_hz").filter(f => f * seconds < MinCycles)
          .map(f => f"a line at $f%.4g Hz completes ${f * seconds}%.2g cycles in the ${seconds}%.3g s record (at least ${MinCycles}%.0f needed)")
      case "jitter" =>
        c.params.get("jitter_s").filter(j => j * fs > MaxJitterOfPeriod)
          .map(j => f"jitter of ${j * 1e12}%.4g ps rms is ${100 * j * fs}%.2g %% of the sample period (at most ${100 * MaxJitterOfPeriod}%.0f %% is credible)")
      case _ => None
    }
  }
}
