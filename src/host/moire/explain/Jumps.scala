package moire.explain

import moire.recording.Recording

/** Steps of the fringe phase between two neighbouring samples where the motion is smooth on both sides: samples cut
  * out of a capture (a FIFO that overflowed, a USB packet dropped: the rows go on at a later phase), or the read head
  * slipping. No trajectory follows a step: it shows as a window where the model does not follow, or, where it falls on
  * a segment's end, as nothing at all. The data's phase is read through the fitted ellipse, and a step is an increment
  * from one sample to the next far beyond the noise's from its neighbours' median, with those around it at the noise's.
  */
object Jumps {
  /** Noise widths (robust sd of the phase's increment a sample) a step exceeds. */
  val Off = 12.0
  /** Samples on each side of a step whose increments stay within `Near` noise widths (the motion smooth there). */
  val Side = 8
  val Near = 4.0
  /** Steps smaller than this (periods) are not told: a shock or a slip of a few degree is no lost sample. */
  val MinPeriods = 0.02
  /** Increments standing out beyond which a record holds no few steps but a motion or noise not followed. */
  val MaxFlagged = 4096

  /** A step of `periods` (-0.5..0.5] from sample `at` - 1 to `at`, with the fringe's samples per period there (signed:
    * negative when the phase runs backwards).
    */
  final case class Jump(at: Int, periods: Double, samplesPerPeriod: Double)

  /** The steps in the engine's samples [a, b), at most `max`, the largest first. */
  def find(e: SignalEngine, a: Int, b: Int, max: Int = 3): Seq[Jump] = {
    val bad = e.badData
    steps(e.n, e.ys, e.yc, e.base, i => bad != null && bad(i), a, b, max)
  }

  /** The steps in a whole recording, its data read through the ellipse `base` (`SignalEngine.base`, full scale),
    * samples of bad data (rows of the record) left out; at most `max`, in order.
    */
  def inRecord(rec: Recording, base: Array[Double], bad: Int => Boolean, max: Int = 64): Seq[Jump] = {
    val lsb = rec.adc.lsb
    val table = if (rec.adc.bits <= 16) Array.tabulate(1 << rec.adc.bits)(c => rec.adc.fromPins(c) * lsb) else null
    def value(codes: Array[Int]): Int => Double = if (table != null) i => table(codes(i)) else i => rec.adc.fromPins(codes(i)) * lsb
    steps(rec.length, value(rec.sin), value(rec.cos), base, bad, 0, rec.length, max).sortBy(_.at)
  }

  private def steps(n: Int, xs: Int => Double, xc: Int => Double, p: Array[Double], skip: Int => Boolean, a: Int, b: Int,
                    max: Int): Seq[Jump] = {
    val lo = math.max(1, a); val hi = math.min(n, b)
    if (hi - lo < 4 * Side || !regular(p)) return Nil
    val th = phaseOf(xs, xc, p)
    def inc(i: Int) = wrap(th(i) - th(i - 1))
    def ok(i: Int) = !skip(i) && !skip(i - 1)
    // the noise of an increment, from a strided sample of the increments' changes (the speed's a sample is far below)
    val stride = math.max(1, (hi - lo) / 65536)
    val dd = (lo + 1 until hi by stride).filter(i => ok(i) && ok(i - 1)).map(i => math.abs(inc(i) - inc(i - 1))).toArray
    val sd = 1.4826 * median(dd) / math.sqrt(2)
    if (!(sd > 0)) return Nil
    // the increments whose change stands out, a block at a time on all cores
    val block = Par.Block; val nb = (hi - lo + block - 1) / block
    val parts = new Array[Array[Int]](nb)
    Par.blocks(hi - lo, block) { (b0, b1) =>
      val out = Array.newBuilder[Int]; var i = lo + b0; var prevTh = th(i - 1); var prevInc = Double.NaN
      if (i - 1 >= lo) prevInc = inc(i - 1)
      while (i < lo + b1) {
        val t = th(i); val c = wrap(t - prevTh)
        if (!prevInc.isNaN && ok(i) && ok(i - 1) && math.abs(c - prevInc) > Off * sd) out += i
        prevTh = t; prevInc = c; i += 1
      }
      parts(b0 / block) = out.result()
    }
    // (the reference path runs the loop as one block: the others stay empty)
    val flagged = parts.filter(_ != null).flatten
    if (flagged.isEmpty || flagged.length > MaxFlagged) return Nil
    // each step changes two increments: into it and out of it; the one that stands out from its neighbours is the step.
    // The neighbours on each side on a line of their own (a motion that speeds up changes them a sample by about the
    // noise, and the samples lost carry the speed on to where the record goes on), read at the step
    def side(k: Int, js: Seq[Int]): (Double, Double) = {
      val x = js.map(j => (j - k).toDouble); val y = js.map(inc)
      val mx = x.sum / x.size; val my = y.sum / y.size
      val sxx = x.map(v => (v - mx) * (v - mx)).sum
      val b = if (sxx > 0) x.zip(y).map { case (u, v) => (u - mx) * (v - my) }.sum / sxx else 0.0
      (my - b * mx, b)
    }
    def sides(k: Int) = ((k - Side until k).filter(j => j >= lo && ok(j)), (k + 1 to k + Side).filter(j => j < hi && ok(j)))
    def local(k: Int): Double = {
      val (l, r) = sides(k)
      if (l.size < 3 || r.size < 3) Double.NaN else (side(k, l)._1 + side(k, r)._1) / 2
    }
    val out = flagged.flatMap(k => Seq(k - 1, k)).distinct.filter { k => val m = local(k); k >= lo && ok(k) && !m.isNaN && math.abs(inc(k) - m) > Off * sd }
    if (SignalEngine.debug) System.err.println(f"jumps [$a, $b): sd $sd%.3g rad, ${out.length} stand out: " +
      out.take(6).map(k => f"$k:${(inc(k) - local(k)) / sd}%.1f").mkString(" "))
    if (out.isEmpty || out.length > max) return Nil
    out.toSeq.flatMap { k =>
      val m = local(k); val step = inc(k) - m
      val (l, r) = sides(k)
      def within(js: Seq[Int]) = { val (c, b) = side(k, js); js.forall(j => math.abs(inc(j) - c - b * (j - k)) <= Near * sd) }
      val smooth = l.size >= Side / 2 && r.size >= Side / 2 && math.abs(m) < 0.3 * 2 * math.Pi && within(l) && within(r)
      if (smooth && math.abs(step) > 2 * math.Pi * MinPeriods)
        Some(Jump(k, step / (2 * math.Pi), if (m != 0) 2 * math.Pi / m else Double.PositiveInfinity))
      else None
    }.sortBy(j => -math.abs(j.periods))
  }

  /** Where the data go over [a, b) of the engine's samples, read from their own phase (not the fitted trajectory's,
    * which does not follow there): the position's range in periods from the phase at `a` and the fringe frequency's
    * range (Hz), from medians of the phase's increments over blocks of 16 samples. None where the ellipse is singular.
    */
  def track(e: SignalEngine, a: Int, b: Int): Option[(Double, Double, Double, Double)] = {
    if (b - a < 2 || !regular(e.base)) return None
    val th = phaseOf(e.ys(_), e.yc(_), e.base)
    val bad = e.badData
    var x = 0.0; var x0 = 0.0; var x1 = 0.0; var f0 = Double.MaxValue; var f1 = 0.0
    val blk = new Array[Double](16); var nb = 0; var prev = th(a); var i = a + 1
    while (i < b) {
      val t = th(i)
      if (bad == null || (!bad(i) && !bad(i - 1))) {
        val d = wrap(t - prev); x += d / (2 * math.Pi); x0 = math.min(x0, x); x1 = math.max(x1, x)
        blk(nb) = d; nb += 1
        if (nb == blk.length) { val f = math.abs(median(blk)) * e.fs / (2 * math.Pi); f0 = math.min(f0, f); f1 = math.max(f1, f); nb = 0 }
      }
      prev = t; i += 1
    }
    if (f0 == Double.MaxValue) { f0 = 0.0 }
    Some((x0, x1, f0, f1))
  }

  /** Whether the fitted ellipse's 2 x 2 matrix (`SignalEngine.base`: offset and the sin and cos parts of each channel) can be inverted. */
  private def regular(p: Array[Double]): Boolean = math.abs(p(1) * p(5) - p(2) * p(4)) > 1e-12
  /** The data's fringe phase (radian) at a sample: [sin; cos] = M^-1 [u; v], M = [[p1, p2], [p4, p5]], the offsets
    * taken off (the amplitudes and the phase error with M; its determinant's size and sign leave the increments alone).
    */
  private def phaseOf(xs: Int => Double, xc: Int => Double, p: Array[Double]): Int => Double = { i =>
    val u = xs(i) - p(0); val v = xc(i) - p(3); math.atan2(p(5) * u - p(2) * v, -p(4) * u + p(1) * v)
  }

  private def wrap(x: Double): Double = { val t = x % (2 * math.Pi); if (t > math.Pi) t - 2 * math.Pi else if (t <= -math.Pi) t + 2 * math.Pi else t }
  private def median(xs: Array[Double]): Double = if (xs.isEmpty) 0.0 else { val s = xs.sorted; s(s.length / 2) }

  /** The samples lost that would make a step (a share of a fringe period), and the period in samples. */
  private def lost(j: Jump): String = {
    val spp = math.abs(j.samplesPerPeriod)
    // samples lost move the phase on along the motion
    val along = if (j.samplesPerPeriod < 0) -j.periods else j.periods
    if (spp.isInfinite || spp > 1e9) "" else f"about ${(((along % 1) + 1) % 1) * spp}%.1f samples lost, or that plus a multiple of ${spp}%.1f"
  }

  /** What a step says, for a window's summary: its size, where, and the samples lost that would make it. */
  def describe(j: Jump, fs: Double): String =
    f"the signals' phase steps by ${j.periods}%+.3f period (${j.periods * 360}%+.1f degree) between data rows ${j.at} and ${j.at + 1} " +
      f"(${j.at / fs}%.6g s), the motion smooth on both sides: samples lost from the capture (a FIFO overflow, a dropped " +
      f"transfer: ${lost(j)} (a fringe period there)) or the read head slipping; the model fits no step"

  /** The record's steps, as a note. */
  def note(js: Seq[Jump], fs: Double): Option[String] = if (js.isEmpty) None else {
    val shown = js.take(4).map(j => f"${j.periods}%+.3f period between data rows ${j.at} and ${j.at + 1} (${j.at / fs}%.6g s; ${lost(j)})").mkString(", ") +
      (if (js.size > 4) s", ... (${js.size} in all)" else "")
    Some(s"the signals' phase steps from one sample to the next with the motion smooth on both sides ${if (js.size == 1) "once" else s"${js.size} times"}: " +
      s"$shown: samples lost from the capture (a FIFO overflow, a dropped transfer) or the read head slipping; the model fits no step " +
      "(where one falls on a trajectory segment's end the segments take it up; elsewhere it leaves a window the model does not follow)")
  }
}
