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
}
