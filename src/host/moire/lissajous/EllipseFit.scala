package moire.lissajous

/** The Lissajous figure's ellipse, Heydemann's way (Appl. Opt. 20, 1981): x = cos channel, y = sin channel,
  * x = ox + ax cos t, y = oy + ay sin(t - phi). Values in full-scale units (-1 .. 1); `phaseErrorDeg` = phi,
  * the departure of the channels from 90 degrees.
  */
final case class Ellipse(offsetCos: Double, offsetSin: Double, ampCos: Double, ampSin: Double, phaseErrorDeg: Double, points: Int,
                         rmsRadial: Double) {
  /** sin amplitude over cos amplitude. */
  def ratio: Double = ampSin / ampCos
  /** Fringe phase (radians) of a point, corrected with this ellipse (offsets, gains, phase error). */
  def phase(x: Double, y: Double): Double = {
    val c = (x - offsetCos) / ampCos
    val p = math.toRadians(phaseErrorDeg)
    val s = ((y - offsetSin) / ampSin + c * math.sin(p)) / math.cos(p)
    math.atan2(s, c)
  }
  /** Points of the fitted ellipse, for a plot: (x, y) pairs. */
  def outline(n: Int): Seq[(Double, Double)] = (0 to n).map { k =>
    val t = 2 * math.Pi * k / n
    (offsetCos + ampCos * math.cos(t), offsetSin + ampSin * math.sin(t - math.toRadians(phaseErrorDeg)))
  }
}

object EllipseFit {
  /** Fewest points a fit takes (five unknowns; a few more for a figure that is not all noise). */
  val MinPoints = 16

  /** Least squares of the conic A x^2 + B xy + C y^2 + D x + E y = 1, then its centre, axes and tilt.
    * None when there are too few points or they do not lie on an ellipse (a line, a dot: no fringes).
    */
  def fit(xs: Array[Double], ys: Array[Double], n: Int): Option[Ellipse] = {
    if (n < MinPoints) return None
    // centre and scale the data for a well-conditioned system
    var mx = 0.0; var my = 0.0; var i = 0
    while (i < n) { mx += xs(i); my += ys(i); i += 1 }
    mx /= n; my /= n
    var sc = 0.0; i = 0
    while (i < n) { sc = math.max(sc, math.max(math.abs(xs(i) - mx), math.abs(ys(i) - my))); i += 1 }
    if (!(sc > 0)) return None
    // the normal equations' 15 distinct sums and the right side's 5, in local variables (row r times row c: x^2, xy,
    // y^2, x, y)
    var s00 = 0.0; var s01 = 0.0; var s02 = 0.0; var s03 = 0.0; var s04 = 0.0; var s11 = 0.0; var s12 = 0.0; var s13 = 0.0
    var s14 = 0.0; var s22 = 0.0; var s23 = 0.0; var s24 = 0.0; var s33 = 0.0; var s34 = 0.0; var s44 = 0.0
    var b0 = 0.0; var b1 = 0.0; var b2 = 0.0; var b3 = 0.0; var b4 = 0.0
    i = 0
    while (i < n) {
      val x = (xs(i) - mx) / sc; val y = (ys(i) - my) / sc
      val r0 = x * x; val r1 = x * y; val r2 = y * y
      s00 += r0 * r0; s01 += r0 * r1; s02 += r0 * r2; s03 += r0 * x; s04 += r0 * y
      s11 += r1 * r1; s12 += r1 * r2; s13 += r1 * x; s14 += r1 * y
      s22 += r2 * r2; s23 += r2 * x; s24 += r2 * y
      s33 += x * x; s34 += x * y; s44 += y * y
      b0 += r0; b1 += r1; b2 += r2; b3 += x; b4 += y
      i += 1
    }
    val ata = Array(Array(s00, s01, s02, s03, s04), Array(s01, s11, s12, s13, s14), Array(s02, s12, s22, s23, s24),
      Array(s03, s13, s23, s33, s34), Array(s04, s14, s24, s34, s44))
    val atb = Array(b0, b1, b2, b3, b4)
    val sol = try new org.hipparchus.linear.LUDecomposition(new org.hipparchus.linear.Array2DRowRealMatrix(ata), 1e-14).getSolver
      .solve(new org.hipparchus.linear.ArrayRealVector(atb)).toArray catch { case _: org.hipparchus.exception.MathRuntimeException => return None }
    val Array(a, b, c, d, e) = sol
    val det = 4 * a * c - b * b
    if (!(det > 0)) return None
    val x0 = (b * e - 2 * c * d) / det; val y0 = (b * d - 2 * a * e) / det
    // centred: A x^2 + B xy + C y^2 = K
    val big = 1 - (d * x0 + e * y0) / 2
    if (!(big > 0) || !(a > 0) || !(c > 0)) return None
    val sinPhi = b / (2 * math.sqrt(a * c))
    if (math.abs(sinPhi) >= 1) return None
    val cos2 = 1 - sinPhi * sinPhi
    val ax = math.sqrt(big / (a * cos2)) * sc; val ay = math.sqrt(big / (c * cos2)) * sc
    val el = Ellipse(mx + x0 * sc, my + y0 * sc, ax, ay, math.toDegrees(math.asin(sinPhi)), n, 0)
    // radial misfit: distance of each corrected point from the unit circle, in full scale of the mean amplitude
    var s2 = 0.0; i = 0
    val p = math.toRadians(el.phaseErrorDeg)
    while (i < n) {
      val cc = (xs(i) - el.offsetCos) / ax; val ss = ((ys(i) - el.offsetSin) / ay + cc * math.sin(p)) / math.cos(p)
      val r = math.sqrt(cc * cc + ss * ss) - 1; s2 += r * r; i += 1
    }
    Some(el.copy(rmsRadial = math.sqrt(s2 / n) * (ax + ay) / 2))
  }
}
