package moire.explain

/** The materiality floor of a finding (issue 28): an effect must change the signal by a visible amount, at least
  * `minLsb` LSB and `minNoise` times the noise's rms (the floor from neighbouring samples; the larger of the two), measured as the 99th percentile of the
  * change of the prediction it makes over the record (for jitter: the noise it adds at the steepest slope).
  * What is significant but smaller goes to the report's `negligible` list with its size.
  */
final case class Materiality(minLsb: Double = Materiality.MinLsb, minNoise: Double = Materiality.MinNoise) {
  require(minLsb >= 0 && !minLsb.isInfinite, s"--min-effect-lsb must be a finite number, 0 or more, got $minLsb")
  require(minNoise >= 0 && !minNoise.isInfinite, s"--min-effect-noise must be a finite number, 0 or more, got $minNoise")
  /** The floor in full-scale units for a recording with this LSB and noise rms. */
  def floor(lsb: Double, noise: Double): Double = math.max(minLsb * lsb, minNoise * noise)
}

object Materiality {
  val MinLsb = 0.25
  val MinNoise = 0.1
  /** The quantile of |change of the prediction| that is the effect's size (robust to a few samples). */
  val Quantile = 0.99

  /** Both channels' values of a prediction at the points the size reads (one at a random place in each block of
    * `stride`, all samples when it is 1): a trial keeps these, not two arrays of the record's length.
    */
  final case class Points(stride: Int, s: Array[Double], c: Array[Double])
  object Points {
    def apply(n: Int, stride: Int, fs: Int => Double, fc: Int => Double): Points = {
      val at = if (stride <= 1) null else Candidates.spread(n, stride)
      val m = if (at == null) n else at.length
      val s = new Array[Double](m); val c = new Array[Double](m); var q = 0
      while (q < m) { val i = if (at == null) q else at(q); s(q) = fs(i); c(q) = fc(i); q += 1 }
      Points(stride, s, c)
    }
    /** A linear term's own part of the prediction (its columns times `beta`) at the size's points, its columns made
      * a block at a time by `gen` (the blocks `ColGen.whole` makes: the same numbers, without the whole columns).
      */
    def ofTerm(n: Int, stride: Int, gen: ColGen, beta: Array[Double]): Points = {
      val at = if (stride <= 1) null else Candidates.spread(n, stride)
      val m = if (at == null) n else at.length
      val s = new Array[Double](m); val c = new Array[Double](m)
      Par.blocks(n, Gram.Block) { (lo, hi) =>
        val out = gen.buffers(hi - lo)
        gen.fill(lo, hi, out, 0)
        // the points in [lo, hi): point q lies in [q stride, (q + 1) stride)
        var q = if (at == null) lo else lo / stride
        val end = if (at == null) hi else math.min(m, (hi - 1) / stride + 1)
        while (q < end) {
          val i = if (at == null) q else at(q)
          if (i >= lo && i < hi) {
            var vs = 0.0; var vc = 0.0; var k = 0
            while (k < gen.size) {
              val b = beta(k)
              if (b != 0) { val a = out(2 * k); val d = out(2 * k + 1); if (a != null) vs += b * a(i - lo); if (d != null) vc += b * d(i - lo) }
              k += 1
            }
            s(q) = vs; c(q) = vc
          }
          q += 1
        }
      }
      Points(stride, s, c)
    }
    /** The engine's prediction at the size's points for its record. */
    def of(e: SignalEngine): Points = Points(e.n, strideOf(e.n), e.predSAt, e.predCAt)
  }
  /** The stride of the size's points for a record of n samples: about 200,000 points. */
  def strideOf(n: Int): Int = math.max(1, n / 200000)

  /** The size of the change from prediction `a` to `b` at the same points (one sample at a random place in each block
    * of the stride: a regular stride would sample a line at a multiple of fs / stride at the same phase, e.g. at its
    * zeros): the `Quantile` point of |b - a|.
    */
  def size(a: Points, b: Points): Double = {
    val m = a.s.length
    val d = new Array[Double](2 * m); var k = 0; var q = 0
    while (q < m) { d(k) = math.abs(b.s(q) - a.s(q)); d(k + 1) = math.abs(b.c(q) - a.c(q)); k += 2; q += 1 }
    if (k == 0) 0.0 else OrderStats.of(k, d(_), Seq(math.min(k - 1, (Quantile * k).toInt)))(0)
  }
}

/** A significant structure too small to matter: its effect, channel, size, the floor it is below, and what it is (the
  * effect's own sentence, with where it shows: a line's frequency, a harmonic's order), so the list says which structure it was.
  */
final case class Negligible(effect: String, channel: String, sizeLsb: Double, floorLsb: Double, deltaBic: Double, params: Map[String, Double],
                            what: String = "", takenBy: Seq[String] = Nil) {
  def json: ujson.Obj = ujson.Obj("effect" -> effect, "channel" -> channel, "size_lsb" -> Report.num(sizeLsb),
    "floor_lsb" -> Report.num(floorLsb), "delta_bic" -> Report.num(deltaBic), "params" -> Report.nums(params),
    "taken_by" -> ujson.Arr(takenBy.map(ujson.Str(_)): _*),
    "summary" -> ((if (what.isEmpty) effect else s"$effect: $what") + (
      if (takenBy.isEmpty) f": lowers BIC by $deltaBic%.0f but changes the signal by only $sizeLsb%.3g LSB (floor $floorLsb%.3g LSB): too small to matter"
      else f": lowered BIC by $deltaBic%.0f when found, but ${takenBy.mkString(" and ")}, found after it, took its part: in the final fit it " +
        f"changes the signal by only $sizeLsb%.3g LSB (floor $floorLsb%.3g LSB), too small to matter (the two predict nearly the same signal here)")))
}
