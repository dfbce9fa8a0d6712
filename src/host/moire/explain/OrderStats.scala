package moire.explain

/** Exact order statistics: the values a sort of x(0 until n) puts at given ranks, from one pass for the range, one
  * for a histogram of the values and one gathering the buckets the ranks fall in (only those are sorted). A speed
  * range or a quantile of a record's length then costs a few passes, not a sort (the fit asks after every refit).
  */
object OrderStats {
  private val Buckets = 1 << 14

  /** x sorted ascending at each of `ranks` (each in 0 until n); NaN sorts last, as in `java.util.Arrays.sort`. */
  def of(n: Int, x: Int => Double, ranks: Seq[Int]): Array[Double] = {
    require(n > 0 && ranks.forall(r => r >= 0 && r < n), s"ranks must lie in 0 until $n")
    val block = math.max(Par.Block, (n + 15) / 16)
    // each pass a method of its own (small methods to compile: the one method was compiled three times in a run)
    val (lo, hi, nan) = range(n, x)
    val real = n - nan
    val span = hi - lo
    if (real == 0 || !(span < Double.PositiveInfinity)) return sorted(n, x, ranks)
    if (span == 0) return ranks.map(r => if (r < real) lo else Double.NaN).toArray
    val scale = Buckets / span
    @inline def bucket(v: Double): Int = bucketAt(v, lo, scale)
    val counts = Par.sums(n, Buckets, block) { (a, b, acc) =>
      var i = a; while (i < b) { val v = x(i); if (v == v) acc(bucket(v)) += 1; i += 1 }
    }
    // each rank's bucket and its rank within it
    val start = starts(counts)
    def bucketOf(r: Int): Int = bucketOfRank(start, r)
    val wanted = ranks.filter(_ < real).map(bucketOf).distinct.toArray
    val slot = Array.fill(Buckets)(-1); wanted.indices.foreach(j => slot(wanted(j)) = j)
    val held = wanted.map(k => new Array[Double](counts(k).toInt))
    gather(n, x, lo, scale, slot, held)
    held.foreach(a => java.util.Arrays.sort(a))
    ranks.map { r =>
      if (r >= real) Double.NaN
      else { val k = bucketOf(r); held(slot(k))((r - start(k)).toInt) }
    }.toArray
  }

  /** Where each bucket starts in the sorted order (its loops over the buckets in methods of their own: within `of` they
    * made the JIT compile all of `of`, twice in a run).
    */
  private def starts(counts: Array[Double]): Array[Long] = {
    val start = new Array[Long](Buckets + 1); var b = 0
    while (b < Buckets) { start(b + 1) = start(b) + counts(b).toLong; b += 1 }
    start
  }
  /** The bucket holding rank r. */
  private def bucketOfRank(start: Array[Long], r: Int): Int = { var k = 0; while (start(k + 1) <= r) k += 1; k }

  /** The bucket of value v (of the range from lo, `scale` buckets per unit). */
  @inline private def bucketAt(v: Double, lo: Double, scale: Double): Int = math.min(Buckets - 1, ((v - lo) * scale).toInt)

  /** The lowest and highest value that is not NaN, and the count of NaN. */
  private def range(n: Int, x: Int => Double): (Double, Double, Int) = {
    var lo = Double.PositiveInfinity; var hi = Double.NegativeInfinity; var nan = 0; var i = 0
    while (i < n) { val v = x(i); if (v != v) nan += 1 else { if (v < lo) lo = v; if (v > hi) hi = v }; i += 1 }
    (lo, hi, nan)
  }

  /** The values in the buckets kept (slot >= 0) into their arrays, in the values' order. */
  private def gather(n: Int, x: Int => Double, lo: Double, scale: Double, slot: Array[Int], held: Array[Array[Double]]): Unit = {
    val fill = new Array[Int](held.length); var i = 0
    while (i < n) {
      val v = x(i)
      if (v == v) { val s = slot(bucketAt(v, lo, scale)); if (s >= 0) { held(s)(fill(s)) = v; fill(s) += 1 } }
      i += 1
    }
  }

  /** The same by a sort (what `of` must equal). */
  def sorted(n: Int, x: Int => Double, ranks: Seq[Int]): Array[Double] = {
    val a = Array.tabulate(n)(x); java.util.Arrays.sort(a); ranks.map(a(_)).toArray
  }
}
