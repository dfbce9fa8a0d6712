package moire.explain

import org.hipparchus.linear.{Array2DRowRealMatrix, LUDecomposition}

/** A column of a least-squares design over both channels; null where it is zero on a channel. */
final case class Col(s: Array[Double], c: Array[Double])

/** Linear least squares on the stacked (sin, cos) samples via normal equations with column scaling.
  * `inv` is (X'X)^-1 (unscaled covariance); `ok` is false when the columns are (nearly) dependent.
  */
final case class LinSol(beta: Array[Double], inv: Array[Array[Double]], ok: Boolean)

object LinearFit {
  /** The fit on all samples, or on the samples `idx` (a fold, without copying the columns). */
  def solve(cols: IndexedSeq[Col], ys: Array[Double], yc: Array[Double], idx: Array[Int] = null): LinSol = {
    val (g, r) = Gram.of(cols, ys, yc, idx)
    normal(g, r)
  }

  /** Solves the normal equations g beta = r with column scaling. */
  private[explain] def normal(g: Array[Array[Double]], r: Array[Double]): LinSol = {
    val k = r.length
    val sc = Array.tabulate(k)(i => if (g(i)(i) > 0) 1 / math.sqrt(g(i)(i)) else 0.0)
    val m = new Array2DRowRealMatrix(Array.tabulate(k, k)((i, j) => g(i)(j) * sc(i) * sc(j) + (if (i == j && sc(i) == 0) 1.0 else 0.0)))
    val lu = new LUDecomposition(m, 1e-14)
    if (!lu.getSolver.isNonSingular) return LinSol(new Array[Double](k), Array.ofDim[Double](k, k), ok = false)
    val inv = lu.getSolver.getInverse
    val ok = (0 until k).forall(i => sc(i) > 0 && inv.getEntry(i, i) < 1e8)
    val beta = Array.tabulate(k)(i => sc(i) * (0 until k).map(j => inv.getEntry(i, j) * sc(j) * r(j)).sum)
    LinSol(beta, Array.tabulate(k, k)((i, j) => inv.getEntry(i, j) * sc(i) * sc(j)), ok)
  }

  /** Residual sum of squares of both channels on the samples `idx`. */
  def rss(cols: IndexedSeq[Col], beta: Array[Double], ys: Array[Double], yc: Array[Double], idx: Array[Int]): Double = {
    var sum = 0.0; var m = 0
    while (m < idx.length) {
      val i = idx(m); var ps = ys(i); var pc = yc(i); var k = 0
      while (k < cols.length) {
        val c = cols(k)
        if (c.s != null) ps -= beta(k) * c.s(i)
        if (c.c != null) pc -= beta(k) * c.c(i)
        k += 1
      }
      sum += ps * ps + pc * pc; m += 1
    }
    sum
  }

  /** Residual sum of squares of one channel over all samples, without a residual array. */
  def rss(cols: IndexedSeq[Col], beta: Array[Double], y: Array[Double], sinCh: Boolean): Double = {
    val use = cols.indices.filter(k => (if (sinCh) cols(k).s else cols(k).c) != null && beta(k) != 0).toArray
    val a = use.map(k => if (sinCh) cols(k).s else cols(k).c); val b = use.map(beta(_))
    Par.sum(y.length) { (lo, hi) =>
      var sum = 0.0; var i = lo
      while (i < hi) {
        var r = y(i); var k = 0
        while (k < a.length) { r -= b(k) * a(k)(i); k += 1 }
        sum += r * r; i += 1
      }
      sum
    }
  }

  /** out = sum beta_i * column_i on one channel (sin when `sinCh`). */
  def combine(cols: IndexedSeq[Col], beta: Array[Double], sinCh: Boolean, n: Int): Array[Double] = {
    val out = new Array[Double](n)
    combineInto(cols, beta, sinCh, out)
    out
  }

  /** `combine` written into `out` (overwritten). */
  def combineInto(cols: IndexedSeq[Col], beta: Array[Double], sinCh: Boolean, out: Array[Double]): Unit = {
    java.util.Arrays.fill(out, 0.0)
    addTo(out, cols, beta, sinCh, 1.0)
  }

  /** y - sum beta_i * column_i on one channel, as a new array (one pass per column, no intermediate arrays). */
  def minus(y: Array[Double], cols: IndexedSeq[Col], beta: Array[Double], sinCh: Boolean): Array[Double] = {
    val out = y.clone()
    addTo(out, cols, beta, sinCh, -1.0)
    out
  }

  /** out += sign * sum beta_i * column_i on one channel. */
  def addTo(out: Array[Double], cols: IndexedSeq[Col], beta: Array[Double], sinCh: Boolean, sign: Double): Unit = {
    // each sample gets the columns' parts in column order, as one thread would add them
    Par.blocks(out.length) { (lo, hi) =>
      var k = 0
      while (k < cols.length) {
        val a = if (sinCh) cols(k).s else cols(k).c; val b = sign * beta(k)
        if (a != null && b != 0) { var i = lo; while (i < hi) { out(i) += b * a(i); i += 1 } }
        k += 1
      }
    }
  }
}

/** A design's columns in groups (the default part, then one group per term), made on demand. With `keep` each group
  * is made once and held; without it a group is made again whenever it is needed, so that no more than two groups
  * are in memory at once (a long record's terms would not fit together). Both give the same numbers.
  */
final class ColGroups(make: IndexedSeq[() => IndexedSeq[Col]], keep: Boolean, held0: IndexedSeq[Boolean] = IndexedSeq()) {
  private val held = new Array[IndexedSeq[Col]](make.size)
  private var at: Array[Int] = _
  def size: Int = make.size
  /** Group g's columns. The first group and those marked in `held0` are always held. */
  def apply(g: Int): IndexedSeq[Col] =
    if (held(g) != null) held(g) else { val c = make(g)(); if (keep || g == 0 || held0.lift(g).contains(true)) held(g) = c; c }
  /** Where each group's coefficients start in the solution (known after `solve`). */
  def offsets: IndexedSeq[Int] = at.toIndexedSeq

  /** The least-squares fit over all groups' columns (the same numbers as `LinearFit.solve` on them all). */
  def solve(ys: Array[Double], yc: Array[Double]): LinSol = {
    val n = make.size
    // held groups: all their products in one pass over the samples; groups made again: a pass per pair of groups
    if (keep) {
      val all = (0 until n).map(apply)
      at = all.map(_.size).scanLeft(0)(_ + _).toArray
      val (g, r) = Gram.of(all.flatten, ys, yc)
      return LinearFit.normal(g, r)
    }
    val blocks = Array.ofDim[Array[Array[Double]]](n, n); val rs = new Array[Array[Double]](n)
    for (i <- 0 until n) {
      val ci = apply(i)
      for (j <- 0 to i) {
        val cj = if (j == i) ci else apply(j)
        // the products of the pair (i, j): ci's own Gram (with y), or the block between ci and cj
        if (j == i) { val (g, r) = Gram.of(ci, ys, yc); rs(i) = r; blocks(i)(j) = g }
        else blocks(i)(j) = Gram.cross(ci, cj)
      }
    }
    at = rs.map(_.length).scanLeft(0)(_ + _)
    val k = at(n)
    val g = Array.ofDim[Double](k, k)
    for (i <- 0 until n; j <- 0 to i; a <- rs(i).indices; b <- rs(j).indices) {
      val v = blocks(i)(j)(a)(b); g(at(i) + a)(at(j) + b) = v; g(at(j) + b)(at(i) + a) = v
    }
    LinearFit.normal(g, rs.flatten)
  }

  /** out += sign * sum beta_i * column_i on one channel, a group at a time. */
  def addTo(out: Array[Double], beta: Array[Double], sinCh: Boolean, sign: Double): Unit =
    for (g <- 0 until make.size) LinearFit.addTo(out, apply(g), beta.slice(at(g), at(g + 1)), sinCh, sign)
}
