package moire.explain

/** Arrays of doubles made from a function of the index without boxing (Array.tabulate boxes each element). */
object Doubles {
  def tabulate(n: Int)(f: Int => Double): Array[Double] = {
    val a = new Array[Double](n); var i = 0
    while (i < n) { a(i) = f(i); i += 1 }
    a
  }
}
