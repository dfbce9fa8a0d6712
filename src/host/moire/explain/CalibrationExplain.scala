package moire.explain

import moire.recording.Calibration

/** explain for turntable calibration data: the default model is an offset plus harmonics 1..K of the turn
  * (K from metadata `harmonics`, default 2); candidates are `harmonic_order` (one more order) and `reversal`
  * (error(cw) - error(ccw)). Same BIC rule as for signals.
  */
object CalibrationExplain {
  final case class Result(report: Report, cal: Calibration, before: Array[Double], after: Array[Double], fit: Array[Double],
                          steps: Seq[(Finding, Array[Double], Array[Double])])

  private sealed trait T
  private final case class H(k: Int) extends T
  private case object Rev extends T

  def run(file: String, c: Calibration): Result = {
    val t0 = System.nanoTime()
    val n = c.length; val a = c.angleDeg.map(math.toRadians); val y = c.errorArcsec
    val kMax = math.max(1, math.min(128, (n - 1) / 2 - 1))
    // the default model's harmonic count: what the data can support, or an error saying so
    val k0 = c.meta.get("harmonics").map(h => moire.numbers.Decimal.int(h).filter(k => k >= 0 && k <= kMax).getOrElse(throw new ExplainError(
      s"$file: metadata harmonics '$h' must be an integer in 0..$kMax: $n points support at most $kMax harmonics besides the candidates"))).getOrElse(math.min(2, kMax))
    def cols(t: T): IndexedSeq[Col] = t match {
      case H(k) => IndexedSeq(Col(a.map(x => math.cos(k * x)), null), Col(a.map(x => math.sin(k * x)), null))
      case Rev => IndexedSeq(Col(c.direction.map(_ * 0.5), null))
    }
    val none = new Array[Double](0)
    var terms: Vector[T] = (1 to math.min(k0, kMax)).map(H).toVector
    def design(ts: Seq[T]) = Col(Array.fill(n)(1.0), null) +: ts.flatMap(cols).toIndexedSeq
    def fit(ts: Seq[T]): (LinSol, Array[Double]) = {
      val d = design(ts); val s = LinearFit.solve(d, y, none)
      val p = LinearFit.combine(d, s.beta, sinCh = true, n)
      (s, y.indices.map(i => y(i) - p(i)).toArray)
    }
    def m2ll(r: Array[Double]) = { val v = math.max(1e-30, r.map(x => x * x).sum / n); n * (math.log(2 * math.Pi * v) + 1) }
    def k(ts: Seq[T]) = 2 + ts.map { case H(_) => 2; case Rev => 1 }.sum
    def bic(ts: Seq[T], r: Array[Double]) = m2ll(r) + k(ts) * math.log(n.toDouble)
    def rms(r: Array[Double]) = math.sqrt(r.map(x => x * x).sum / n)

    var (sol, res) = fit(terms)
    val before = res.clone(); val baseRms = rms(res); val baseBic = bic(terms, res)
    val located = locate(c, res, a, kMax)
    val steps = Seq.newBuilder[(Finding, Array[Double], Array[Double])]
    var done = false
    while (!done) {
      val cands = ((1 to kMax).map(H).filterNot(terms.contains) ++ (if (c.hasDirection && !terms.contains(Rev)) Seq(Rev) else Nil))
        .map { t => val (s, r) = fit(terms :+ t); (t, s, r) }.filter(_._2.ok)
      val cur = bic(terms, res)
      val best = if (cands.isEmpty) None else Some(cands.maxBy { case (t, _, r) => cur - bic(terms :+ t, r) })
      best match {
        case Some((t, s, r)) if cur - bic(terms :+ t, r) > SignalExplain.Threshold =>
          val d = cur - bic(terms :+ t, r); val rb = res.clone()
          terms = terms :+ t; sol = s; res = r
          steps += ((Finding(name(t), "both", "", Map.empty, Map.empty, d, rms(rb), rms(r), ""), rb, r.clone()))
        case _ => done = true
      }
    }
    // parameters from the final fit
    val v = res.map(x => x * x).sum / math.max(1, n - k(terms) + 1)
    var at = 1; val index = terms.map { t => val i = at; at += cols(t).size; t -> i }.toMap
    // accepted terms follow the default harmonics in the order they were accepted
    val fins = steps.result().zip(terms.drop(math.min(k0, kMax))).map { case ((f, rb, ra), t) =>
      val i = index(t); def sd(j: Int) = math.sqrt(math.max(0, sol.inv(j)(j)) * v)
      val g = t match {
        case H(kk) =>
          val ac = sol.beta(i); val as = sol.beta(i + 1); val amp = math.hypot(ac, as)
          val su = if (amp > 0) math.sqrt(ac * ac * sd(i) * sd(i) + as * as * sd(i + 1) * sd(i + 1)) / amp else sd(i)
          val ph = math.toDegrees(math.atan2(-as, ac))
          f.copy(params = Map("order" -> kk, "amplitude_arcsec" -> amp, "phase_deg" -> ph),
            unc = Map("order" -> 0, "amplitude_arcsec" -> su, "phase_deg" -> (if (amp > 0) math.toDegrees(su / amp) else 180)),
            where = s"against angle: harmonic $kk of the turn",
            summary = f"the error function needs harmonic $kk: ${amp}%.3f arcsec amplitude (error = ... + A cos($kk angle + phase))")
        case Rev =>
          f.copy(params = Map("reversal_arcsec" -> sol.beta(i)), unc = Map("reversal_arcsec" -> sd(i)), where = "by direction",
            summary = f"direction-dependent error: cw reads ${sol.beta(i)}%.3f arcsec more than ccw (backlash or hysteresis)")
        case _ => f
      }
      (g, rb, ra)
    }
    val unexplained = locate(c, res, a, kMax).filter(_.significant)
    val baseParams = Map("offset_arcsec" -> sol.beta(0), "default_harmonics" -> math.min(k0, kMax).toDouble, "noise_arcsec" -> rms(res))
    val fitted = y.indices.map(i => y(i) - res(i)).toArray
    val report = Report(file, "calibration", baseRms, baseBic, baseParams, located, fins.map(_._1), unexplained, rms(res), bic(terms, res), n,
      (System.nanoTime() - t0) / 1e9, c.notes)
    Result(report, c, before, res, fitted, fins)
  }
  private def name(t: T) = t match { case H(_) => effects.HarmonicOrder.name; case Rev => effects.Reversal.name }

  /** Residual against angle (bins), its harmonic amplitudes, and the mean difference between directions. */
  def locate(c: Calibration, r: Array[Double], a: Array[Double], kMax: Int): Seq[Located] = {
    val n = r.length; val sd = math.sqrt(r.map(x => x * x).sum / n)
    val amps = (1 to kMax).map { k =>
      val cc = r.indices.map(i => r(i) * math.cos(k * a(i))).sum * 2 / n; val ss = r.indices.map(i => r(i) * math.sin(k * a(i))).sum * 2 / n
      k -> math.hypot(cc, ss)
    }
    val (kb, ab) = amps.maxBy(_._2)
    // amplitude of a harmonic of pure noise: Rayleigh with sigma = sd * sqrt(2/n); significant beyond ~5.5 sigma
    val noiseAmp = sd * math.sqrt(2.0 / n)
    // a residual of exactly 0 (a flat table) has no harmonic and no noise: a ratio of 0, not 0 / 0
    def over(a: Double, b: Double) = if (b > 0) a / b else 0.0
    val out = Seq.newBuilder[Located]
    out += Located("against angle (harmonics of the turn)", f"largest residual harmonic: order $kb, $ab%.3f arcsec (${over(ab, noiseAmp)}%.1f x its noise level)",
      Map("order" -> kb, "amplitude_arcsec" -> ab, "ratio" -> over(ab, noiseAmp)), over(ab, noiseAmp) > math.sqrt(2 * math.log(kMax.toDouble) + 30))
    if (c.hasDirection) {
      val cw = r.indices.filter(c.direction(_) > 0).map(r); val ccw = r.indices.filter(c.direction(_) < 0).map(r)
      if (cw.nonEmpty && ccw.nonEmpty) {
        val d = cw.sum / cw.size - ccw.sum / ccw.size; val se = sd * math.sqrt(1.0 / cw.size + 1.0 / ccw.size)
        out += Located("by direction", f"cw minus ccw mean residual $d%.3f arcsec (${over(d, se)}%.1f standard errors)",
          Map("difference_arcsec" -> d, "z" -> over(d, se)), math.abs(over(d, se)) > 6)
      }
    }
    out.result()
  }

  /** The three plots, drawn; nothing is written (the caller writes them with the report, as one). */
  def plots(r: Result, stem: String): Seq[Plots.Drawn] = {
    val a = r.cal.angleDeg; val order = a.indices.sortBy(a(_)).toArray
    def sorted(x: Array[Double]) = order.map(x)
    val c1 = Plots.chart(s"$stem: calibration error and final fit", "angle (degree)", "error (arcsec)")
    Plots.line(c1, "measured", sorted(a), sorted(r.cal.errorArcsec)); Plots.line(c1, "final fit", sorted(a), sorted(r.fit))
    val c2 = Plots.chart(s"$stem: residual before and after", "angle (degree)", "residual (arcsec)")
    Plots.line(c2, "default model", sorted(a), sorted(r.before)); Plots.line(c2, "final model", sorted(a), sorted(r.after))
    val kMax = math.max(1, math.min(128, (a.length - 1) / 2 - 1)); val rad = a.map(math.toRadians)
    def amps(x: Array[Double]) = (1 to kMax).map { k =>
      math.hypot(x.indices.map(i => x(i) * math.cos(k * rad(i))).sum, x.indices.map(i => x(i) * math.sin(k * rad(i))).sum) * 2 / x.length }.toArray
    val c3 = Plots.chart(s"$stem: residual harmonics of the turn", "order", "amplitude (arcsec)")
    val ks = (1 to kMax).map(_.toDouble).toArray
    Plots.line(c3, "default model", ks, amps(r.before)); Plots.line(c3, "final model", ks, amps(r.after))
    Seq(Plots.draw(c1, s"${stem}_fit.png"), Plots.draw(c2, s"${stem}_residual_angle.png"), Plots.draw(c3, s"${stem}_residual_spectrum.png"))
  }
}
