package moire.explain

/** In-place radix-2 FFT and a power spectrum (the Hipparchus FFT lives in hipparchus-fft, not on our class path). */
object Fft {
  def transform(re: Array[Double], im: Array[Double]): Unit = {
    val n = re.length
    require(n > 0 && (n & (n - 1)) == 0, s"FFT length must be a power of two, got $n")
    var j = 0
    for (i <- 1 until n) {
      var bit = n >> 1
      while ((j & bit) != 0) { j ^= bit; bit >>= 1 }
      j |= bit
      if (i < j) { val t = re(i); re(i) = re(j); re(j) = t; val u = im(i); im(i) = im(j); im(j) = u }
    }
    var len = 2
    while (len <= n) {
      val ang = -2 * math.Pi / len; val wr = math.cos(ang); val wi = math.sin(ang)
      var i = 0
      while (i < n) {
        var cr = 1.0; var ci = 0.0; var k = 0
        while (k < len / 2) {
          val a = i + k; val b = a + len / 2
          val xr = re(b) * cr - im(b) * ci; val xi = re(b) * ci + im(b) * cr
          re(b) = re(a) - xr; im(b) = im(a) - xi; re(a) += xr; im(a) += xi
          val t = cr * wr - ci * wi; ci = cr * wi + ci * wr; cr = t
          k += 1
        }
        i += len
      }
      len <<= 1
    }
  }

  /** |X_k|^2 for k = 0 .. m/2-1 of the first m samples (m a power of two). */
  def power(x: Array[Double], m: Int): Array[Double] = {
    val re = java.util.Arrays.copyOf(x, m); val im = new Array[Double](m)
    transform(re, im)
    Array.tabulate(m / 2)(k => re(k) * re(k) + im(k) * im(k))
  }
}
