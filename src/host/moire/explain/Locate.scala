package moire.explain


/** Where the residual departs from white noise: against time, fringe phase, speed, frequency, per channel,
  * and in the code histogram. Each test is a chi-square (or spectral peak) test with a strict threshold
  * (about 6 standard deviations) so that clean recordings locate nothing.
  */
object Locate {
  /** chi-square with `dof` degrees of freedom, as standard deviations above its mean. */
  def zOf(chi2: Double, dof: Int): Double = (chi2 - dof) / math.sqrt(2.0 * dof)
  val Z = 6.0
  /** Cycles in the spectrum's span below which its strongest bin is called a wander, not a line. */
  val SlowCycles = 10
  /** A departure's size: how far the residual departs (LSB), where a test can say (the materiality of `unexplained`). */
  val SizeLsb = "size_lsb"
  /** Where a test knows only the least a departure's size may be (LSB): a spectrum's strongest bin. */
  val AtLeastLsb = "size_at_least_lsb"

  /** Every test, or those whose `where` starts with a name `want` takes (the ones an effect claims). */
  def all(e: SignalEngine, want: String => Boolean = _ => true): Seq[Located] = {
    // each test its own method: small methods for the JIT to compile (one method of all of them was compiled four
    // times over in a run, a few seconds of a compiler thread on a 2-core machine)
    val out = Seq.newBuilder[Located]
    againstTime(e, want, out); againstPhase(e, want, out); againstSpeed(e, want, out); spectrum(e, want, out)
    perChannel(e, want, out); codeHistogram(e, want, out)
    out.result()
  }

  /** Bin means of one channel's residual by bin index; returns (chi2, worst bin, its mean). */
  private def binMeans(n: Int, r: Array[Double], sd: Double, bins: Int, bin: Int => Int): (Double, Int, Double, Array[Double]) = {
    val sum = new Array[Double](bins); val cnt = new Array[Int](bins); var i = 0
    while (i < n) { val b = bin(i); sum(b) += r(i); cnt(b) += 1; i += 1 }
    val mean = Array.tabulate(bins)(b => if (cnt(b) > 0) sum(b) / cnt(b) else 0.0)
    val z2 = Array.tabulate(bins)(b => if (cnt(b) > 0) mean(b) * mean(b) * cnt(b) / (sd * sd) else 0.0)
    val used = cnt.count(_ > 0)
    val worst = z2.indices.maxBy(z2(_))
    (z2.sum - 1, worst, mean(worst), mean) -> used match { case ((c, w, m, a), u) => (zOf(c, math.max(1, u - 1)), w, m, a) }
  }

  /** Residual means against time. */
  private def againstTime(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val rs = e.resS; val rc = e.resC; val lsb = e.lsb; val n = e.n
    val sdS = math.sqrt(e.noise.varS); val sdC = math.sqrt(e.noise.varC)
    // against time
    val tb = 32
    for ((r, sd, ch) <- Seq((rs, sdS, "sin"), (rc, sdC, "cos")) if want("against time")) {
      val (z, w, m, _) = binMeans(n, r, sd, tb, i => (i.toLong * tb / n).toInt)
      val t0 = w * n / tb / e.fs; val t1 = (w + 1) * n / tb / e.fs
      out += Located(s"against time, $ch channel", f"residual mean ${m / lsb}%.2f LSB at $t0%.4g..$t1%.4g s (chi-square ${z}%.1f sd)",
        Map("chi2_sd" -> z, "t0_s" -> t0, "t1_s" -> t1, "mean_lsb" -> m / lsb, SizeLsb -> math.abs(m / lsb)), z > Z)
    }
  }

  /** Residual means against fringe phase. */
  private def againstPhase(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val rs = e.resS; val rc = e.resC; val lsb = e.lsb; val n = e.n
    val sdS = math.sqrt(e.noise.varS); val sdC = math.sqrt(e.noise.varC)
    // against fringe phase
    val pb = 64
    for ((r, sd, ch) <- Seq((rs, sdS, "sin"), (rc, sdC, "cos")) if want("against fringe phase")) {
      val (z, w, m, _) = binMeans(n, r, sd, pb, i => { val p = e.phase(i) - math.floor(e.phase(i)); math.min(pb - 1, (p * pb).toInt) })
      out += Located(s"against fringe phase, $ch channel", f"residual mean ${m / lsb}%.2f LSB near ${360.0 * (w + 0.5) / pb}%.0f degree (chi-square $z%.1f sd)",
        Map("chi2_sd" -> z, "phase_deg" -> 360.0 * (w + 0.5) / pb, "mean_lsb" -> m / lsb, SizeLsb -> math.abs(m / lsb)), z > Z)
    }
  }

  /** Amplitude, phase and noise against speed. */
  private def againstSpeed(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val n = e.n
    val sdS = math.sqrt(e.noise.varS); val sdC = math.sqrt(e.noise.varC)
    // against speed: in-phase (amplitude) and quadrature (phase) projections per speed bin
    val sb = 8
    // the slowest, the speed at each eighth of the samples, the fastest
    lazy val sorted = OrderStats.of(n, i => math.abs(e.freq(i)), (0 until sb).map(k => k * n / sb) :+ (n - 1))
    lazy val edges = Array.tabulate(sb - 1)(k => sorted(k + 1))
    if ((want("against speed") || want("noise against speed")) && sorted(sb) - sorted(0) > 0.05 * sorted(sb)) Laps("locate: against speed") {
      // one pass: each sample's speed bin found once for both channels' projections and the noise (each sum gets the
      // same additions in the same order as a pass of its own)
      // the projections per speed bin and direction of motion (bin b + sb for the samples moving backwards): a lag (a
      // skew, a low-pass) and a crosstalk's gain turn with the direction, and in a bin of |speed| that held both the
      // halves cancelled (a 1.5 ns skew under back-and-forth motion, 2 LSB, read -3.0 sd there, and a jitter was found)
      val m2 = 2 * sb
      val pu = Array.ofDim[Double](2, m2); val pv = Array.ofDim[Double](2, m2); val uu = Array.ofDim[Double](2, m2); val vv = Array.ofDim[Double](2, m2)
      val ss = new Array[Double](sb); val cnt = new Array[Int](sb); val cntD = new Array[Int](m2)
      speedSums(e, edges, sdS * sdS, sdC * sdC, pu, pv, uu, vv, ss, cnt, cntD, -0.01 * sorted(sb))
      // the direction most samples move in, for the figures the summary shows
      val back = (0 until sb).map(b => cntD(b + sb)).sum > (0 until sb).map(cntD).sum
      val shown = (0 until sb).map(b => if (back) b + sb else b)
      for ((sd, ch, k) <- Seq((sdS, "sin", 0), (sdC, "cos", 1))) {
        val (pu1, pv1, uu1, vv1) = (pu(k), pv(k), uu(k), vv(k))
        val za = (0 until m2).map(b => if (uu1(b) > 0) pu1(b) * pu1(b) / (uu1(b) * sd * sd) else 0.0)
        val zp = (0 until m2).map(b => if (vv1(b) > 0) pv1(b) * pv1(b) / (vv1(b) * sd * sd) else 0.0)
        val amp = (0 until m2).map(b => if (uu1(b) > 0) pu1(b) / uu1(b) else 0.0); val ph = (0 until m2).map(b => if (vv1(b) > 0) math.toDegrees(pv1(b) / vv1(b)) else 0.0)
        val used = (0 until m2).count(b => cntD(b) > 0)
        val z = zOf(za.sum + zp.sum - 4, math.max(1, 2 * used - 4))
        // the change of the signal: per bin the amplitude's (phase's) part times the peak of the fundamental (its slope)
        // (over the bins of 1 % of the samples or more: in a few samples, a standstill's wobble about zero speed
        // moving backwards, the noise alone reads as a change of sd * sqrt(2 / samples))
        val size = (0 until m2).filter(b => cntD(b) >= 0.01 * n).map { b => val m = cntD(b).toDouble
          math.max(math.abs(amp(b)) * math.sqrt(2 * uu1(b) / m), math.abs(math.toRadians(ph(b))) * math.sqrt(2 * vv1(b) / m)) }.maxOption.getOrElse(0.0)
        val (a0, a1, p0, p1) = (amp(shown.head), amp(shown.last), ph(shown.head), ph(shown.last))
        val lo = sorted(0) / 1e3; val hi = sorted(sb) / 1e3
        out += Located(s"against speed, $ch channel",
          f"amplitude ${100 * a0}%+.3f %% .. ${100 * a1}%+.3f %%, phase ${p0}%+.3f .. ${p1}%+.3f degree from $lo%.1f to $hi%.1f kHz (chi-square $z%.1f sd)",
          Map("chi2_sd" -> z, "amplitude_low_rel" -> a0, "amplitude_high_rel" -> a1, "phase_low_deg" -> p0, "phase_high_deg" -> p1,
            SizeLsb -> size / e.lsb), z > Z)
      }
      // noise against speed (jitter-like), relative to the noise the model gives each sample (white, or growing with
      // a slope once jitter or phase noise is in the spec: what it takes up is then no departure)
      val all = ss.sum / math.max(1, cnt.sum)
      val ratio = (0 until sb).map(b => ss(b) / math.max(1, cnt(b)) / all)
      val zz = (0 until sb).map(b => (ratio(b) - 1) / math.sqrt(2.0 / math.max(1, cnt(b))))
      val z = zOf(zz.map(x => x * x).sum, sb - 1)
      out += Located("noise against speed", f"residual variance x${ratio.head}%.3f at low speed, x${ratio.last}%.3f at high speed (chi-square $z%.1f sd)",
        Map("chi2_sd" -> z, "variance_low_rel" -> ratio.head, "variance_high_rel" -> ratio.last,
          // the noise's rms moved from its mean in the bin where it moves most
          SizeLsb -> ratio.map(x => math.abs(math.sqrt(x) - 1)).max * math.sqrt(0.5 * (sdS * sdS + sdC * sdC)) / e.lsb), z > Z)
    }
  }

  /** The speed bins' sums of `againstSpeed` (per channel and direction of motion the residual's projections on the
    * fitted fundamental and its slope, and their squares, and the samples; per bin of |speed| the noise's), from one pass: a method of its own, a small one to compile.
    */
  private def speedSums(e: SignalEngine, ed: Array[Double], vS: Double, vC: Double, pu: Array[Array[Double]], pv: Array[Array[Double]],
                        uu: Array[Array[Double]], vv: Array[Array[Double]], ss: Array[Double], cnt: Array[Int], cntD: Array[Int],
                        back: Double): Unit = {
    val rs = e.resS; val rc = e.resC; val n = e.n
    val (puS, pvS, uuS, vvS) = (pu(0), pv(0), uu(0), vv(0)); val (puC, pvC, uuC, vvC) = (pu(1), pv(1), uu(1), vv(1))
    // the fitted fundamentals as `SignalEngine.us` etc. make them, from locals (the stores below may not be assumed
    // to leave the engine's arrays alone: read through the engine, its coefficients were loaded again every sample)
    val bs = e.base; val (b1, b2, b4, b5) = (bs(1), bs(2), bs(4), bs(5)); val (s1, s2, c1, c2, fr) = (e.s1, e.s2, e.c1, e.c2, e.freq)
    // the noise model's slope term: jitter against time (the slope times 2 pi f), phase noise against the fringe phase
    val j2 = if (e.spec.slopeNoise) e.noise.jitter2 else 0.0; val byTime = e.spec.jitter
    var i = 0
    while (i < n) {
      val f = math.abs(fr(i)); var b = 0; while (b < ed.length && f > ed(b)) b += 1
      val r = rs(i); val q = rc(i)
      val us = b1 * s1(i) + b2 * s2(i); val vs = b1 * s2(i) - b2 * s1(i); val uc = b4 * c1(i) + b5 * c2(i); val vc = b4 * c2(i) - b5 * c1(i)
      // (backwards where it moves at 1 % of the top speed at least: a standstill's fitted speed wobbles about zero with
      // the noise it followed, and split by its sign its samples read as a change against speed of 150 sd)
      val d = if (fr(i) < back) b + ed.length + 1 else b
      puS(d) += r * us; uuS(d) += us * us; pvS(d) += r * vs; vvS(d) += vs * vs
      puC(d) += q * uc; uuC(d) += uc * uc; pvC(d) += q * vc; vvC(d) += vc * vc; cntD(d) += 1
      if (j2 == 0) ss(b) += r * r / vS + q * q / vC
      else {
        val k = if (byTime) 2 * math.Pi * fr(i) else 1.0; val ds = vs * k; val dc = vc * k
        ss(b) += r * r / (vS + j2 * ds * ds) + q * q / (vC + j2 * dc * dc)
      }
      cnt(b) += 2
      i += 1
    }
  }

  /** The strongest line of each channel's residual spectrum. */
  private def spectrum(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val rs = e.resS; val rc = e.resC; val lsb = e.lsb; val n = e.n
    // spectrum
    val m = Integer.highestOneBit(math.min(n, 1 << 18))
    if (m >= 256 && want("spectrum")) {
      for ((r, ch) <- Seq((rs, "sin"), (rc, "cos"))) {
        val p = Fft.power(r, m).drop(1)
        val mean = p.sum / p.size
        val k = p.indices.maxBy(p(_))
        val x = p(k) / mean; val thr = math.log(p.size.toDouble) + 14
        val hz = (k + 1) * e.fs / m; val ampl = 2 * math.sqrt(p(k)) / m
        // a peak in the lowest bins is a wander of a few cycles over the span, not a line (a random walk of the offsets
        // read "strongest line 3.8 Hz" in a 0.4 s record)
        val what = if (k + 1 < SlowCycles) f"strongest power at $hz%.1f Hz, ${k + 1} cycle${if (k == 0) "" else "s"} in the ${m / e.fs}%.3g s analysed: a slow wander, not a line"
          else f"strongest line $hz%.1f Hz"
        out += Located(s"spectrum, $ch channel", f"$what, ${ampl / lsb}%.2f LSB, ${x}%.1f x the mean power (threshold $thr%.1f)",
          // (no size, only its least: a line that sweeps spreads over many bins, each below the floor; a 2 LSB chirp
          // read 0.07 LSB)
          Map("frequency_hz" -> hz, "amplitude_lsb" -> ampl / lsb, "peak_to_mean" -> x, AtLeastLsb -> ampl / lsb), x > thr)
      }
    }
  }

  /** Each channel's residual rms. */
  private def perChannel(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val lsb = e.lsb
    val sdS = math.sqrt(e.noise.varS); val sdC = math.sqrt(e.noise.varC)
    // per channel
    if (want("per channel")) out += Located("per channel", f"residual rms sin ${sdS / lsb}%.2f LSB, cos ${sdC / lsb}%.2f LSB", Map("rms_sin_lsb" -> sdS / lsb, "rms_cos_lsb" -> sdC / lsb), false)
  }

  /** The samples per pin pattern and per code (from the lowest code up), in one pass of a method of its own: within
    * the histogram's closure the JIT compiled the passes with all that reads them, three times over (0.6 s of a
    * compiler thread in a new JVM's 1 M run).
    */
  private def counts(codes: Array[Int], n: Int, adc: moire.signal.Adc): (Array[Int], Array[Int]) = {
    val pins = new Array[Int](1 << adc.bits); val hist = new Array[Int](1 << adc.bits); var i = 0
    while (i < n) { val c = codes(i); pins(c) += 1; hist(adc.fromPins(c) + adc.half) += 1; i += 1 }
    (pins, hist)
  }

  /** Each pin's share of samples at 1, from the samples per pin pattern: the patterns that occur only (a 24-bit ADC
    * has 2^24 patterns and a short record a few thousand of them).
    */
  private def bitShares(pins: Array[Int], bits: Int, n: Int): IndexedSeq[Double] = {
    val ones = new Array[Long](bits); var c = 0
    while (c < pins.length) {
      if (pins(c) > 0) { var b = 0; while (b < bits) { if (((c >> b) & 1) == 1) ones(b) += pins(c); b += 1 } }
      c += 1
    }
    ones.map(_.toDouble / n).toIndexedSeq
  }

  /** Constant bits and pile-ups at the extremes of each channel's codes. */
  private def codeHistogram(e: SignalEngine, want: String => Boolean, out: scala.collection.mutable.Builder[Located, Seq[Located]]): Unit = {
    val n = e.n
    // code histogram: constant bits and pile-ups at the extremes
    for ((codes, ch) <- Seq((e.rec.sin, "sin"), (e.rec.cos, "cos")) if want("code histogram")) {
      val bits = e.rec.adc.bits
      val adc = e.rec.adc
      val (pins, hist) = counts(codes, n, adc)
      val frac = bitShares(pins, bits, n)
      val stuck = (e.coarseBits until bits - 2).filter(b => frac(b) == 0.0 || frac(b) == 1.0)
      val hi = hist.lastIndexWhere(_ > 0); val lo = hist.indexWhere(_ > 0)
      def pile(c: Int, nb: Int) = hist(c).toDouble / math.max(1, if (nb >= 0 && nb < hist.length) hist(nb) else 0)
      val q = 1 << e.coarseBits // the neighbouring code a coarse converter can reach
      val pileHi = pile(hi, hi - q); val pileLo = pile(lo, lo + q)
      val chi = if (ch == "sin") 0 else 1
      val faulty = e.spec.faults.filter(_.ch == chi).map(_.bit).toSet; val clipped = e.spec.clips.exists(_.ch == chi)
      val sig = stuck.exists(b => !faulty.contains(b)) || (!clipped && ((pileHi > 8 && hist(hi) > 50 && hi < hist.length - q) || (pileLo > 8 && hist(lo) > 50 && lo > 0)))
      out += Located(s"code histogram, $ch channel",
        (if (stuck.nonEmpty) s"bits ${stuck.mkString(",")} never change; " else "") +
          f"signed codes ${lo - adc.half}..${hi - adc.half}, ${hist(hi)} samples at the top code (${pileHi}%.1f x its neighbour), ${hist(lo)} at the bottom (${pileLo}%.1f x)",
        Map("code_min" -> (lo - adc.half), "code_max" -> (hi - adc.half), "pile_high" -> pileHi, "pile_low" -> pileLo, "constant_bits" -> stuck.size), sig)
    }
  }
}
