package moire.explain

import java.util.stream.IntStream

/** Loops over the samples on all cores, in fixed blocks: an element-wise loop gives the same arrays as one thread, a
  * sum adds its blocks' partial sums in block order (the same numbers whatever the number of cores).
  */
object Par {
  /** Samples per block. */
  val Block = 8192
  /** Samples below which one thread does the loop. */
  val Min = 1 << 15

  /** body(lo, hi) over consecutive blocks of `block` samples covering [0, n), on all cores when n is large. */
  def blocks(n: Int, block: Int = Block)(body: (Int, Int) => Unit): Unit = {
    if (FitPath.isReference) { body(0, n); return }
    val k = (n + block - 1) / block
    val f: java.util.function.IntConsumer = b => body(b * block, math.min(n, (b + 1) * block))
    if (n >= Min) IntStream.range(0, k).parallel().forEach(f) else { var b = 0; while (b < k) { f.accept(b); b += 1 } }
  }

  /** The sums of m accumulators over [0, n): part(lo, hi, acc) adds block [lo, hi) into acc (zeroed); blocks added in order. */
  def sums(n: Int, m: Int, block: Int = Block)(part: (Int, Int, Array[Double]) => Unit): Array[Double] = {
    if (FitPath.isReference) { val a = new Array[Double](m); part(0, n, a); return a }
    val k = (n + block - 1) / block
    val parts = Array.ofDim[Double](k, m)
    blocks(n, block)((lo, hi) => part(lo, hi, parts(lo / block)))
    val out = new Array[Double](m)
    var b = 0
    while (b < k) { var j = 0; while (j < m) { out(j) += parts(b)(j); j += 1 }; b += 1 }
    out
  }

  /** body(k) for each of k independent parts (segments) that together cover `samples` samples, on all cores when
    * they are many; each part is done by one thread, so the numbers do not depend on the cores.
    */
  def each(k: Int, samples: Long)(body: Int => Unit): Unit = {
    if (FitPath.isReference || samples < Min || k < 2) { var j = 0; while (j < k) { body(j); j += 1 }; return }
    IntStream.range(0, k).parallel().forEach(j => body(j))
  }

  /** One sum over [0, n) (see `sums`). */
  def sum(n: Int)(part: (Int, Int) => Double): Double = sums(n, 1)((lo, hi, a) => a(0) += part(lo, hi))(0)
}
