package moire.explain

/** The sums the one-parameter profile (skew, cut-offs) needs, binned by fringe frequency: made in one pass over the
  * points, after which any spec's profile costs a pass over the bins, not over the samples.
  *
  * The channel response turns and scales the phase's (sin, cos) by coefficients that depend only on the fringe
  * frequency f: each channel's columns are x1 = A(f) sn + B(f) cs, x2 = A(f) cs - B(f) sn. Every sum the profile
  * takes (x1, x2, their squares and products, their products with the data) is a sum of w(f) p over the points, with w
  * one of A, B, A^2, AB, B^2 and p a product of sn, cs and the data. Within a bin of width D around its centre c,
  * w(c + u D) is the quadratic through u = -1/2, 0, 1/2, so a bin keeps the sums of p, u p and u^2 p of each product.
  * The error is the cubic term, at most (D / fc)^3 / 48 of a coefficient at a cut-off fc, smooth in the spec; over a
  * bin's points it mostly cancels (`ProfileSumsSpec`: within 2e-6 of -2 ln L on 60,000 samples with 2,048 bins, for
  * cut-offs down to a fifth of the highest fringe frequency). A candidate's own -2 ln L is taken on every sample.
  */
private[explain] final class ProfileSums(e: SignalEngine, idx: Array[Int]) {
  /** The engine state the sums were made from. */
  val version: Long = e.version
  /** Points summed (the samples, or the fold's). */
  val count: Int = if (idx == null) e.n else idx.length
  /** Bins: about 16 points each, at most 2,048. */
  val bins: Int = math.max(1, math.min(ProfileSums.MaxBins, count / 16))
  private val (lo, width) = {
    val (mn, mx) = if (idx == null) e.freqRange else Doubles.range(count)(q => e.freq(idx(q)))
    (mn, if (mx > mn) (mx - mn) / bins else 0.0)
  }
  @inline private def at(q: Int): Int = if (idx == null) q else idx(q)

  /** The nodes of the bins that hold points. */
  private val used = new Array[Boolean](2 * bins + 1)
  // per bin, 9 products x 3 moments: sn, cs, sn^2, sn cs, cs^2, ys sn, ys cs, yc sn, yc cs; and the totals of ys, ys^2, yc, yc^2
  private val (sums: Array[Double], totals: Array[Double]) = {
    val chunks = math.min(ProfileSums.Chunks, math.max(1, count / Par.Block))
    val per = (count + chunks - 1) / chunks
    val parts = new Array[Array[Double]](chunks); val tots = Array.ofDim[Double](chunks, 4)
    Par.each(chunks, count.toLong) { c =>
      val s = new Array[Double](bins * ProfileSums.Stride); val t = tots(c)
      val inv = if (width > 0) 1 / width else 0.0
      val sc = new Array[Double](2)
      val b0 = e.base(0); val b1 = e.base(1); val b2 = e.base(2); val b3 = e.base(3); val b4 = e.base(4); val b5 = e.base(5)
      val rs = e.resS; val rc = e.resC; val s1 = e.s1; val s2 = e.s2; val c1 = e.c1; val c2 = e.c2
      @inline def binOf(f: Double): Int = if (width > 0) math.min(bins - 1, ((f - lo) * inv).toInt) else 0
      var t0 = 0.0; var t1 = 0.0; var t2 = 0.0; var t3 = 0.0
      var q = c * per; val end = math.min(count, (c + 1) * per)
      // a run of points in one bin at a time (the fringe frequency moves slowly): its sums in local variables, then
      // added to the bin's place (in an array, each sample's 27 additions waited on the array's last store)
      while (q < end) {
        val cur = binOf(e.freq(at(q))); val curD = cur.toDouble // the bin as a double once a run (see `Turns.floor`)
        var a00 = 0.0; var a01 = 0.0; var a02 = 0.0; var a10 = 0.0; var a11 = 0.0; var a12 = 0.0; var a20 = 0.0; var a21 = 0.0; var a22 = 0.0
        var a30 = 0.0; var a31 = 0.0; var a32 = 0.0; var a40 = 0.0; var a41 = 0.0; var a42 = 0.0; var a50 = 0.0; var a51 = 0.0; var a52 = 0.0
        var a60 = 0.0; var a61 = 0.0; var a62 = 0.0; var a70 = 0.0; var a71 = 0.0; var a72 = 0.0; var a80 = 0.0; var a81 = 0.0; var a82 = 0.0
        var going = true
        while (going) {
          val i = at(q); val f = e.freq(i)
          if (binOf(f) != cur) going = false
          else {
            val u = if (width > 0) (f - lo) * inv - curD - 0.5 else 0.0
            Turns.sinCos(e.turn(i), sc, 0); val sn = sc(0); val cs = sc(1)
            // the data less the terms: the residual plus the default part
            val ys = rs(i) + b0 + b1 * s1(i) + b2 * s2(i); val yc = rc(i) + b3 + b4 * c1(i) + b5 * c2(i)
            t0 += ys; t1 += ys * ys; t2 += yc; t3 += yc * yc
            val u2 = u * u;
            { val p = sn; a00 += p; a01 += u * p; a02 += u2 * p }
            { val p = cs; a10 += p; a11 += u * p; a12 += u2 * p }
            { val p = sn * sn; a20 += p; a21 += u * p; a22 += u2 * p }
            { val p = sn * cs; a30 += p; a31 += u * p; a32 += u2 * p }
            { val p = cs * cs; a40 += p; a41 += u * p; a42 += u2 * p }
            { val p = ys * sn; a50 += p; a51 += u * p; a52 += u2 * p }
            { val p = ys * cs; a60 += p; a61 += u * p; a62 += u2 * p }
            { val p = yc * sn; a70 += p; a71 += u * p; a72 += u2 * p }
            { val p = yc * cs; a80 += p; a81 += u * p; a82 += u2 * p }
            q += 1; going = q < end
          }
        }
        val o = cur * ProfileSums.Stride
        s(o + 0) += a00; s(o + 1) += a01; s(o + 2) += a02
        s(o + 3) += a10; s(o + 4) += a11; s(o + 5) += a12
        s(o + 6) += a20; s(o + 7) += a21; s(o + 8) += a22
        s(o + 9) += a30; s(o + 10) += a31; s(o + 11) += a32
        s(o + 12) += a40; s(o + 13) += a41; s(o + 14) += a42
        s(o + 15) += a50; s(o + 16) += a51; s(o + 17) += a52
        s(o + 18) += a60; s(o + 19) += a61; s(o + 20) += a62
        s(o + 21) += a70; s(o + 22) += a71; s(o + 23) += a72
        s(o + 24) += a80; s(o + 25) += a81; s(o + 26) += a82
      }
      t(0) = t0; t(1) = t1; t(2) = t2; t(3) = t3
      parts(c) = s
    }
    val s = new Array[Double](bins * ProfileSums.Stride); val t = new Array[Double](4)
    for (c <- 0 until chunks) {
      val p = parts(c); var k = 0
      while (k < s.length) { s(k) += p(k); k += 1 }
      for (j <- 0 until 4) t(j) += tots(c)(j)
    }
    // the bin's quadratic in u through its three nodes (u = -1/2, 0, 1/2): sum w(f) p = w(-) Q- + w(0) Q0 + w(+) Q+ with
    // Q- = 2 P2 - P1, Q0 = P0 - 4 P2, Q+ = P1 + 2 P2; a bin's right node is the next one's left
    val q = new Array[Double]((2 * bins + 1) * 9)
    for (b <- 0 until bins if s(b * ProfileSums.Stride + 6) + s(b * ProfileSums.Stride + 12) > 0) {
      used(2 * b) = true; used(2 * b + 1) = true; used(2 * b + 2) = true
    }
    for (b <- 0 until bins; j <- 0 until 9) {
      val k = b * ProfileSums.Stride + 3 * j; val p0 = s(k); val p1 = s(k + 1); val p2 = s(k + 2)
      q(2 * b * 9 + j) += 2 * p2 - p1; q((2 * b + 1) * 9 + j) += p0 - 4 * p2; q((2 * b + 2) * 9 + j) += p1 + 2 * p2
    }
    (q, t)
  }

  /** -2 ln L of the default part refitted with the fundamentals of `sp` (white noise per channel), scaled to the
    * engine's n: `Candidates.profile(sp, 1, idx)` up to the cubic term of the bins.
    */
  def m2ll(sp: ModelSpec): Double = {
    val resp = new ChannelResponse(sp)
    val half = 0.5 * width; val nodes = 2 * bins + 1
    // the response at the nodes in use: A and B of each channel (x1 = A sn + B cs, x2 = A cs - B sn)
    val at = new Array[Double](4 * nodes)
    Par.blocks(nodes, ProfileSums.NodeBlock) { (v0, v1) =>
      val o = new Array[Double](4); var v = v0
      while (v < v1) {
        if (used(v)) { resp(lo + v * half, 1.0, 0.0, o); at(4 * v) = o(0); at(4 * v + 1) = -o(1); at(4 * v + 2) = o(2); at(4 * v + 3) = -o(3) }
        v += 1
      }
    }
    // the quadratic through a bin's nodes must hold the response at its quarter point to 1e-8: else NaN (the caller
    // takes the profile on every sample; a range of fringe frequencies far wider than the cut-off)
    val missed = Par.sums(bins, 1, ProfileSums.NodeBlock) { (b0, b1, m) =>
      val o = new Array[Double](4); var b = b0
      while (b < b1) {
        if (used(2 * b + 1)) {
          resp(lo + (b + 0.75) * width, 1.0, 0.0, o)
          var j = 0
          while (j < 4) {
            val x = if (j % 2 == 0) o(j) else -o(j)
            val q = -0.125 * at(8 * b + j) + 0.75 * at(8 * b + 4 + j) + 0.375 * at(8 * b + 8 + j) // the quadratic at u = 1/4
            if (!(math.abs(q - x) <= 1e-8 * math.max(1.0, math.abs(x)))) m(0) += 1
            j += 1
          }
        }
        b += 1
      }
    }
    if (missed(0) > 0) return Double.NaN
    // per channel: x1, x2, x1 x1, x1 x2, x2 x2, y x1, y x2
    val m = Par.sums(nodes, 14, ProfileSums.NodeBlock) { (v0, v1, m) =>
      var v = v0
      while (v < v1) {
        val k = 9 * v
        if (used(v)) {
          val sn = sums(k); val cs = sums(k + 1); val ss = sums(k + 2); val sc = sums(k + 3); val cc = sums(k + 4)
          var ch = 0
          while (ch < 2) {
            val a = at(4 * v + 2 * ch); val b = at(4 * v + 2 * ch + 1); val aa = a * a; val ab = a * b; val bb = b * b
            val ysn = sums(k + 5 + 2 * ch); val ycs = sums(k + 6 + 2 * ch)
            val q = 7 * ch
            m(q) += a * sn + b * cs
            m(q + 1) += a * cs - b * sn
            m(q + 2) += aa * ss + 2 * ab * sc + bb * cc
            m(q + 3) += aa * sc + ab * (cc - ss) - bb * sc
            m(q + 4) += aa * cc - 2 * ab * sc + bb * ss
            m(q + 5) += a * ysn + b * ycs
            m(q + 6) += a * ycs - b * ysn
            ch += 1
          }
        }
        v += 1
      }
    }
    val n = count.toDouble
    def of(ch: Int): Array[Double] = {
      val q = 7 * ch
      Array(n, m(q), m(q + 1), m(q + 2), m(q + 3), m(q + 4), totals(2 * ch), m(q + 5), m(q + 6), totals(2 * ch + 1))
    }
    e.whiteM2ll(Candidates.rss(of(0)) / n, Candidates.rss(of(1)) / n)
  }
}

private[explain] object ProfileSums {
  /** Values per bin: 9 products, 3 moments each. */
  val Stride = 27
  val MaxBins = 2048
  /** Parts the points are summed in (each into bins of its own), added in order: the numbers do not depend on the cores. */
  val Chunks = 8
  /** Nodes per block of the profile's pass. */
  val NodeBlock = 1024
}
