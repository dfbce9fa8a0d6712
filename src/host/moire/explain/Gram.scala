package moire.explain

/** The normal equations' sums of a design (X'X and X'y over both channels) in one pass over the samples: blocks of
  * rows, each block's products of every column pair while the block is in cache, blocks on all cores. The blocks are
  * fixed by the sample count and their sums added in order, so the numbers do not depend on the cores.
  */
object Gram {
  /** Rows per block (a block of 30 columns on both channels stays in a core's cache). */
  val Block = 2048

  /** The rows a fit leaves out on each channel: those where `cS` (`cC`), a censored sample's distance from the
    * prediction up to its level (NaN where not censored), is below `belowS` (`belowC`): a prediction that far beyond
    * the level, where the sample tells the fit nothing. Null arrays: none left out.
    */
  final case class Skip(cS: Array[Double], belowS: Double, cC: Array[Double], belowC: Double,
                        heldS: Array[Boolean] = null, heldC: Array[Boolean] = null) {
    @inline def s(i: Int): Boolean = (cS != null && cS(i) < belowS) || (heldS != null && heldS(i))
    @inline def c(i: Int): Boolean = (cC != null && cC(i) < belowC) || (heldC != null && heldC(i))
  }

  /** The runs of rows in [from, to) a channel keeps (those `out` does not leave out), as from0, to0, from1, to1, ... */
  private[explain] def kept(out: Int => Boolean, from: Int, to: Int): Array[Int] = {
    val b = Array.newBuilder[Int]; var i = from
    while (i < to) {
      while (i < to && out(i)) i += 1
      if (i < to) { val a = i; while (i < to && !out(i)) i += 1; b += a; b += i }
    }
    b.result()
  }

  /** g(i)(j) = sum x_i x_j and r(i) = sum x_i y over the rows (all, or the rows `idx` when it is not null), each
    * channel's rows that `skip` leaves out left out (null: none).
    */
  def of(cols: IndexedSeq[Col], ys: Array[Double], yc: Array[Double], idx: Array[Int] = null, skip: Skip = null): (Array[Array[Double]], Array[Double]) = {
    if (skip != null) {
      require(idx == null, "a fold's rows and rows left out")
      val as = cols.map(_.s).toArray; val ac = cols.map(_.c).toArray; val z = new Array[Int](cols.length); val k = cols.length
      val rows = if (ys != null) ys.length else yc.length
      if (FitPath.isReference) { val out = new Array[Double](k * (k + 1) / 2 + k); blockAt(as, z, ac, z, ys, yc, 0, rows, out, skip); return unpack(out, k) }
      return unpack(Par.sums(rows, k * (k + 1) / 2 + k, Block)((lo, hi, out) => blockAt(as, z, ac, z, ys, yc, lo, hi, out, skip)), k)
    }
    if (FitPath.isReference) return plain(cols, ys, yc, idx)
    val k = cols.length
    def stored(a: Array[Double]) = a != null && !(a eq Col.Ones)
    val rows = if (idx != null) idx.length else if (ys != null) ys.length
      else cols.find(c => stored(c.s)).map(_.s.length).orElse(cols.find(c => stored(c.c)).map(_.c.length)).getOrElse(0)
    val as = cols.map(_.s).toArray; val ac = cols.map(_.c).toArray
    val sum = Par.sums(rows, k * (k + 1) / 2 + k, Block)((lo, hi, out) => block(as, ac, ys, yc, idx, lo, hi, out))
    unpack(sum, k)
  }

  /** X'X and X'y from the sums in `block`'s order. */
  private[explain] def unpack(sum: Array[Double], k: Int): (Array[Array[Double]], Array[Double]) = {
    val g = Array.ofDim[Double](k, k); val r = new Array[Double](k)
    var q = 0
    for (i <- 0 until k) { for (j <- 0 to i) { g(i)(j) = sum(q); g(j)(i) = sum(q); q += 1 }; r(i) = sum(q); q += 1 }
    (g, r)
  }

  /** One block's sums, in the order (0,0), y0, (1,0), (1,1), y1, ... : pair (i, j <= i), then column i against y. A fold's
    * rows (`idx`) are gathered first, in a method of its own: with the gather a branch of this one, each fold's call
    * after plain ones made the JIT drop its code and compile it again (four times in a new JVM's 1 M run).
    */
  private[explain] def block(as: Array[Array[Double]], ac: Array[Array[Double]], ys: Array[Double], yc: Array[Double], idx: Array[Int],
                    lo: Int, hi: Int, out: Array[Double]): Unit =
    if (idx == null) products(as, ac, ys, yc, lo, hi, out) else gathered(as, ac, ys, yc, idx, lo, hi, out)

  /** `block` for the rows idx(lo until hi): the products over contiguous copies of them. */
  private def gathered(as: Array[Array[Double]], ac: Array[Array[Double]], ys: Array[Double], yc: Array[Double], idx: Array[Int],
                       lo: Int, hi: Int, out: Array[Double]): Unit = {
    def rows(a: Array[Double]): Array[Double] =
      if (a == null || (a eq Col.Ones)) a
      else { val o = new Array[Double](hi - lo); var t = lo; while (t < hi) { o(t - lo) = a(idx(t)); t += 1 }; o }
    val k = as.length; val s = new Array[Array[Double]](k); val c = new Array[Array[Double]](k); var i = 0
    while (i < k) { s(i) = rows(as(i)); c(i) = rows(ac(i)); i += 1 }
    products(s, c, rows(ys), rows(yc), 0, hi - lo, out)
  }

  /** The sums of `block` over the rows [from, to) of the columns and data as they are. */
  private def products(s: Array[Array[Double]], c: Array[Array[Double]], y1: Array[Double], y2: Array[Double], from: Int, to: Int,
                       out: Array[Double]): Unit = {
    val k = s.length
    var q = 0; var i = 0
    while (i < k) {
      var j = 0
      while (j <= i) { out(q) = dot(s(i), s(j), from, to) + dot(c(i), c(j), from, to); q += 1; j += 1 }
      out(q) = dot(s(i), y1, from, to) + dot(c(i), y2, from, to); q += 1
      i += 1
    }
  }

  /** `block`'s sums over the rows [lo, hi) of columns read where they are: column k's row i at as(k)(i - sa(k)) (and
    * ac, sc for the cos channel), the data at ys(i), yc(i). The same numbers as `block` on copies of the rows.
    */
  private[explain] def blockAt(as: Array[Array[Double]], sa: Array[Int], ac: Array[Array[Double]], sc: Array[Int], ys: Array[Double],
                               yc: Array[Double], lo: Int, hi: Int, out: Array[Double], skip: Skip = null): Unit = {
    val k = as.length
    if (skip != null) {
      // each channel's sums over the runs of rows it keeps
      val rs = kept(skip.s, lo, hi); val rc = kept(skip.c, lo, hi)
      def over(r: Array[Int], a: Array[Double], da: Int, b: Array[Double], db: Int): Double = {
        var s = 0.0; var t = 0; while (t < r.length) { s += dotAt(a, da, b, db, r(t), r(t + 1)); t += 2 }; s
      }
      var q = 0; var i = 0
      while (i < k) {
        var j = 0
        while (j <= i) { out(q) = over(rs, as(i), sa(i), as(j), sa(j)) + over(rc, ac(i), sc(i), ac(j), sc(j)); q += 1; j += 1 }
        out(q) = over(rs, as(i), sa(i), ys, 0) + over(rc, ac(i), sc(i), yc, 0); q += 1
        i += 1
      }
      return
    }
    var q = 0; var i = 0
    while (i < k) {
      var j = 0
      while (j <= i) { out(q) = dotAt(as(i), sa(i), as(j), sa(j), lo, hi) + dotAt(ac(i), sc(i), ac(j), sc(j), lo, hi); q += 1; j += 1 }
      out(q) = dotAt(as(i), sa(i), ys, 0, lo, hi) + dotAt(ac(i), sc(i), yc, 0, lo, hi); q += 1
      i += 1
    }
  }

  /** `dot` of a and b over the rows [from, to), row t at a(t - sa) and b(t - sb). */
  private def dotAt(a: Array[Double], sa: Int, b: Array[Double], sb: Int, from: Int, to: Int): Double = {
    if (a == null || b == null) return 0.0
    if (a eq Col.Ones) return if (b eq Col.Ones) (to - from).toDouble else sum(b, from - sb, to - sb)
    if (b eq Col.Ones) return sum(a, from - sa, to - sa)
    var s0 = 0.0; var s1 = 0.0; var s2 = 0.0; var s3 = 0.0
    // the rows as indices of a; b's are a's shifted by d
    var t = from - sa; val end = to - sa; val end4 = t + ((to - from) & ~3); val d = sa - sb
    while (t < end4) { s0 += a(t) * b(t + d); s1 += a(t + 1) * b(t + 1 + d); s2 += a(t + 2) * b(t + 2 + d); s3 += a(t + 3) * b(t + 3 + d); t += 4 }
    while (t < end) { s0 += a(t) * b(t + d); t += 1 }
    (s0 + s1) + (s2 + s3)
  }

  /** The reference path: each pair's products over all rows in turn, on one thread. */
  private def plain(cols: IndexedSeq[Col], ys: Array[Double], yc: Array[Double], idx: Array[Int]): (Array[Array[Double]], Array[Double]) = {
    val n = if (idx != null) idx.length else if (ys != null) ys.length else 0
    def one(a: Array[Double]) = a eq Col.Ones
    def dot(a: Array[Double], b: Array[Double]): Double =
      if (a == null || b == null) 0.0
      else if (one(a) && one(b)) n.toDouble
      else if (one(a)) dot(b, onesLike(b))
      else if (one(b)) dot(a, onesLike(a))
      else if (idx == null) { var s = 0.0; var i = 0; while (i < a.length) { s += a(i) * b(i); i += 1 }; s }
      else { var s = 0.0; var i = 0; while (i < idx.length) { val j = idx(i); s += a(j) * b(j); i += 1 }; s }
    val k = cols.length
    val g = Array.ofDim[Double](k, k); val r = new Array[Double](k)
    for (i <- 0 until k) {
      r(i) = dot(cols(i).s, ys) + dot(cols(i).c, yc)
      for (j <- 0 to i) { val v = dot(cols(i).s, cols(j).s) + dot(cols(i).c, cols(j).c); g(i)(j) = v; g(j)(i) = v }
    }
    (g, r)
  }

  /** An array of ones as long as a (the reference path's stand-in for `Col.Ones`). */
  private def onesLike(a: Array[Double]): Array[Double] = Array.fill(a.length)(1.0)

  /** The sum of a over [from, to) as `dot` adds it (`Col.Ones` times a: the same numbers, a times 1 is a). */
  private def sum(a: Array[Double], from: Int, to: Int): Double = {
    var s0 = 0.0; var s1 = 0.0; var s2 = 0.0; var s3 = 0.0; var t = from
    val end4 = from + ((to - from) & ~3)
    while (t < end4) { s0 += a(t); s1 += a(t + 1); s2 += a(t + 2); s3 += a(t + 3); t += 4 }
    while (t < to) { s0 += a(t); t += 1 }
    (s0 + s1) + (s2 + s3)
  }

  /** Four running sums (one would wait on each addition), added at the end. */
  private def dot(a: Array[Double], b: Array[Double], from: Int, to: Int): Double = {
    if (a == null || b == null) return 0.0
    if (a eq Col.Ones) return if (b eq Col.Ones) (to - from).toDouble else sum(b, from, to)
    if (b eq Col.Ones) return sum(a, from, to)
    var s0 = 0.0; var s1 = 0.0; var s2 = 0.0; var s3 = 0.0; var t = from
    val end4 = from + ((to - from) & ~3)
    while (t < end4) { s0 += a(t) * b(t); s1 += a(t + 1) * b(t + 1); s2 += a(t + 2) * b(t + 2); s3 += a(t + 3) * b(t + 3); t += 4 }
    while (t < to) { s0 += a(t) * b(t); t += 1 }
    (s0 + s1) + (s2 + s3)
  }
}
