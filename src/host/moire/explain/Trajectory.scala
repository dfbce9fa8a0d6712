package moire.explain

/** A model of the fringe phase (periods) and frequency (Hz) per sample, refined by weighted least squares. */
trait PhaseTrack {
  def nseg: Int
  def params: Int
  def eval(phase: Array[Double], freq: Array[Double]): Unit
  /** Adds the weighted least-squares fit of the phase difference `d` (periods); weight w (null = 1). */
  def addFit(d: Array[Double], w: Array[Double]): Unit
}

/** A smooth phase trajectory: one cubic in time per segment of `len` samples, phase in periods. */
final class Trajectory(val n: Int, val len: Int, val fs: Double) extends PhaseTrack {
  val nseg: Int = math.max(1, (n + len - 1) / len)
  /** Cubic coefficients of segment s in local time x in [-1, 1]. */
  val coef: Array[Double] = new Array[Double](4 * nseg)
  private def seg(s: Int): (Int, Int) = (s * len, math.min(n, (s + 1) * len))
  def params: Int = 4 * nseg

  /** Phase (periods) and fringe frequency (Hz) of every sample. */
  def eval(phase: Array[Double], freq: Array[Double]): Unit = {
    var s = 0
    while (s < nseg) {
      val (a, b) = seg(s); val mid = 0.5 * (a + b - 1); val half = math.max(0.5, 0.5 * (b - a - 1))
      val c0 = coef(4 * s); val c1 = coef(4 * s + 1); val c2 = coef(4 * s + 2); val c3 = coef(4 * s + 3)
      var i = a
      while (i < b) {
        val x = (i - mid) / half
        phase(i) = c0 + x * (c1 + x * (c2 + x * c3))
        freq(i) = (c1 + x * (2 * c2 + x * 3 * c3)) * fs / half
        i += 1
      }
      s += 1
    }
  }

  /** Adds the weighted least-squares cubic of `d` (periods) per segment; weight w (null = 1). */
  def addFit(d: Array[Double], w: Array[Double]): Unit = {
    var s = 0
    val m = Array.ofDim[Double](4, 5)
    while (s < nseg) {
      val (a, b) = seg(s); val mid = 0.5 * (a + b - 1); val half = math.max(0.5, 0.5 * (b - a - 1))
      val sx = new Array[Double](7); val sy = new Array[Double](4)
      var i = a
      while (i < b) {
        val x = (i - mid) / half; val wi = if (w == null) 1.0 else w(i)
        var p = wi; var k = 0
        while (k < 7) { sx(k) += p; if (k < 4) sy(k) += p * d(i); p *= x; k += 1 }
        i += 1
      }
      val deg = math.min(3, b - a - 1)
      for (r <- 0 to 3; c <- 0 to 3) m(r)(c) = if (r <= deg && c <= deg) sx(r + c) else if (r == c) 1.0 else 0.0
      for (r <- 0 to 3) m(r)(4) = if (r <= deg) sy(r) else 0.0
      val sol = Trajectory.solve4(m)
      var k = 0
      while (k < 4) { coef(4 * s + k) += sol(k); k += 1 }
      s += 1
    }
  }
}

object Trajectory {
  /** Gaussian elimination with partial pivoting of a 4x5 augmented matrix (zero where singular). */
  def solve4(m: Array[Array[Double]]): Array[Double] = {
    val a = m.map(_.clone()); val n = 4
    for (c <- 0 until n) {
      val p = (c until n).maxBy(r => math.abs(a(r)(c)))
      val t = a(c); a(c) = a(p); a(p) = t
      if (math.abs(a(c)(c)) > 1e-300) for (r <- c + 1 until n) {
        val f = a(r)(c) / a(c)(c)
        for (k <- c to n) a(r)(k) -= f * a(c)(k)
      }
    }
    val x = new Array[Double](n)
    for (r <- n - 1 to 0 by -1) {
      var s = a(r)(n); for (k <- r + 1 until n) s -= a(r)(k) * x(k)
      x(r) = if (math.abs(a(r)(r)) > 1e-300) s / a(r)(r) else 0.0
    }
    x
  }

  /** Segment length for a recording: `periods` fringe periods at the typical speed, 64 .. 65536 samples. */
  def segmentLength(n: Int, fs: Double, typicalHz: Double, periods: Double): Int = {
    val l = if (typicalHz > 0) periods * fs / typicalHz else n.toDouble
    math.max(64, math.min(65536, math.min(n, l.toInt)))
  }
}
