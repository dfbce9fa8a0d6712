package moire.explain

/** Isolated samples (one to three in a row) far off the signal with their neighbours on it: data glitches (an ADC's or a transfer's error, a
  * spike), which no effect of the read head makes. They are weighted out of the fit before the search and named in the
  * report's notes. Before, three samples at code 0 in a clean record were taken as samples at the rail (censored,
  * nothing said), and ten at mid-scale made misfit windows and a "phase noise" of unexplained structure.
  */
object Glitches {
  /** Robust noise widths (the residual's median absolute value, as a Gaussian's sd) a glitch lies off the prediction. */
  val Off = 10.0
  /** Noise widths within which both neighbours of a glitch lie (it is alone; or a tenth of its own distance). */
  val Near = 4.0
  /** Samples the noise width is the median of, at most (every k-th). */
  val SdSamples: Int = 1 << 18
  /** Steps from its channel's extreme code within which a sample with the prediction beyond it is a clipped top. */
  val AtExtreme = 3.0
  /** Consecutive samples a glitch lasts at most. */
  val MaxRun = 3
  /** Glitches are at most this share of the samples (more is no glitch: a misfit or a wrong model). */
  val MaxShare = 1e-3

  /** The samples (sorted) of `e`'s default fit that are glitches, each with how far off it lies (LSB, the larger of
    * the two channels'). The data are the raw codes; a sample held at a saturation level (censored) is off only by
    * how far the prediction falls short of that level: at the level, any prediction beyond it fits it. Before, where
    * both channels of another generator's record were clipped at once the fit's phase was free, and the record's last
    * three samples, at the rails, were told as glitches 216..464 LSB off.
    */
  def find(e: SignalEngine): Seq[(Int, Double)] = {
    val n = e.n
    if (n < 64) return Nil
    // a sample at its channel's extreme (within `AtExtreme` steps) with the prediction beyond it is a top the signal
    // was clipped at, no glitch: at high speed a clipped top lasts a sample or two, its neighbours on the signal
    val (loS, hiS) = Doubles.range(n)(e.ys(_)); val (loC, hiC) = Doubles.range(n)(e.yc(_))
    def off(y: Array[Double], rep: Array[Double], res: Array[Double], cen: Array[Double], hi: Double, lo: Double)(i: Int): Double =
      if (cen != null && !cen(i).isNaN) math.max(0.0, cen(i))
      else {
        val p = rep(i) - res(i); val v = y(i)
        if ((v >= hi - AtExtreme * e.step && p >= v) || (v <= lo + AtExtreme * e.step && p <= v)) 0.0 else v - p
      }
    val ds = off(e.ys, e.repS, e.resS, e.cens.censS, hiS, loS) _; val dc = off(e.yc, e.repC, e.resC, e.cens.censC, hiC, loC) _
    // the median absolute residual of each channel, as a Gaussian's sd
    // (over at most `SdSamples` spread over the record: it is looked for after each finding, and at 20 M samples two
    // medians of all samples cost a second)
    // (the censored samples left out: at a level, their zero would pull the median down)
    def sd(d: Int => Double, cen: Array[Double]): Double = {
      val st = math.max(1, n / SdSamples)
      val at = (0 until n / st).iterator.map(_ * st).filter(i => cen == null || cen(i).isNaN).toArray
      if (at.isEmpty) return 0.5 * e.step
      val med = OrderStats.of(at.length, q => math.abs(d(at(q))), Seq(at.length / 2))(0) * 1.4826
      math.max(med, 0.5 * e.step)
    }
    val (ss, sc) = (sd(ds, e.cens.censS), sd(dc, e.cens.censC))
    def far(i: Int) = math.abs(ds(i)) > Off * ss || math.abs(dc(i)) > Off * sc
    // a neighbour j of glitch i lies within `Near` noise widths, or a tenth of the glitch's distance (the fit's phase,
    // pulled by the glitch, takes its neighbours off too: ten mid-scale glitches at 100 kHz fringes left theirs 10-30 LSB off)
    def near(j: Int, i: Int) = j < 0 || j >= n || {
      val w = math.max(Near, 0.1 * math.max(math.abs(ds(i)) / ss, math.abs(dc(i)) / sc))
      math.abs(ds(j)) < w * ss && math.abs(dc(j)) < w * sc
    }
    if (SignalEngine.debug) (0 until n).filter(far).take(40).foreach(i => System.err.println(
      f"glitch? row ${i + 1}: sin ${ds(i) / e.lsb}%.1f cos ${dc(i) / e.lsb}%.1f LSB; before ${ds(math.max(0, i - 1)) / e.lsb}%.1f ${dc(math.max(0, i - 1)) / e.lsb}%.1f, " +
      f"after ${ds(math.min(n - 1, i + 1)) / e.lsb}%.1f ${dc(math.min(n - 1, i + 1)) / e.lsb}%.1f; sd ${ss / e.lsb}%.2f ${sc / e.lsb}%.2f"))
    // runs of up to `MaxRun` far samples between neighbours on the signal (a glitch may last a sample or three)
    def size(i: Int) = math.max(math.abs(ds(i)) / ss, math.abs(dc(i)) / sc)
    val out = Seq.newBuilder[(Int, Double)]; var k = 0; var i = 0
    while (i < n && k <= MaxShare * n) {
      if (far(i)) {
        var j = i; while (j < n && far(j)) j += 1
        val top = (i until j).maxBy(size)
        if (j - i <= MaxRun && near(i - 1, top) && near(j, top))
          for (q <- i until j) { out += q -> math.max(math.abs(ds(q)), math.abs(dc(q))) / e.lsb; k += 1 }
        i = j
      }
      else i += 1
    }
    val found = out.result()
    if (k > MaxShare * n || lockedToFringe(e, found.map(_._1))) Nil else found
  }

  /** Share of a fringe period's circle (the mean resultant length) above which samples off the signal lie at one
    * fringe phase (or at two half a period apart, or four a quarter apart): the fringe's own shape, no glitch.
    */
  val Locked = 0.9
  /** Glitches (runs of samples) that must gather at one phase before they are taken for the fringe's own shape. */
  val LockedRuns = 5

  /** `LockedRuns` or more glitches whose fringe phases (or twice or four times them: the extremes of either channel)
    * gather at one angle: a clipped top at high speed lasts one to three samples with its neighbours on the signal, as
    * a glitch does, but at the same phase each period (another generator's sin clipped 12 LSB at 28 kHz: five
    * "glitches", all at 90 degrees, hid the clipping).
    */
  private def lockedToFringe(e: SignalEngine, at: Seq[Int]): Boolean = {
    val runs = at.indices.filter(j => j == 0 || at(j) != at(j - 1) + 1).map(at(_))
    runs.size >= LockedRuns && Seq(1, 2, 4).exists { k =>
      val (c, s) = runs.foldLeft((0.0, 0.0)) { case ((c, s), i) => val a = k * e.angle(i); (c + math.cos(a), s + math.sin(a)) }
      math.hypot(c, s) / runs.size > Locked
    }
  }

  /** `known` and the glitches `find` sees beyond them in `e`'s fit as it stands; new ones are weighted out (with the
    * samples already out) and the fit converges.
    */
  def more(e: SignalEngine, known: Seq[(Int, Double)]): Seq[(Int, Double)] = {
    val had = known.map(_._1).toSet
    val fresh = find(e).filterNot(g => had(g._1))
    if (fresh.isEmpty || known.size + fresh.size > MaxShare * e.n) known
    else { e.badData = union(e.badData, mask(e.n, fresh)); e.exclude(e.excluded); (known ++ fresh).sortBy(_._1) }
  }

  /** The mask of the glitches (null: none). */
  def mask(n: Int, at: Seq[(Int, Double)]): Array[Boolean] =
    if (at.isEmpty) null else { val m = new Array[Boolean](n); at.foreach(g => m(g._1) = true); m }

  /** Samples weighted out by either mask (null: none). */
  def union(a: Array[Boolean], b: Array[Boolean]): Array[Boolean] =
    if (a == null) b else if (b == null) a else Array.tabulate(a.length)(i => a(i) || b(i))

  /** The report's note on them (None: none). Rows are the data rows, counted from 1. */
  def note(at: Seq[(Int, Double)]): Option[String] = if (at.isEmpty) None else {
    val rows = at.take(5).map(g => (g._1 + 1).toString).mkString(", ") + (if (at.size > 5) s", ... (${at.size} in all)" else "")
    val (lo, hi) = (at.map(_._2).min, at.map(_._2).max)
    val one = at.size == 1
    Some(f"${at.size} isolated sample${if (one) "" else "s"} (data row${if (one) "" else "s"} $rows) " +
      f"${if (one) "lies" else "lie"} ${if (lo == hi) f"$lo%.0f" else f"$lo%.0f..$hi%.0f"} LSB off the signal with " +
      f"${if (one) "its" else "their"} neighbours on it: data glitches (an ADC's or a transfer's error, a spike), no effect of the " +
      "read head; left out of the fit")
  }
}
