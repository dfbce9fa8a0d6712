package moire.explain

import org.hipparchus.transform.{DftNormalization, FastFourierTransformer, TransformType}

/** Power spectrum through Hipparchus' in-place FFT. */
object Fft {
  /** |X_k|^2 for k = 0 .. m/2-1 of the first m samples (m a power of two). */
  def power(x: Array[Double], m: Int): Array[Double] = {
    require(m > 0 && (m & (m - 1)) == 0, s"FFT length must be a power of two, got $m")
    val ri = Array(java.util.Arrays.copyOf(x, m), new Array[Double](m))
    FastFourierTransformer.transformInPlace(ri, DftNormalization.STANDARD, TransformType.FORWARD)
    Doubles.tabulate(m / 2)(k => ri(0)(k) * ri(0)(k) + ri(1)(k) * ri(1)(k))
  }

  /** |A_k|^2 + |B_k|^2 for k = 0 .. m/2-1 of two real records' first m samples, by one complex FFT of a + i b:
    * |A_k|^2 + |B_k|^2 = (|Z_k|^2 + |Z_(m-k)|^2) / 2.
    */
  def powerSum(a: Array[Double], b: Array[Double], m: Int): Array[Double] = {
    require(m > 0 && (m & (m - 1)) == 0, s"FFT length must be a power of two, got $m")
    val ri = Array(java.util.Arrays.copyOf(a, m), java.util.Arrays.copyOf(b, m))
    FastFourierTransformer.transformInPlace(ri, DftNormalization.STANDARD, TransformType.FORWARD)
    def p(k: Int) = ri(0)(k) * ri(0)(k) + ri(1)(k) * ri(1)(k)
    Doubles.tabulate(m / 2)(k => if (k == 0) p(0) else 0.5 * (p(k) + p(m - k)))
  }
}
