package moire.explain

/** Runs of samples the converter or the transfer lost: both channels held at their last codes (a FIFO repeating a
  * word) or both at an ADC end code, while the fit's signal moves on by far more than the noise. No read head holds
  * both channels still while the fringe turns. They are weighted out of the fit and named in the notes. Before,
  * another generator's three runs of 30 samples at code 0 were samples at the rail, whose censored likelihood a
  * "jitter" of 380 ps took up; two holds of 40 samples were misfit windows and a jitter of 1400 ps.
  */
object Dropouts {
  /** Noise widths the held value lies off the prediction somewhere in the run. */
  val Off = 10.0
  /** Samples a hold lasts at least (a repeated pair of codes; at an end code, two). */
  val MinHold = 4
  /** Dropouts are at most this share of the samples (more is no dropout: a stopped head, a model that does not follow). */
  val MaxShare = 0.01

  /** The runs [a, b) of samples lost, in order (none where they would be more than `MaxShare`). */
  def find(e: SignalEngine): Seq[(Int, Int)] = {
    val n = e.n; val ys = e.ys; val yc = e.yc
    if (n < 64) return Nil
    val sdS = math.max(math.sqrt(e.noise.varS), 0.5 * e.step); val sdC = math.max(math.sqrt(e.noise.varC), 0.5 * e.step)
    @inline def held(i: Int) = i > 0 && ys(i) == ys(i - 1) && yc(i) == yc(i - 1)
    @inline def rail(i: Int) = e.atRail(ys(i)) && e.atRail(yc(i))
    // a code at the rail only says the signal is there or beyond: a prediction beyond the rail is clipping, not a loss
    @inline def far(y: Double, p: Double, sd: Double) =
      if (y >= e.railHi - 0.5 * e.lsb) p < y - Off * sd
      else if (y <= e.railLo + 0.5 * e.lsb) p > y + Off * sd
      else math.abs(y - p) > Off * sd
    @inline def off(i: Int) = far(ys(i), e.predSAt(i), sdS) || far(yc(i), e.predCAt(i), sdC)
    val out = Seq.newBuilder[(Int, Int)]; var total = 0; var i = 1
    while (i < n && total <= MaxShare * n) {
      if (rail(i) || held(i)) {
        // a hold counts from the sample it repeats
        val a = if (held(i)) i - 1 else i
        var b = i + 1; while (b < n && (rail(b) || held(b))) b += 1
        val atRail = (a until b).forall(rail)
        if (b - a >= (if (atRail) 2 else MinHold) && (a until b).exists(off)) { out += a -> b; total += b - a }
        i = b
      } else i += 1
    }
    if (total > MaxShare * n) Nil else out.result()
  }

  /** The mask of the runs (null: none). */
  def mask(n: Int, runs: Seq[(Int, Int)]): Array[Boolean] =
    if (runs.isEmpty) null else { val m = new Array[Boolean](n); runs.foreach { case (a, b) => java.util.Arrays.fill(m, a, b, true) }; m }

  /** The report's note on them (None: none). Rows are the data rows, counted from 1. */
  def note(runs: Seq[(Int, Int)]): Option[String] = if (runs.isEmpty) None else {
    val shown = runs.take(4).map { case (a, b) => s"${a + 1}..$b" }.mkString(", ") + (if (runs.size > 4) s", ... (${runs.size} in all)" else "")
    val samples = runs.map { case (a, b) => b - a }.sum
    Some(s"${runs.size} run${if (runs.size == 1) "" else "s"} of samples (data rows $shown; $samples samples) hold both channels still, " +
      "at their last codes or at an end code, where the signal moves on: data lost by the converter or the transfer " +
      "(a dropout, a repeated word), no effect of the read head; left out of the fit")
  }
}
