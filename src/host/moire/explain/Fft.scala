package moire.explain

import org.hipparchus.transform.{DftNormalization, FastFourierTransformer, TransformType}

/** Power spectrum through Hipparchus' in-place FFT. */
object Fft {
  /** |X_k|^2 for k = 0 .. m/2-1 of the first m samples (m a power of two). */
  def power(x: Array[Double], m: Int): Array[Double] = {
    require(m > 0 && (m & (m - 1)) == 0, s"FFT length must be a power of two, got $m")
    val ri = Array(java.util.Arrays.copyOf(x, m), new Array[Double](m))
    FastFourierTransformer.transformInPlace(ri, DftNormalization.STANDARD, TransformType.FORWARD)
    Array.tabulate(m / 2)(k => ri(0)(k) * ri(0)(k) + ri(1)(k) * ri(1)(k))
  }
}
