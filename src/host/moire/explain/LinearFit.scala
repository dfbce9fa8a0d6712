package moire.explain

import org.hipparchus.linear.{Array2DRowRealMatrix, LUDecomposition}

/** A column of a least-squares design over both channels; null where it is zero on a channel. */
final case class Col(s: Array[Double], c: Array[Double])

/** Linear least squares on the stacked (sin, cos) samples via normal equations with column scaling.
  * `inv` is (X'X)^-1 (unscaled covariance); `ok` is false when the columns are (nearly) dependent.
  */
final case class LinSol(beta: Array[Double], inv: Array[Array[Double]], ok: Boolean)

object LinearFit {
  private def dot(a: Array[Double], b: Array[Double]): Double = {
    if (a == null || b == null) return 0.0
    var s = 0.0; var i = 0; val n = a.length
    while (i < n) { s += a(i) * b(i); i += 1 }
    s
  }

  def solve(cols: IndexedSeq[Col], ys: Array[Double], yc: Array[Double]): LinSol = {
    val k = cols.length
    val g = Array.ofDim[Double](k, k); val r = new Array[Double](k)
    for (i <- 0 until k) {
      r(i) = dot(cols(i).s, ys) + dot(cols(i).c, yc)
      for (j <- 0 to i) { val v = dot(cols(i).s, cols(j).s) + dot(cols(i).c, cols(j).c); g(i)(j) = v; g(j)(i) = v }
    }
    val sc = Array.tabulate(k)(i => if (g(i)(i) > 0) 1 / math.sqrt(g(i)(i)) else 0.0)
    val m = new Array2DRowRealMatrix(Array.tabulate(k, k)((i, j) => g(i)(j) * sc(i) * sc(j) + (if (i == j && sc(i) == 0) 1.0 else 0.0)))
    val lu = new LUDecomposition(m, 1e-14)
    if (!lu.getSolver.isNonSingular) return LinSol(new Array[Double](k), Array.ofDim[Double](k, k), ok = false)
    val inv = lu.getSolver.getInverse
    val ok = (0 until k).forall(i => sc(i) > 0 && inv.getEntry(i, i) < 1e8)
    val beta = Array.tabulate(k)(i => sc(i) * (0 until k).map(j => inv.getEntry(i, j) * sc(j) * r(j)).sum)
    LinSol(beta, Array.tabulate(k, k)((i, j) => inv.getEntry(i, j) * sc(i) * sc(j)), ok)
  }

  /** out = sum beta_i * column_i on one channel (sin when `sinCh`). */
  def combine(cols: IndexedSeq[Col], beta: Array[Double], sinCh: Boolean, n: Int): Array[Double] = {
    val out = new Array[Double](n)
    var k = 0
    while (k < cols.length) {
      val a = if (sinCh) cols(k).s else cols(k).c; val b = beta(k)
      if (a != null && b != 0) { var i = 0; while (i < n) { out(i) += b * a(i); i += 1 } }
      k += 1
    }
    out
  }
}
