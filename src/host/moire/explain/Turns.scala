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

  /** sin(2 pi x) and cos(2 pi x) into out(at), out(at + 1), for x in [0, 1]. */
  @inline def sinCos(x: Double, out: Array[Double], at: Int): Unit = {
    val t = x * N; val j = t.toInt; val r = (t - j) * Step; val r2 = r * r
    val sr = r * (1 - r2 / 6 * (1 - r2 / 20 * (1 - r2 / 42)))
    val cr = 1 - r2 / 2 * (1 - r2 / 12 * (1 - r2 / 30 * (1 - r2 / 56)))
    val s = S(j); val c = C(j)
    out(at) = s * cr + c * sr; out(at + 1) = c * cr - s * sr
  }
}
