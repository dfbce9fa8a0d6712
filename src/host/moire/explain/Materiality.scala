package moire.explain

/** The materiality floor of a finding (issue 28): an effect must change the signal by a visible amount, at least
  * `minLsb` LSB and `minNoise` times the noise's rms (the floor from neighbouring samples; the larger of the two), measured as the 99th percentile of the
  * change of the prediction it makes over the record (for jitter: the noise it adds at the steepest slope).
  * What is significant but smaller goes to the report's `negligible` list with its size.
  */
final case class Materiality(minLsb: Double = Materiality.MinLsb, minNoise: Double = Materiality.MinNoise) {
  require(minLsb >= 0 && !minLsb.isInfinite, s"--min-effect-lsb must be 0 or more, got $minLsb")
  require(minNoise >= 0 && !minNoise.isInfinite, s"--min-effect-noise must be 0 or more, got $minNoise")
  /** The floor in full-scale units for a recording with this LSB and noise rms. */
  def floor(lsb: Double, noise: Double): Double = math.max(minLsb * lsb, minNoise * noise)
}

object Materiality {
  val MinLsb = 0.25
  val MinNoise = 0.1
  /** The quantile of |change of the prediction| that is the effect's size (robust to a few samples). */
  val Quantile = 0.99

  /** The size of the change from prediction `a` to `b` (from one sample at a random place in each block of `stride`: a
    * regular stride would sample a line at a multiple of fs / stride at the same phase, e.g. at its zeros): the
    * `Quantile` point of |b - a|.
    */
  def size(aS: Array[Double], aC: Array[Double], bS: Array[Double], bC: Array[Double], stride: Int): Double = {
    val n = aS.length
    val at = if (stride <= 1) null else Candidates.spread(n, stride)
    val m = if (at == null) n else at.length
    val d = new Array[Double](2 * m); var k = 0; var q = 0
    while (q < m) { val i = if (at == null) q else at(q); d(k) = math.abs(bS(i) - aS(i)); d(k + 1) = math.abs(bC(i) - aC(i)); k += 2; q += 1 }
    if (k == 0) 0.0 else OrderStats.of(k, d(_), Seq(math.min(k - 1, (Quantile * k).toInt)))(0)
  }
}

/** A significant structure too small to matter: its effect, channel, size, the floor it is below, and what it is (the
  * effect's own sentence, with where it shows: a line's frequency, a harmonic's order), so the list says which structure it was.
  */
final case class Negligible(effect: String, channel: String, sizeLsb: Double, floorLsb: Double, deltaBic: Double, params: Map[String, Double],
                            what: String = "") {
  def json: ujson.Obj = ujson.Obj("effect" -> effect, "channel" -> channel, "size_lsb" -> Report.num(sizeLsb),
    "floor_lsb" -> Report.num(floorLsb), "delta_bic" -> Report.num(deltaBic), "params" -> Report.nums(params),
    "summary" -> ((if (what.isEmpty) effect else s"$effect: $what") +
      f": lowers BIC by $deltaBic%.0f but changes the signal by only $sizeLsb%.3g LSB (floor $floorLsb%.3g LSB): too small to matter"))
}
