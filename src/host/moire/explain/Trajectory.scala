package moire.explain

/** A model of the fringe phase (periods) and frequency (Hz) per sample, refined by weighted least squares. */
trait PhaseTrack {
  def nseg: Int
  def params: Int
  def eval(phase: Array[Double], freq: Array[Double]): Unit
  /** Adds the weighted least-squares fit of the phase difference `d` (periods); weight w (null = 1). */
  def addFit(d: Array[Double], w: Array[Double]): Unit
  /** Puts this trajectory back as it is now, when called. */
  def keep(): () => Unit
}

/** A smooth phase trajectory: one cubic in time per segment of `len` samples, phase in periods; segments where the
  * motion asked for shorter ones halved (`split`): segment s spans samples [bounds(s), bounds(s + 1)).
  */
final class Trajectory(val n: Int, val len: Int, val fs: Double, given: Array[Int] = null) extends PhaseTrack {
  val bounds: Array[Int] =
    if (given != null) given else { val k = math.max(1, (n + len - 1) / len); Array.tabulate(k + 1)(s => math.min(n, s * len)) }
  val nseg: Int = bounds.length - 1
  /** Cubic coefficients of segment s in local time x in [-1, 1]. */
  val coef: Array[Double] = new Array[Double](4 * nseg)
  private def seg(s: Int): (Int, Int) = (bounds(s), bounds(s + 1))
  /** The shortest segment (samples), but for the last one (the record's remainder after whole segments). */
  def shortest: Int = if (nseg == 1) n else (0 until nseg - 1).map(s => bounds(s + 1) - bounds(s)).min
  def params: Int = 4 * nseg

  /** This trajectory with the segments `which` halved (coefficients zero: fit it to a phase). */
  def split(which: Array[Boolean]): Trajectory = {
    val b = Array.newBuilder[Int]
    for (s <- 0 until nseg) { b += bounds(s); if (which(s)) b += (bounds(s) + bounds(s + 1)) / 2 }
    b += n
    new Trajectory(n, len, fs, b.result())
  }

  /** Per segment, how much two cubics on its halves (each of `least` samples at least) explain of `dw`'s weighted
    * difference beyond one cubic on the whole: the weighted sum of squares a split would take up (0 where too short).
    */
  def splitGains(dw: Trajectory.Residual, least: Int): Array[Double] = {
    val g = new Array[Double](nseg)
    Par.each(nseg, n) { s =>
      val (a, b) = seg(s)
      if (b - a >= 2 * least) {
        val m = (a + b) / 2
        g(s) = math.max(0.0, Trajectory.explained(dw, a, m) + Trajectory.explained(dw, m, b) - Trajectory.explained(dw, a, b))
      }
    }
    g
  }
  def keep(): () => Unit = { val c = coef.clone(); () => System.arraycopy(c, 0, coef, 0, c.length) }

  /** Phase (periods) and fringe frequency (Hz) of every sample. */
  def eval(phase: Array[Double], freq: Array[Double]): Unit =
    Par.each(nseg, n) { s =>
      val (a, b) = seg(s); val mid = 0.5 * (a + b - 1); val half = math.max(0.5, 0.5 * (b - a - 1))
      val c0 = coef(4 * s); val c1 = coef(4 * s + 1); val c2 = coef(4 * s + 2); val c3 = coef(4 * s + 3)
      val inv = 1 / half; val hz = fs / half
      // i as a double counted along (exact): converting the int at every sample took six times the loop's time
      var i = a; var id = a.toDouble
      while (i < b) {
        val x = (id - mid) * inv
        phase(i) = c0 + x * (c1 + x * (c2 + x * c3))
        freq(i) = (c1 + x * (2 * c2 + x * 3 * c3)) * hz
        i += 1; id += 1.0
      }
    }

  /** Adds the weighted least-squares cubic of `d` (periods) per segment; weight w (null = 1). */
  def addFit(d: Array[Double], w: Array[Double]): Unit =
    addFitBy { (i, o) => val p = if (w == null) 1.0 else w(i); o(1) = p; o(0) = if (p == 0) 0.0 else d(i) }

  /** `addFit` of the phase difference and weight that `dw` writes for sample i into o(0) and o(1) (the difference is
    * not read where the weight is 0), made where they are needed (no arrays of the record's length).
    */
  def addFitBy(dw: Trajectory.Residual): Unit =
    Par.each(nseg, n) { s =>
      val m = Array.ofDim[Double](4, 5); val o = new Array[Double](2)
      val (a, b) = seg(s); val mid = 0.5 * (a + b - 1); val half = math.max(0.5, 0.5 * (b - a - 1))
      val sums = new Array[Double](11)
      Trajectory.segmentSums(dw, a, b, mid, 1 / half, o, sums)
      val sx = sums.take(7); val sy = sums.drop(7)
      val deg = math.min(3, b - a - 1)
      for (r <- 0 to 3; c <- 0 to 3) m(r)(c) = if (r <= deg && c <= deg) sx(r + c) else if (r == c) 1.0 else 0.0
      for (r <- 0 to 3) m(r)(4) = if (r <= deg) sy(r) else 0.0
      val sol = Trajectory.solve4(m)
      var k = 0
      while (k < 4) { coef(4 * s + k) += sol(k); k += 1 }
    }
}

object Trajectory {
  /** A sample's phase difference (periods) and weight, written to o(0) and o(1). */
  trait Residual { def at(i: Int, o: Array[Double]): Unit }

  /** A segment's [a, b) weighted sums of x^0..x^6 and of d x^0..x^3 (x the sample's place in it, from -1 to 1) into
    * out(0..6) and out(7..10), `dw`'s difference and weight written to o. A method of its own: within the segment's
    * closure the JIT compiled it three times in a new JVM's 1 M run.
    */
  def segmentSums(dw: Residual, a: Int, b: Int, mid: Double, inv: Double, o: Array[Double], out: Array[Double]): Unit = {
    var x0 = 0.0; var x1 = 0.0; var x2 = 0.0; var x3 = 0.0; var x4 = 0.0; var x5 = 0.0; var x6 = 0.0
    var y0 = 0.0; var y1 = 0.0; var y2 = 0.0; var y3 = 0.0
    var i = a; var id = a.toDouble // i as a double, counted along (exact; see eval)
    while (i < b) {
      dw.at(i, o)
      val x = (id - mid) * inv; val p0 = o(1)
      val p1 = p0 * x; val p2 = p1 * x; val p3 = p2 * x; val p4 = p3 * x; val p5 = p4 * x; val p6 = p5 * x; val di = if (p0 == 0) 0.0 else o(0)
      x0 += p0; x1 += p1; x2 += p2; x3 += p3; x4 += p4; x5 += p5; x6 += p6
      y0 += p0 * di; y1 += p1 * di; y2 += p2 * di; y3 += p3 * di
      i += 1; id += 1.0
    }
    out(0) = x0; out(1) = x1; out(2) = x2; out(3) = x3; out(4) = x4; out(5) = x5; out(6) = x6
    out(7) = y0; out(8) = y1; out(9) = y2; out(10) = y3
  }

  /** The weighted sum of squares of `dw`'s difference over [a, b) that its least-squares cubic there explains. */
  def explained(dw: Residual, a: Int, b: Int): Double = {
    val mid = 0.5 * (a + b - 1); val half = math.max(0.5, 0.5 * (b - a - 1))
    val sums = new Array[Double](11); segmentSums(dw, a, b, mid, 1 / half, new Array[Double](2), sums)
    val deg = math.min(3, b - a - 1)
    val m = Array.tabulate(4, 5)((r, c) => if (c == 4) (if (r <= deg) sums(7 + r) else 0.0) else if (r <= deg && c <= deg) sums(r + c) else if (r == c) 1.0 else 0.0)
    val beta = solve4(m)
    (0 to deg).map(r => beta(r) * sums(7 + r)).sum
  }

  /** Gaussian elimination with partial pivoting of a 4x5 augmented matrix (zero where singular). */
  def solve4(m: Array[Array[Double]]): Array[Double] = {
    val a = m.map(_.clone()); val n = 4
    var c = 0
    while (c < n) {
      var p = c; var r = c + 1
      while (r < n) { if (math.abs(a(r)(c)) > math.abs(a(p)(c))) p = r; r += 1 }
      val t = a(c); a(c) = a(p); a(p) = t
      if (math.abs(a(c)(c)) > 1e-300) {
        r = c + 1
        while (r < n) { val f = a(r)(c) / a(c)(c); var k = c; while (k <= n) { a(r)(k) -= f * a(c)(k); k += 1 }; r += 1 }
      }
      c += 1
    }
    val x = new Array[Double](n)
    var r = n - 1
    while (r >= 0) {
      var s = a(r)(n); var k = r + 1
      while (k < n) { s -= a(r)(k) * x(k); k += 1 }
      x(r) = if (math.abs(a(r)(r)) > 1e-300) s / a(r)(r) else 0.0
      r -= 1
    }
    x
  }

  /** The shortest segment (samples) for motion the longer ones follow, or that are all far off. */
  val MinLength = 64
  /** The shortest segment (samples) at all: for motion that 64-sample cubics still leave, while shorter ones lower BIC. */
  val LeastLength = 16

  /** Segment length for a recording: `periods` fringe periods at the typical speed, 64 .. 65536 samples. */
  def segmentLength(n: Int, fs: Double, typicalHz: Double, periods: Double): Int = {
    val l = if (typicalHz > 0) periods * fs / typicalHz else n.toDouble
    math.max(MinLength, math.min(65536, math.min(n, l.toInt)))
  }
}
