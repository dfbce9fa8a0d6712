package moire.explain

/** The linear candidates whose columns are a function of the sample (the harmonics of the fringe, the ADCs'
  * nonlinearity, crosstalk, drift, a contrast change along the travel; a warm-up or a pickup line once its time constant
  * or frequency is searched) fitted from one pass over the samples: for a chunk of samples at a time, every family's
  * columns are made (a family across the chunk at a time) and laid out by rows, and their products with the default
  * part's columns, with each other and with the residual summed per channel, in blocks on all cores. No column of the
  * record's length is made. Each family's sums are the ones `LinearFamily` takes from its columns (`LinearSweepSpec`:
  * the same fits).
  */
object LinearSweep {
  /** The families this pass makes: harmonics of `orders`, INL, crosstalk, drift, contrast (each the term whose columns
    * hold its variants).
    */
  def terms(orders: Seq[Int]): Seq[Term] = orders.map(k => Term.Harm(k, "both")) ++ Seq(Term.Inl("both"), Term.Crosstalk, Term.Drift, Term.Contrast)

  /** Which channel parts each of a family's columns has (as its `termCols`). */
  private def parts(t: Term): (Array[Boolean], Array[Boolean]) = t match {
    case _: Term.Harm => (Array(true, true, false, false), Array(false, false, true, true))
    case _: Term.Inl => (Array(true, true), Array(true, true))
    case Term.Crosstalk => (Array(true, false), Array(false, true))
    case _: Term.Interference => (Array(true, true, false, false), Array(false, false, true, true))
    case _ => (Array(true, false, true, false), Array(false, true, false, true)) // drift, contrast, warm-up
  }

  /** Samples laid out row by row before their products are summed (rows of a chunk stay in the core's cache). */
  private val Chunk = 256

  /** Four running sums of a(0 until m) b(0 until m) (one would wait on each addition), added at the end. */
  private def dot(a: Array[Double], b: Array[Double], m: Int): Double = {
    var s0 = 0.0; var s1 = 0.0; var s2 = 0.0; var s3 = 0.0; var t = 0
    val end4 = m & ~3
    while (t < end4) { s0 += a(t) * b(t); s1 += a(t + 1) * b(t + 1); s2 += a(t + 2) * b(t + 2); s3 += a(t + 3) * b(t + 3); t += 4 }
    while (t < m) { s0 += a(t) * b(t); t += 1 }
    (s0 + s1) + (s2 + s3)
  }

  def apply(e: SignalEngine, orders: Seq[Int], yyS: Double, yyC: Double): Map[Term, LinearFamily] = of(e, terms(orders), yyS, yyC)

  /** The families `families` (of `terms`) from one pass over all samples, or over the samples `idx` (a screening
    * subsample): then each channel's sums are scaled so that the default part's own fit there leaves the whole record's
    * residual sum of squares (yyS, yyC), and a family's variant lowers it by the same fraction as on the subsample.
    */
  def of(e: SignalEngine, families: Seq[Term], yyS: Double, yyC: Double, idx: Array[Int] = null): Map[Term, LinearFamily] = {
    import e._
    val orders = families.collect { case Term.Harm(k, _) => k }.sorted
    val fams = (orders.map(k => Term.Harm(k, "both")) ++ families.filterNot(_.isInstanceOf[Term.Harm])).toArray
    val nf = fams.length
    val maxOrder = if (orders.isEmpty) 0 else orders.max
    val orderAt = Array.fill(maxOrder + 1)(-1); orders.zipWithIndex.foreach { case (k, j) => orderAt(k) = j }
    // each order's pass through the low-passes (`HarmonicResponse`; null: none)
    val responses = Array.tabulate(maxOrder + 1)(k => if (orderAt(k) >= 0) harmonicResponse(k) else null)
    val ps = fams.map(parts)
    val width = ps.map(_._1.length) // columns per family
    val colAt = width.scanLeft(0)(_ + _) // where each family's values start (two per column: sin part, cos part)
    // accumulators per channel: base 3 x 3 (lower) + 3 against y; per family, per column with a part on the channel:
    // 3 against the base, against its earlier columns and itself, 1 against y
    def layout(has: Int => Array[Boolean]): (Array[Int], Int) = {
      val at = new Array[Int](nf + 1); var m = 9
      for (f <- 0 until nf) { at(f) = m; val c = has(f).count(identity); m += c * 4 + c * (c + 1) / 2 }
      at(nf) = m; (at, m)
    }
    val (atS, mS) = layout(f => ps(f)._1); val (atC, mC) = layout(f => ps(f)._2)
    val drift = 0.5 * (n - 1)
    val meanPhase = Par.sum(n) { (lo, hi) => var s = 0.0; var i = lo; while (i < hi) { s += phase(i); i += 1 }; s } / n
    val twoPi = 2 * math.Pi
    // per channel, the family's columns with a part there (indices into its columns)
    val onS = ps.map(p => p._1.indices.filter(p._1(_)).toArray); val onC = ps.map(p => p._2.indices.filter(p._2(_)).toArray)

    // per channel, the rows a chunk of samples is laid out in: 0..2 the default part's columns (1, sin, cos), 3 the
    // residual, then each family's columns with a part there; and the pairs of rows whose products are summed, in the
    // order of the accumulators (`layout`)
    def plan(on: Array[Array[Int]], part: Int): (Array[Int], Array[Int]) = {
      val from = Array.newBuilder[Int]; val pairs = Array.newBuilder[Int]
      def pair(a: Int, b: Int): Unit = { pairs += a; pairs += b }
      for (a <- 0 until 3; c <- 0 to a) pair(a, c)
      for (a <- 0 until 3) pair(a, 3)
      var row = 4
      for (f <- 0 until nf) {
        val first = row
        for (j <- on(f).indices) {
          from += 2 * colAt(f) + part + 2 * on(f)(j)
          pair(row, 0); pair(row, 1); pair(row, 2)
          for (l <- 0 to j) pair(row, first + l)
          pair(row, 3); row += 1
        }
      }
      (from.result(), pairs.result())
    }
    val (fromS, pairsS) = plan(onS, 0); val (fromC, pairsC) = plan(onC, 1)
    val rows = if (idx == null) n else idx.length
    val nOrders = orders.size // a list's size is a walk along it: not at every sample
    // where each family value goes (`v` in the families' layout: two per column, its sin part and its cos part): the
    // row of the chunk it is laid out in, per channel; -1 where that channel does not read it
    val rowS = Array.fill(2 * colAt(nf))(-1); val rowC = Array.fill(2 * colAt(nf))(-1)
    for (r <- fromS.indices) rowS(fromS(r)) = 4 + r
    for (r <- fromC.indices) rowC(fromC(r)) = 4 + r
    // each thread's chunk buffers, made once per pass (not per block of rows)
    final class Bufs {
      val s: Array[Array[Double]] = Array.ofDim[Double](4 + fromS.length, Chunk); val c: Array[Array[Double]] = Array.ofDim[Double](4 + fromC.length, Chunk)
      val at = new Array[Int](Chunk) // the chunk's sample indices
      val u: Array[Array[Double]] = Array.ofDim[Double](4, Chunk) // us, vs, uc, vc at them
      val sn = new Array[Double](Chunk); val cn = new Array[Double](Chunk); val amp = new Array[Double](Chunk)
      val re = new Array[Double](Chunk); val im = new Array[Double](Chunk); val on = new Array[Boolean](Chunk)
    }
    val bufs = ThreadLocal.withInitial[Bufs](() => new Bufs)
    val sums = Par.sums(rows, mS + mC + 2, Gram.Block) { (lo, hi, acc) =>
      val sc = new Array[Double](2)
      val B = bufs.get(); val bufS = B.s; val bufC = B.c // every row of a chunk is written before it is read
      val at = B.at; val (us, vs, uc, vc) = (B.u(0), B.u(1), B.u(2), B.u(3))
      // the chunk's row of value index x of the families' layout (on the channel that reads it), or null
      def dst(x: Int): Array[Double] = if (rowS(x) >= 0) bufS(rowS(x)) else if (rowC(x) >= 0) bufC(rowC(x)) else null
      // the harmonics' rows of a chunk of m samples (a method of its own, as `others`: small methods to compile)
      def harmonics(m: Int): Unit = {
        var k = 0
        if (maxOrder > 0) {
          val sn = B.sn; val cn = B.cn; val amp = B.amp; val re = B.re; val im = B.im; val on = B.on
          var part = 0
          while (part < 2) {
            val u = if (part == 0) us else uc; val w = if (part == 0) vs else vc
            k = 0
            while (k < m) {
              val a = math.sqrt(u(k) * u(k) + w(k) * w(k))
              on(k) = a > 0
              if (a > 0) { val ia = 1 / a; sn(k) = u(k) * ia; cn(k) = w(k) * ia; amp(k) = a; re(k) = 1.0; im(k) = 0.0 }
              k += 1
            }
            var j = 0
            while (j < maxOrder) {
              k = 0
              while (k < m) {
                if (on(k)) { val r2 = re(k) * cn(k) - im(k) * sn(k); im(k) = re(k) * sn(k) + im(k) * cn(k); re(k) = r2 }
                k += 1
              }
              j += 1
              val f = orderAt(j)
              if (f >= 0) {
                val x = 2 * colAt(f) + 4 * part
                val dIm = dst(x + part); val dRe = dst(x + 2 + part)
                val hr = responses(j)
                k = 0
                while (k < m) {
                  if (on(k)) { if (dIm != null) dIm(k) = amp(k) * im(k); if (dRe != null) dRe(k) = amp(k) * re(k) }
                  else { if (dIm != null) dIm(k) = 0; if (dRe != null) dRe(k) = 0 }
                  if (hr != null && dIm != null && dRe != null) hr(freq(at(k)), part, dIm, dRe, k)
                  k += 1
                }
              }
            }
            part += 1
          }
        }
      }
      // the other families' rows of a chunk of m samples
      def others(m: Int): Unit = {
        var k = 0
        var f = nOrders
        while (f < nf) {
          val x = 2 * colAt(f)
          val d0 = dst(x); val d1 = dst(x + 1); val d2 = dst(x + 2); val d3 = dst(x + 3)
          fams(f) match {
            case _: Term.Inl =>
              k = 0
              while (k < m) {
                val i = at(k); val p = repS(i) - resS(i); val q = repC(i) - resC(i)
                if (d0 != null) d0(k) = (2 * p * p - 1) * lsb
                if (d1 != null) d1(k) = (2 * q * q - 1) * lsb
                if (d2 != null) d2(k) = (4 * p * p * p - 3 * p) * lsb
                if (d3 != null) d3(k) = (4 * q * q * q - 3 * q) * lsb
                k += 1
              }
            case Term.Crosstalk =>
              k = 0
              while (k < m) {
                val w = twoPi * freq(at(k)); if (d0 != null) d0(k) = vc(k) * w; if (d3 != null) d3(k) = vs(k) * w
                k += 1
              }
            case Term.Interference(hz) =>
              val d5 = dst(x + 5); val d7 = dst(x + 7)
              k = 0
              while (k < m) {
                val t = hz * at(k) / fs; Turns.sinCos(t - Turns.floor(t), sc, 0)
                if (d0 != null) d0(k) = sc(0); if (d2 != null) d2(k) = sc(1); if (d5 != null) d5(k) = sc(0); if (d7 != null) d7(k) = sc(1)
                k += 1
              }
            case tm =>
              val d4 = dst(x + 4); val d7 = dst(x + 7)
              val tau = tm match { case Term.Warmup(t) => t; case _ => Double.NaN }
              val kind = tm match { case _: Term.Warmup => 0; case Term.Drift => 1; case _ => 2 }
              k = 0
              while (k < m) {
                val i = at(k)
                val z = if (kind == 0) math.exp(-i / fs / tau) else if (kind == 1) (i - drift) / fs else phase(i) - meanPhase
                if (d0 != null) d0(k) = z; if (d3 != null) d3(k) = z; if (d4 != null) d4(k) = us(k) * z; if (d7 != null) d7(k) = uc(k) * z
                k += 1
              }
          }
          f += 1
        }
      }
      var c0 = lo
      while (c0 < hi) {
        val m = math.min(Chunk, hi - c0)
        // the default part's rows and each sample's fitted fundamentals; then the families' rows, one family (one
        // harmonic order) across the chunk at a time: the same values, as `termCols` makes them, without a sample's
        // rotations waiting on each other
        var k = 0
        while (k < m) {
          val row = c0 + k
          val i = if (idx == null) row else idx(row)
          at(k) = i; us(k) = e.us(i); vs(k) = e.vs(i); uc(k) = e.uc(i); vc(k) = e.vc(i)
          bufS(0)(k) = 1.0; bufS(1)(k) = s1(i); bufS(2)(k) = s2(i); bufS(3)(k) = resS(i)
          bufC(0)(k) = 1.0; bufC(1)(k) = c1(i); bufC(2)(k) = c2(i); bufC(3)(k) = resC(i)
          k += 1
        }
        harmonics(m); others(m)
        // the chunk's products, row by row
        def channel(buf: Array[Array[Double]], pairs: Array[Int], off: Int): Unit = {
          var q = 0
          while (q < pairs.length) { acc(off + q / 2) += dot(buf(pairs(q)), buf(pairs(q + 1)), m); q += 2 }
        }
        channel(bufS, pairsS, 0); channel(bufC, pairsC, mS)
        acc(mS + mC) += dot(bufS(3), bufS(3), m); acc(mS + mC + 1) += dot(bufC(3), bufC(3), m)
        c0 += m
      }
    }
    // a subsample's sums scaled per channel: the default part's fit there to the record's residual sum of squares
    val (famS, famC) = if (idx == null) (yyS, yyC) else {
      def scale(off: Int, m: Int, yySub: Double, yyAll: Double): Double = {
        val q = sums.slice(off, off + 9)
        val c = yyAll / Candidates.rss(Array(q(0), q(1), q(3), q(2), q(4), q(5), q(6), q(7), q(8), yySub))
        for (j <- off until off + m) sums(j) *= c
        c * yySub
      }
      (scale(0, mS, sums(mS + mC), yyS), scale(mS, mC, sums(mS + mC + 1), yyC))
    }

    // each family's Gram in LinearFamily's layout: columns 0..5 the default part's, 6.. the family's; index j for a
    // column's sin part, k + j for its cos part
    (0 until nf).map { f =>
      val w = width(f); val k = 6 + w
      val g = Array.ofDim[Double](2 * k, 2 * k); val r = new Array[Double](2 * k)
      def put(a: Int, b: Int, x: Double): Unit = { g(a)(b) = x; g(b)(a) = x }
      def channel(off: Int, at: Array[Int], on: Array[Array[Int]], baseIdx: Array[Int], shift: Int): Unit = {
        var q = off
        for (a <- 0 until 3; c <- 0 to a) { put(baseIdx(a), baseIdx(c), sums(q)); q += 1 }
        for (a <- 0 until 3) { r(baseIdx(a)) = sums(q); q += 1 }
        q = off + at(f); val cols = on(f)
        for (j <- cols.indices) {
          val idx = shift + 6 + cols(j)
          for (b <- 0 until 3) { put(idx, baseIdx(b), sums(q)); q += 1 }
          for (l <- 0 to j) { put(idx, shift + 6 + cols(l), sums(q)); q += 1 }
          r(idx) = sums(q); q += 1
        }
      }
      channel(0, atS, onS, Array(0, 1, 2), 0); channel(mS, atC, onC, Array(k + 3, k + 4, k + 5), k)
      val (hs, hc) = ps(f)
      fams(f) -> new LinearFamily(k, g, r, IndexedSeq(true, true, true, false, false, false) ++ hs,
        IndexedSeq(false, false, false, true, true, true) ++ hc, famS, famC)
    }.toMap
  }
}
