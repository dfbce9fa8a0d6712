package moire.explain

/** What the two channels' signal paths do to the fundamental at fringe frequency f (Hz): the skew of
  * `sp` (the sin channel sampled half of it early, the cos channel half late), a bandwidth of both
  * channels and one of each (first-order low-pass: gain 1/sqrt(1+u^2), lag atan(u), u = f/fc; the
  * mean lag of the two is taken as the motion's own and left to the phase). For the phase's sin `sn`
  * and cos `cs`, writes into `out` the sin and cos columns of the sin channel, then of the cos channel.
  */
private[explain] final class ChannelResponse(sp: ModelSpec) {
  private val fcB = sp.bw.getOrElse("both", Double.PositiveInfinity)
  private val fcS = sp.bw.getOrElse("sin", Double.PositiveInfinity)
  private val fcC = sp.bw.getOrElse("cos", Double.PositiveInfinity)
  private val w = 2 * math.Pi * sp.skewS
  private val (kS, kC) = sp.gainPerHz

  private val reference = FitPath.isReference
  /** A channel has a cut-off of its own (without, neither channel lags the other). */
  private val own = !fcS.isInfinite || !fcC.isInfinite

  def apply(f: Double, sn: Double, cs: Double, out: Array[Double]): Unit = if (reference) direct(f, sn, cs, out) else {
    var gs = 1 + kS * f; var gc = 1 + kC * f
    if (!fcB.isInfinite) { val u = f / fcB; val g = 1 / math.sqrt(1 + u * u); gs *= g; gc *= g }
    // the sin channel turns by l = (lagC - lagS) / 2 - w f / 2 and the cos channel by -l; l's half of the lag difference
    // from exp(i (lagC - lagS)) = (1 + uC uS + i (uC - uS)) / (nS nC) by the half-angle formulas (no atan)
    var ch = 1.0; var sh = 0.0
    if (own) {
      val uS = if (fcS.isInfinite) 0.0 else f / fcS; val uC = if (fcC.isInfinite) 0.0 else f / fcC
      val nS = math.sqrt(1 + uS * uS); val nC = math.sqrt(1 + uC * uC)
      gs /= nS; gc /= nC
      val cd = (1 + uC * uS) / (nS * nC); ch = math.sqrt(0.5 * (1 + cd)); sh = (uC - uS) / (nS * nC) / (2 * ch)
    }
    var cl = ch; var sl = sh
    if (w != 0) {
      val x = 0.5 * w * f; var cw = 0.0; var sw = 0.0
      if (math.abs(x) <= 0.25) { cw = ChannelResponse.cosSmall(x); sw = ChannelResponse.sinSmall(x) } else { cw = math.cos(x); sw = math.sin(x) }
      cl = ch * cw + sh * sw; sl = sh * cw - ch * sw
    }
    out(0) = gs * (sn * cl + cs * sl); out(1) = gs * (cs * cl - sn * sl)
    out(2) = gc * (sn * cl - cs * sl); out(3) = gc * (cs * cl + sn * sl)
  }

  /** The reference path: the lags by atan, each channel's turn on its own. */
  private def direct(f: Double, sn: Double, cs: Double, out: Array[Double]): Unit = {
    var gs = 1 + kS * f; var gc = 1 + kC * f; var ls = -0.5 * w * f; var lc = 0.5 * w * f
    if (!fcB.isInfinite) { val u = f / fcB; val g = 1 / math.sqrt(1 + u * u); gs *= g; gc *= g }
    var lagS = 0.0; var lagC = 0.0
    if (!fcS.isInfinite) { val u = f / fcS; gs /= math.sqrt(1 + u * u); lagS = math.atan(u) }
    if (!fcC.isInfinite) { val u = f / fcC; gc /= math.sqrt(1 + u * u); lagC = math.atan(u) }
    val m = 0.5 * (lagS + lagC); ls += m - lagS; lc += m - lagC
    val cls = math.cos(ls); val sls = math.sin(ls); val clc = math.cos(lc); val slc = math.sin(lc)
    out(0) = gs * (sn * cls + cs * sls); out(1) = gs * (cs * cls - sn * sls)
    out(2) = gc * (sn * clc + cs * slc); out(3) = gc * (cs * clc - sn * slc)
  }
}

/** A response's coefficients over the fringe frequencies [lo, hi] in bins, each the quadratic through its centre and
  * ends: a sample's columns from a few products instead of square roots and divisions. `ok` is false when the
  * quadratic misses the response by more than `tol` (relative) at a bin's quarter points (a range far wider than the
  * cut-offs): the caller then evaluates the response itself.
  */
private[explain] final class ResponseTable(resp: ChannelResponse, lo: Double, hi: Double, bins: Int, tol: Double) {
  private val width = if (hi > lo) (hi - lo) / bins else 0.0
  private val inv = if (width > 0) 1 / width else 0.0
  private val k = if (width > 0) bins else 1
  private val last = (k - 1).toDouble
  // per bin, for A and B of each channel (x1 = A sn + B cs, x2 = A cs - B sn): c0 + c1 u + c2 u^2, u in [-1/2, 1/2]
  private val c = new Array[Double](12 * k)
  val ok: Boolean = {
    // the bins in parts on all cores (a bin's left end is the response at its own left edge, which is the one before's
    // right edge: the same number), without an array or a closure per response
    val parts = math.min(16, k); val per = (k + parts - 1) / parts; val fine = Array.fill(parts)(true)
    Par.each(parts, 16L * k) { part =>
      val o = new Array[Double](4); var l = new Array[Double](4); val z = new Array[Double](4); var r = new Array[Double](4)
      val x = new Array[Double](4)
      def at(f: Double, to: Array[Double]): Unit = { resp(f, 1.0, 0.0, o); to(0) = o(0); to(1) = -o(1); to(2) = o(2); to(3) = -o(3) }
      var b = part * per; val end = math.min(k, (part + 1) * per)
      if (b < end) at(if (b == 0) lo else lo + b * width, l)
      while (b < end) {
        at(lo + (b + 0.5) * width, z); at(lo + (b + 1) * width, r)
        var j = 0
        while (j < 4) {
          val m = l(j); val zj = z(j); val p = r(j)
          c(12 * b + 3 * j) = zj; c(12 * b + 3 * j + 1) = p - m; c(12 * b + 3 * j + 2) = 2 * (p + m - 2 * zj)
          j += 1
        }
        var side = 0
        while (side < 2) {
          val u = if (side == 0) -0.25 else 0.25
          at(lo + (b + 0.5 + u) * width, x)
          j = 0
          while (j < 4) {
            val q = c(12 * b + 3 * j) + u * (c(12 * b + 3 * j + 1) + u * c(12 * b + 3 * j + 2))
            if (!(math.abs(q - x(j)) <= tol * math.max(1.0, math.abs(x(j))))) fine(part) = false
            j += 1
          }
          side += 1
        }
        val t = l; l = r; r = t; b += 1
      }
    }
    fine.forall(identity)
  }

  /** As `ChannelResponse.apply`, from the table. */
  @inline def apply(f: Double, sn: Double, cs: Double, out: Array[Double]): Unit = {
    val x = (f - lo) * inv
    // the bin as a double (floor, as `toInt` here) and as an int: no int made a double again (see `Turns.floor`)
    val bd = if (x <= 0) 0.0 else if (x >= last) last else Turns.floor(x); val b = bd.toInt
    val u = x - bd - 0.5; val o = 12 * b
    val as = c(o) + u * (c(o + 1) + u * c(o + 2)); val bs = c(o + 3) + u * (c(o + 4) + u * c(o + 5))
    val ac = c(o + 6) + u * (c(o + 7) + u * c(o + 8)); val bc = c(o + 9) + u * (c(o + 10) + u * c(o + 11))
    out(0) = as * sn + bs * cs; out(1) = as * cs - bs * sn
    out(2) = ac * sn + bc * cs; out(3) = ac * cs - bc * sn
  }
}

/** How the spec's low-passes pass harmonic k of the fringe beside its fundamental. A harmonic's columns are made from
  * the fitted fundamental (`SignalEngine.termGen`): its gain at f and k times its lag at f. A first-order low-pass
  * gives the harmonic its gain and lag at k f: per channel the factor F = H(k f) e^(i k lag(f)) / |H(f)|, for
  * H(f) = 1 / (1 + i u), u = f / fc, F = (1 + i u)^k / ((1 + u^2)^((k - 1) / 2) (1 + i k u)), each cut-off on the
  * channel in turn. Another generator's 0.4 % third harmonic behind low-passes at 700 and 550 kHz, on a ramp to 350
  * kHz, fell to half its size at the top speed and turned by 35 degrees: it did not replicate on the halves and was
  * left unexplained with the cut-offs. `apply` turns a harmonic's sin and cos parts by F, read from a table over the
  * fringe frequencies [lo, hi] (linear between `bins` points).
  */
private[explain] final class HarmonicResponse(sp: ModelSpec, k: Int, lo: Double, hi: Double, bins: Int = 4096) {
  private val cuts = Array(Seq("both", "sin"), Seq("both", "cos")).map(_.flatMap(sp.bw.get).filter(fc => fc > 0 && !fc.isInfinite))
  private val width = if (hi > lo) (hi - lo) / bins else 0.0
  private val inv = if (width > 0) 1 / width else 0.0
  // per channel, F's real and imaginary parts at lo + j width
  private val tab = Array.tabulate(2) { ch =>
    val t = new Array[Double](2 * (bins + 1))
    for (j <- 0 to bins) { val f = lo + j * width; val (re, im) = factor(f, cuts(ch)); t(2 * j) = re; t(2 * j + 1) = im }
    t
  }
  private def factor(f: Double, fcs: Seq[Double]): (Double, Double) = fcs.foldLeft((1.0, 0.0)) { case ((ar, ai), fc) =>
    val u = f / fc
    var pr = 1.0; var pi = 0.0; var j = 0
    while (j < k) { val r = pr - pi * u; pi = pi + pr * u; pr = r; j += 1 } // (1 + i u)^k
    val d = math.pow(1 + u * u, 0.5 * (k - 1)); val qr = 1.0; val qi = k * u; val qq = qr * qr + qi * qi
    // (pr + i pi) / (d (1 + i k u))
    val fr = (pr * qr + pi * qi) / (qq * d); val fi = (pi * qr - pr * qi) / (qq * d)
    (ar * fr - ai * fi, ar * fi + ai * fr)
  }
  /** Channel ch's harmonic parts at fringe frequency f, a sin(k a) in o1(q) and a cos(k a) in o2(q), turned by F. */
  @inline def apply(f: Double, ch: Int, o1: Array[Double], o2: Array[Double], q: Int): Unit = if (cuts(ch).nonEmpty) {
    val x = if (width > 0) math.max(0.0, math.min(bins.toDouble, (f - lo) * inv)) else 0.0
    val j = math.min(bins - 1, x.toInt); val w = x - j; val t = tab(ch)
    val fr = t(2 * j) + w * (t(2 * j + 2) - t(2 * j)); val fi = t(2 * j + 1) + w * (t(2 * j + 3) - t(2 * j + 1))
    val s = o1(q); val c = o2(q)
    o1(q) = s * fr + c * fi; o2(q) = c * fr - s * fi
  }
}

private[explain] object ChannelResponse {
  // sin and cos by their series for |x| <= 1/4 (the skew's turn at the fringe frequencies; the next term is below
  // 3e-18 of the value): a fraction of the library's cost, called for every sample in a profile
  @inline def sinSmall(x: Double): Double = {
    val y = x * x
    x * (1 - y / 6 * (1 - y / 20 * (1 - y / 42 * (1 - y / 72 * (1 - y / 110 * (1 - y / 156))))))
  }
  @inline def cosSmall(x: Double): Double = {
    val y = x * x
    1 - y / 2 * (1 - y / 12 * (1 - y / 30 * (1 - y / 56 * (1 - y / 90 * (1 - y / 132 * (1 - y / 182))))))
  }
}
