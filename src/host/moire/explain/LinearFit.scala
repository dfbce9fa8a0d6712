package moire.explain

import org.hipparchus.linear.{Array2DRowRealMatrix, LUDecomposition}

/** A column of a least-squares design over both channels; null where it is zero on a channel, `Col.Ones` where it is
  * one at every sample.
  */
final case class Col(s: Array[Double], c: Array[Double])
object Col {
  /** The column of ones (a channel's offset), not stored: every reader of a column treats this array as 1 at each
    * sample (an array of the record's length, 160 MB at 20 M samples, fewer).
    */
  val Ones: Array[Double] = new Array[Double](0)
  /** a(i), with `Ones` read as 1. */
  @inline def at(a: Array[Double], i: Int): Double = if (a eq Ones) 1.0 else a(i)
}

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
        if (c.s != null) ps -= beta(k) * Col.at(c.s, i)
        if (c.c != null) pc -= beta(k) * Col.at(c.c, i)
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
        while (k < a.length) { r -= b(k) * Col.at(a(k), i); k += 1 }
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
        if (a eq Col.Ones) { if (b != 0) { var i = lo; while (i < hi) { out(i) += b; i += 1 } } }
        else if (a != null && b != 0) { var i = lo; while (i < hi) { out(i) += b * a(i); i += 1 } }
        k += 1
      }
    }
  }
}

/** A group's columns made a block of samples at a time, never whole: `fill(lo, hi, out, at)` writes samples [lo, hi)
  * of column j's sin part into out(2 j) and of its cos part into out(2 j + 1), sample i at index at + i - lo. `sin(j)` /
  * `cos(j)`: column j has a part on that channel (else its out entry is null and left alone).
  */
final class ColGen(val sin: Array[Boolean], val cos: Array[Boolean], val fill: (Int, Int, Array[Array[Double]], Int) => Unit) {
  def size: Int = sin.length
  /** Arrays `fill` writes `len` samples into: column j's sin part at 2 j, its cos part at 2 j + 1 (null where none). */
  def buffers(len: Int): Array[Array[Double]] =
    Array.tabulate(2 * size)(p => if ((if (p % 2 == 0) sin else cos)(p / 2)) new Array[Double](len) else null)
  /** `buffers` for a block that is read before the thread makes its next one: the thread's last ones when of the same
    * length (`fill` writes all of them), else new ones.
    */
  def blockBuffers(len: Int): Array[Array[Double]] = {
    val b = pool.get()
    if (b != null && b.exists(a => a != null && a.length == len)) b else { val m = buffers(len); pool.set(m); m }
  }
  private val pool = new ThreadLocal[Array[Array[Double]]]
  /** The columns over all n samples, as arrays (the blocks on all cores). */
  def whole(n: Int): IndexedSeq[Col] = {
    val out = buffers(n)
    Par.blocks(n, Gram.Block)((lo, hi) => fill(lo, hi, out, lo))
    (0 until size).map(j => Col(out(2 * j), out(2 * j + 1)))
  }
}

/** A design's columns in groups (the default part, then one group per term). With `keep` each group is made once and
  * held; without it the groups that have a generator (`gens`) are made a block at a time wherever they are read (a long
  * record's terms would not fit in memory), the others once and held. Both give the same numbers.
  */
final class ColGroups(make: IndexedSeq[() => IndexedSeq[Col]], keep: Boolean, held0: IndexedSeq[Boolean] = IndexedSeq(),
                      gens: IndexedSeq[ColGen] = IndexedSeq()) {
  private val held = new Array[IndexedSeq[Col]](make.size)
  private var at: Array[Int] = _
  def size: Int = make.size
  private def gen(g: Int): ColGen = if (keep || g == 0 || held0.lift(g).contains(true)) null else gens.lift(g).orNull
  /** Group g's columns, whole. The groups without a generator are held once made. */
  def apply(g: Int): IndexedSeq[Col] =
    if (held(g) != null) held(g) else { val c = make(g)(); if (gen(g) == null) held(g) = c; c }
  /** Where each group's coefficients start in the solution (known after `solve`). */
  def offsets: IndexedSeq[Int] = at.toIndexedSeq
  private def streamed: Boolean = (0 until size).exists(gen(_) != null)

  /** The held groups' columns (null where a group is made a block at a time), and where each group's start. */
  private def layout(): IndexedSeq[IndexedSeq[Col]] = {
    val all = (0 until size).map(g => if (gen(g) == null) apply(g) else null)
    at = (0 until size).map(g => if (all(g) == null) gen(g).size else all(g).size).scanLeft(0)(_ + _).toArray
    all
  }

  /** The least-squares fit over all groups' columns (the same numbers as `LinearFit.solve` on them all). */
  def solve(ys: Array[Double], yc: Array[Double], skip: Gram.Skip = null): LinSol = {
    val all = layout()
    if (!streamed) { val (g, r) = Gram.of(all.flatten, ys, yc, skip = skip); return LinearFit.normal(g, r) }
    // the held columns read in place beside the made ones' block: the same block sums as `Gram.of` on whole columns
    val k = at(size)
    val sum = Par.sums(ys.length, k * (k + 1) / 2 + k, Gram.Block) { (lo, hi, out) =>
      val b = block(all, lo, hi, sinCh = true, cosCh = true)
      Gram.blockAt(b.s, b.sFrom, b.c, b.cFrom, ys, yc, lo, hi, out, skip)
    }
    val (g, r) = Gram.unpack(sum, k)
    LinearFit.normal(g, r)
  }

  /** Every column's samples [lo, hi) on the channels asked for: column k's sample i at s(k)(i - sFrom(k)) (held
    * columns whole, sFrom 0; made ones a block, sFrom lo), and the same for c.
    */
  private final class Block(val s: Array[Array[Double]], val sFrom: Array[Int], val c: Array[Array[Double]], val cFrom: Array[Int])
  private def block(all: IndexedSeq[IndexedSeq[Col]], lo: Int, hi: Int, sinCh: Boolean, cosCh: Boolean): Block = {
    val k = at(size); val b = new Block(new Array[Array[Double]](k), new Array[Int](k), new Array[Array[Double]](k), new Array[Int](k))
    for (g <- 0 until size) {
      val gn = gen(g)
      if (gn == null) for ((col, j) <- all(g).zipWithIndex) {
        if (sinCh) b.s(at(g) + j) = col.s; if (cosCh) b.c(at(g) + j) = col.c
      } else {
        val out = gn.blockBuffers(hi - lo)
        gn.fill(lo, hi, out, 0)
        for (j <- 0 until gn.size) {
          if (sinCh) { b.s(at(g) + j) = out(2 * j); b.sFrom(at(g) + j) = lo }
          if (cosCh) { b.c(at(g) + j) = out(2 * j + 1); b.cFrom(at(g) + j) = lo }
        }
      }
    }
    b
  }

  /** Each channel's residual sum of squares of ys, yc less the columns times beta (no residual arrays). */
  def rss(ys: Array[Double], yc: Array[Double], beta: Array[Double]): (Double, Double) = {
    val all = layout()
    if (!streamed) { val cols = all.flatten; return (LinearFit.rss(cols, beta, ys, sinCh = true), LinearFit.rss(cols, beta, yc, sinCh = false)) }
    val q = Par.sums(ys.length, 2, Gram.Block) { (lo, hi, out) =>
      val bl = block(all, lo, hi, sinCh = true, cosCh = true)
      for ((y, a, from, o) <- Seq((ys, bl.s, bl.sFrom, 0), (yc, bl.c, bl.cFrom, 1))) {
        val r = java.util.Arrays.copyOfRange(y, lo, hi); var k = 0
        while (k < a.length) {
          val x = a(k); val b = beta(k); val d = lo - from(k)
          if (x eq Col.Ones) { if (b != 0) { var i = 0; while (i < r.length) { r(i) -= b; i += 1 } } }
          else if (x != null && b != 0) { var i = 0; while (i < r.length) { r(i) -= b * x(i + d); i += 1 } }
          k += 1
        }
        var z = 0.0; var i = 0; while (i < r.length) { z += r(i) * r(i); i += 1 }
        out(o) += z
      }
    }
    (q(0), q(1))
  }

  /** out += sign * sum beta_i * column_i on each channel (null: not that one), in one pass when columns are made a
    * block at a time: each sample gets the columns' parts in column order, as `LinearFit.addTo` adds them.
    * With `initS`/`initC`, out starts as a copy of them (a block at a time in that pass: a long record's residual is
    * one pass over memory, not a copy and then a pass).
    */
  def addToBoth(outS: Array[Double], outC: Array[Double], beta: Array[Double], sign: Double,
                initS: Array[Double] = null, initC: Array[Double] = null): Unit = {
    val all = layout()
    if (!streamed) {
      for ((o, y) <- Seq((outS, initS), (outC, initC)) if o != null && y != null) System.arraycopy(y, 0, o, 0, o.length)
      for (g <- 0 until size; (o, ch) <- Seq((outS, true), (outC, false)) if o != null) LinearFit.addTo(o, all(g), beta.slice(at(g), at(g + 1)), ch, sign)
      return
    }
    val n = if (outS != null) outS.length else outC.length
    Par.blocks(n, Gram.Block) { (lo, hi) =>
      val bl = block(all, lo, hi, outS != null, outC != null)
      for ((o, a, from, y) <- Seq((outS, bl.s, bl.sFrom, initS), (outC, bl.c, bl.cFrom, initC)) if o != null) {
        if (y != null) System.arraycopy(y, lo, o, lo, hi - lo)
        var k = 0
        while (k < a.length) {
          val x = a(k); val b = sign * beta(k); val d = from(k)
          if (x eq Col.Ones) { if (b != 0) { var i = lo; while (i < hi) { o(i) += b; i += 1 } } }
          else if (x != null && b != 0) { var i = lo; while (i < hi) { o(i) += b * x(i - d); i += 1 } }
          k += 1
        }
      }
    }
  }
}
