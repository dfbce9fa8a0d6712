package moire.explain

/** Arrays of doubles made from a function of the index without boxing (Array.tabulate boxes each element), in blocks
  * on all cores (f must only read: each element is f of its index, whichever thread makes it).
  */
object Doubles {
  def tabulate(n: Int)(f: Int => Double): Array[Double] = {
    val a = new Array[Double](n)
    Par.blocks(n) { (lo, hi) => var i = lo; while (i < hi) { a(i) = f(i); i += 1 } }
    a
  }

  /** The lowest and highest of f(i) over [0, n) (0, 0 when n is 0), in blocks on all cores. */
  def range(n: Int)(f: Int => Double): (Double, Double) = {
    val k = (n + Par.Block - 1) / Par.Block
    val mins = new Array[Double](k); val maxs = new Array[Double](k)
    Par.blocks(n) { (a, b) =>
      var mn = Double.PositiveInfinity; var mx = Double.NegativeInfinity; var i = a
      while (i < b) { val v = f(i); if (v < mn) mn = v; if (v > mx) mx = v; i += 1 }
      mins(a / Par.Block) = mn; maxs(a / Par.Block) = mx
    }
    if (k == 0) (0.0, 0.0) else (mins.min, maxs.max)
  }
}
