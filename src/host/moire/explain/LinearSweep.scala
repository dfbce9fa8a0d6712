package moire.explain

/** The linear candidates whose columns are a function of the sample (the harmonics of the fringe, the ADCs'
  * nonlinearity, crosstalk, drift, a contrast change along the travel) fitted from one pass over the samples: at each
  * sample every family's columns are made and their products with the default part's columns, with each other and
  * with the residual summed per channel, in blocks on all cores. No column of the record's length is made. Each
  * family's sums are the ones `LinearFamily` takes from its columns (`LinearSweepSpec`: the same fits).
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
    case _ => (Array(true, false, true, false), Array(false, true, false, true)) // drift, contrast
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

    val rows = if (idx == null) n else idx.length
    val sums = Par.sums(rows, mS + mC + 2, Gram.Block) { (lo, hi, acc) =>
      val v = new Array[Double](2 * colAt(nf)) // the families' column values at a sample: (sin part, cos part) per column
      val bs = new Array[Double](3); val bc = new Array[Double](3)
      var row = lo
      while (row < hi) {
        val i = if (idx == null) row else idx(row)
        // the families' columns at sample i, as their termCols make them
        val usi = us(i); val vsi = vs(i); val uci = uc(i); val vci = vc(i)
        if (maxOrder > 0) {
          def harm(u: Double, w: Double, part: Int): Unit = {
            val a = math.sqrt(u * u + w * w)
            if (a > 0) {
              val s = u / a; val c = w / a; var re = 1.0; var im = 0.0; var j = 0
              while (j < maxOrder) {
                val r2 = re * c - im * s; im = re * s + im * c; re = r2; j += 1
                val f = orderAt(j)
                if (f >= 0) { val at = 2 * colAt(f) + 4 * part; v(at + part) = a * im; v(at + 2 + part) = a * re }
              }
            } else { var f = 0; while (f < orders.size) { val at = 2 * colAt(f) + 4 * part; v(at + part) = 0; v(at + 2 + part) = 0; f += 1 } }
          }
          harm(usi, vsi, 0); harm(uci, vci, 1)
        }
        var f = orders.size
        while (f < nf) {
          val at = 2 * colAt(f)
          fams(f) match {
            case _: Term.Inl =>
              val p = repS(i) - resS(i); val q = repC(i) - resC(i)
              v(at) = (2 * p * p - 1) * lsb; v(at + 1) = (2 * q * q - 1) * lsb
              v(at + 2) = (4 * p * p * p - 3 * p) * lsb; v(at + 3) = (4 * q * q * q - 3 * q) * lsb
            case Term.Crosstalk =>
              val w = twoPi * freq(i); v(at) = vci * w; v(at + 3) = vsi * w
            case t =>
              val x = if (t == Term.Drift) (i - drift) / fs else phase(i) - meanPhase
              v(at) = x; v(at + 3) = x; v(at + 4) = usi * x; v(at + 7) = uci * x
          }
          f += 1
        }
        bs(0) = 1.0; bs(1) = s1(i); bs(2) = s2(i); bc(0) = 1.0; bc(1) = c1(i); bc(2) = c2(i)
        def channel(b: Array[Double], y: Double, on: Array[Array[Int]], at: Array[Int], off: Int, part: Int): Unit = {
          var q = off
          var a = 0
          while (a < 3) { var c = 0; while (c <= a) { acc(q) += b(a) * b(c); q += 1; c += 1 }; a += 1 }
          a = 0; while (a < 3) { acc(q) += b(a) * y; q += 1; a += 1 }
          var f = 0
          while (f < nf) {
            q = off + at(f); val cols = on(f); val base = 2 * colAt(f) + part; var j = 0
            while (j < cols.length) {
              val x = v(base + 2 * cols(j))
              acc(q) += x * b(0); acc(q + 1) += x * b(1); acc(q + 2) += x * b(2); q += 3
              var l = 0; while (l <= j) { acc(q) += x * v(base + 2 * cols(l)); q += 1; l += 1 }
              acc(q) += x * y; q += 1
              j += 1
            }
            f += 1
          }
        }
        channel(bs, resS(i), onS, atS, 0, 0); channel(bc, resC(i), onC, atC, mS, 1)
        acc(mS + mC) += resS(i) * resS(i); acc(mS + mC + 1) += resC(i) * resC(i)
        row += 1
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
