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
    val ata = Array.ofDim[Double](5, 5); val atb = new Array[Double](5); val row = new Array[Double](5)
    i = 0
    while (i < n) {
      val x = (xs(i) - mx) / sc; val y = (ys(i) - my) / sc
      row(0) = x * x; row(1) = x * y; row(2) = y * y; row(3) = x; row(4) = y
      var r = 0
      while (r < 5) { var c = 0; while (c < 5) { ata(r)(c) += row(r) * row(c); c += 1 }; atb(r) += row(r); r += 1 }
      i += 1
    }
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
