package moire.explain

/** sin and cos of a fraction of a turn from a table of 1,024 points and the short series of the rest (below 2 pi / 1,024
  * rad; the series' next terms are below 1e-19): within a few units in the last place of `math.sin` and `math.cos`,
  * at a fraction of their cost. The fit's fundamentals take them at every sample of every refit.
  */
object Turns {
  private val N = 1024
  private val S = Array.tabulate(N + 1)(k => math.sin(2 * math.Pi * k / N))
  private val C = Array.tabulate(N + 1)(k => math.cos(2 * math.Pi * k / N))
  private val Step = 2 * math.Pi / N

  // the series' factors as products (the JIT keeps a division by a constant a division, several times a product's cost)
  private val S1 = 1.0 / 6; private val S2 = 1.0 / 20; private val S3 = 1.0 / 42
  private val C2 = 1.0 / 12; private val C3 = 1.0 / 30; private val C4 = 1.0 / 56

  /** 1.5 * 2^52: a double below 2^51 in magnitude plus this, less this, is the integer nearest it. */
  private val Magic = 6755399441055744.0
  private val Limit = 2251799813685248.0 // 2^51

  /** `math.floor(t)` to the bit, from an addition and a subtraction: the library's `roundsd`, as the int made a double
    * (`cvtsi2sd`), writes only part of its register and waits on that register's last value, which chained each
    * sample's sin and cos to the one before (a 1 M-sample loop of `sinCos`: 35 -> 22 ms).
    */
  @inline def floor(t: Double): Double =
    if (!(math.abs(t) < Limit) || t == 0.0) math.floor(t) // beyond 2^51, infinite, NaN; and -0.0, which floors to itself
    else { val r = (t + Magic) - Magic; if (r > t) r - 1 else r }

  /** sin(2 pi x) and cos(2 pi x) into out(at), out(at + 1), for x in [0, 1]. */
  @inline def sinCos(x: Double, out: Array[Double], at: Int): Unit = {
    // the index truncated (as `toInt`), as a double without converting the int back
    val t = x * N; val jd = if (t >= 0) floor(t) else -floor(-t); val j = jd.toInt; val r = (t - jd) * Step; val r2 = r * r
    val sr = r * (1 - r2 * S1 * (1 - r2 * S2 * (1 - r2 * S3)))
    val cr = 1 - r2 * 0.5 * (1 - r2 * C2 * (1 - r2 * C3 * (1 - r2 * C4)))
    val s = S(j); val c = C(j)
    out(at) = s * cr + c * sr; out(at + 1) = c * cr - s * sr
  }
}
