package moire.explain.effects

import moire.explain._

/** Time and position along the travel go together in a one-way scan: a change in time (drift, warm-up) and a change
  * along the travel (contrast) predict the same signal there. The finding names the other and the measurement that
  * separates them.
  */
object TimeOrTravel {
  /** |r| of position and time above which the record cannot separate them well. */
  val Correlated = 0.9

  def lookAlikes(e: SignalEngine, other: String): Seq[String] = {
    val r = Identify.correlation(e)
    if (math.abs(r) < Correlated) Nil
    else Seq(f"$other predicts nearly the same signal here: position along the travel and time correlate (r = $r%.3f); " +
      "a scan back over the same travel, or a wait at one position, separates a change in time from one along the travel")
  }
}
