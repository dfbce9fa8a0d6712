package moire.explain

import org.knowm.xchart.{BitmapEncoder, XYChart, XYChartBuilder}
import org.knowm.xchart.BitmapEncoder.BitmapFormat
import org.knowm.xchart.style.markers.SeriesMarkers

/** PNG plots of an explained recording: residual before/after against time, phase and frequency,
  * and one plot per finding showing the structure it removed against its natural axis.
  */
object Plots {
  System.setProperty("java.awt.headless", "true")

  /** Draws a small chart into memory on a daemon thread: the library's first chart costs about half a second of class
    * loading and font set-up, which then overlaps the fit instead of following it.
    */
  def warmUp(): Unit = {
    val t = new Thread(() => try {
      val c = chart("warm-up", "x", "y"); line(c, "y", Array(0.0, 1.0), Array(0.0, 1.0))
      BitmapEncoder.getBitmapBytes(c, BitmapFormat.PNG)
    } catch { case _: Throwable => () }, "moire-plot-warm-up")
    t.setDaemon(true); t.setPriority(Thread.MIN_PRIORITY); t.start()
  }

  def chart(title: String, x: String, y: String): XYChart = {
    val c = new XYChartBuilder().width(900).height(500).title(title).xAxisTitle(x).yAxisTitle(y).build()
    // the legend below the plot: inside, it hides the curves it names
    c.getStyler.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS)
    c.getStyler.setChartBackgroundColor(java.awt.Color.WHITE)
    c.getStyler.setXAxisDecimalPattern("0.###"); c.getStyler.setYAxisDecimalPattern("0.####")
    c
  }
  def line(c: XYChart, name: String, xs: Array[Double], ys: Array[Double]): Unit = {
    val ok = xs.indices.filter(i => !xs(i).isNaN && !ys(i).isNaN && !ys(i).isInfinite)
    if (ok.nonEmpty) c.addSeries(name, ok.map(xs).toArray, ok.map(ys).toArray).setMarker(SeriesMarkers.NONE)
  }
  /** Writes the chart as PNG, its axes at round values first (unless the chart set its own). */
  def save(c: XYChart, path: os.Path): os.Path = {
    if (c.getStyler.getXAxisMin == null) Axes.round(c)
    Laps("plots: draw and encode")(moire.files.SafeWrite(path)(t => { val o = new java.io.FileOutputStream(t.toIO); try BitmapEncoder.saveBitmap(c, o, BitmapFormat.PNG) finally o.close() }))
    path
  }

  /** Mean of y per bin of x (bins over [lo, hi)). */
  def binned(x: Int => Double, y: Int => Double, n: Int, lo: Double, hi: Double, bins: Int, rms: Boolean = false): (Array[Double], Array[Double]) = {
    val s = new Array[Double](bins); val c = new Array[Int](bins); var i = 0
    while (i < n) {
      val xv = x(i); val b = math.min(bins - 1, math.max(0, ((xv - lo) / (hi - lo) * bins).toInt))
      val v = y(i); s(b) += (if (rms) v * v else v); c(b) += 1; i += 1
    }
    (Array.tabulate(bins)(b => lo + (b + 0.5) * (hi - lo) / bins),
      Array.tabulate(bins)(b => if (c(b) == 0) Double.NaN else if (rms) math.sqrt(s(b) / c(b)) else s(b) / c(b)))
  }

  /** Sample i's fringe phase in degrees (0 to 360). */
  private def fringeDeg(e: SignalEngine, i: Int): Double = 360 * (e.phase(i) - math.floor(e.phase(i)))

  def signals(r: SignalExplain.Result, dir: os.Path, stem: String, ie: InterpolationError): Seq[os.Path] = {
    val e = r.engine; val n = e.n; val lsb = e.lsb
    val after = Snapshot.of("final model", e.resS, e.resC)
    val snaps = Seq(r.before, after)
    // each plot made and written on its own: side by side on all cores, listed in this order
    val plots = Seq.newBuilder[() => os.Path]
    // time
    plots += { () =>
      val ct = chart(s"$stem: residual rms against time", "time (s)", "residual rms (LSB)")
      for (s <- snaps; (res, ch) <- Seq((s.resS, "sin"), (s.resC, "cos"))) {
        val (x, y) = binned(j => j * s.stride / e.fs, j => res(j) / lsb, s.size, 0, n / e.fs, 64, rms = true); line(ct, s"$ch, ${s.label}", x, y)
      }
      save(ct, dir / s"${stem}_residual_time.png")
    }
    // fringe phase
    plots += { () =>
      val cp = chart(s"$stem: mean residual against fringe phase", "fringe phase (degree)", "mean residual (LSB)")
      for (s <- snaps; (res, ch) <- Seq((s.resS, "sin"), (s.resC, "cos"))) {
        val (x, y) = binned(j => fringeDeg(e, j * s.stride), j => res(j) / lsb, s.size, 0, 360, 72); line(cp, s"$ch, ${s.label}", x, y)
      }
      save(cp, dir / s"${stem}_residual_phase.png")
    }
    // spectrum
    plots += (() => spectrum(s"$stem: residual spectrum", snaps, e, dir / s"${stem}_residual_spectrum.png"))
    // effects
    for (((f, b, a), k) <- r.steps.zipWithIndex) plots += (() => effect(f, b, a, e, dir / s"${stem}_effect_${k + 1}_${f.effect}.png", stem))
    // the Lissajous figure before and after the Heydemann correction, the interpolation error
    plots += (() => save(LissajousPlot.before(s"$stem: Lissajous figure", e.yc, e.ys, ie.ellipse), dir / s"${stem}_lissajous_before.png"))
    ie.ellipse.foreach(el => plots += (() => save(LissajousPlot.after(s"$stem: Lissajous figure after correction", e.yc, e.ys, el), dir / s"${stem}_lissajous_after.png")))
    plots += (() => save(InterpolationPlot.chart(s"$stem: interpolation error", ie), dir / s"${stem}_interpolation_error.png"))
    val todo = plots.result().toArray
    val out = new Array[os.Path](todo.length)
    // every plot runs to its end (each cleans up after itself when its write fails); the first failure is thrown after
    val failed = new Array[Throwable](todo.length)
    java.util.stream.IntStream.range(0, todo.length).parallel().forEach(k => try out(k) = Laps("plots: each")(todo(k)()) catch { case x: Throwable => failed(k) = x })
    failed.find(_ != null).foreach(x => throw x)
    out.toSeq
  }

  def spectrum(title: String, snaps: Seq[Snapshot], e: SignalEngine, path: os.Path): os.Path = {
    val m = Integer.highestOneBit(math.min(e.n, 1 << 18)); val c = chart(title, "frequency (kHz)", "amplitude (dB LSB)")
    for (s <- snaps) {
      val pq = Fft.powerSum(s.headSin, s.headCos, m) // both channels' power by one FFT
      val g = math.max(1, pq.length / 1500)
      val xs = Doubles.tabulate(pq.length / g)(k => (k * g + g / 2) * e.fs / m / 1e3)
      val ys = Doubles.tabulate(pq.length / g) { k =>
        var mx = Double.NegativeInfinity; var j = k * g
        while (j < (k + 1) * g) { mx = math.max(mx, pq(j)); j += 1 }
        10 * math.log10(2 * mx / m.toDouble / m / (e.lsb * e.lsb) + 1e-30)
      }
      line(c, s.label, xs, ys)
    }
    save(c, path)
  }

  private def effect(f: Finding, b: Snapshot, a: Snapshot, e: SignalEngine, path: os.Path, stem: String): os.Path = {
    val n = e.n; val lsb = e.lsb; val fAbs = (i: Int) => math.abs(e.freq(i))
    // the speed range, made only for the panels against speed (a pass over the record)
    lazy val (fLo, fHi) = {
      var lo = Double.MaxValue; var hi = 0.0; var i = 0
      while (i < n) { val v = math.abs(e.freq(i)); lo = math.min(lo, v); hi = math.max(hi, v); i += 1 }
      (lo, hi + 1e-9)
    }
    def phaseDev(s: Snapshot, u: Int => Double, v: Int => Double, res: Snapshot => Array[Double]) = {
      // per speed bin: phase (degree) = sum r v / sum v^2 ; amplitude (%) = sum r u / sum u^2
      val bins = 24; val pv = new Array[Double](bins); val vv = new Array[Double](bins); val pu = new Array[Double](bins); val uu = new Array[Double](bins)
      val r = res(s); var j = 0
      while (j < s.size) {
        val i = j * s.stride; val k = math.min(bins - 1, ((fAbs(i) - fLo) / (fHi - fLo) * bins).toInt)
        pv(k) += r(j) * v(i); vv(k) += v(i) * v(i); pu(k) += r(j) * u(i); uu(k) += u(i) * u(i); j += 1
      }
      (Array.tabulate(bins)(k => (fLo + (k + 0.5) * (fHi - fLo) / bins) / 1e3),
        Array.tabulate(bins)(k => if (vv(k) > 0) math.toDegrees(pv(k) / vv(k)) else Double.NaN),
        Array.tabulate(bins)(k => if (uu(k) > 0) 100 * pu(k) / uu(k) else Double.NaN))
    }
    val title = s"$stem: ${f.effect} (${f.channel}), residual before and after"
    effects.Effects(f.effect).fold[effects.PlotKind](effects.PlotKind.FringePhase)(_.plot) match {
      case effects.PlotKind.Speed(phaseOnly) =>
        // phase on the left axis (degree), amplitudes on the right one (%)
        val c = chart(title, "fringe frequency (kHz)", "cos - sin phase left in the residual (degree)")
        for (s <- Seq(b, a)) {
          val (x, ps, as) = phaseDev(s, e.us(_), e.vs(_), _.resS); val (_, pc, ac) = phaseDev(s, e.uc(_), e.vc(_), _.resC)
          line(c, s"cos - sin phase (degree), ${s.label}", x, pc.zip(ps).map { case (p, q) => p - q })
          if (!phaseOnly) for ((ch, am) <- Seq("sin" -> as, "cos" -> ac)) {
            line(c, s"$ch amplitude (%), ${s.label}", x, am)
            Option(c.getSeriesMap.get(s"$ch amplitude (%), ${s.label}")).foreach(_.setYAxisGroup(1))
          }
        }
        if (!phaseOnly) {
          c.setYAxisGroupTitle(1, "amplitude left in the residual (%)")
          c.getStyler.setYAxisGroupPosition(1, org.knowm.xchart.style.Styler.YAxisPosition.Right)
        }
        save(c, path)
      case effects.PlotKind.Slope =>
        val c = chart(title, "|signal slope| (full scale per microsecond)", "residual rms (LSB)")
        // each channel's slope against time (as `SignalEngine.slopes`), read where it is needed
        def ds(i: Int) = math.abs(e.vs(i) * 2 * math.Pi * e.freq(i)); def dc(i: Int) = math.abs(e.vc(i) * 2 * math.Pi * e.freq(i))
        val hi = Doubles.range(n)(i => math.max(ds(i), dc(i)))._2 * 1e-6 + 1e-12
        for (s <- Seq(b, a)) {
          val (x, y) = binned(j => ds(j * s.stride) * 1e-6, j => s.resS(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"sin, ${s.label}", x, y)
          val (x2, y2) = binned(j => dc(j * s.stride) * 1e-6, j => s.resC(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"cos, ${s.label}", x2, y2)
        }
        save(c, path)
      case kind @ (effects.PlotKind.Time | effects.PlotKind.Position) =>
        // the amplitude left in the residual (sum r u / sum u^2 per bin), against time or the position along the travel
        val (xf, xl): (Int => Double, String) =
          if (kind == effects.PlotKind.Position) (i => e.phase(i) - e.phase(0), "position from the start (fringe periods)")
          else (i => i / e.fs, "time (s)")
        var lo = Double.MaxValue; var hi = -Double.MaxValue
        for (i <- 0 until n) { val v = xf(i); lo = math.min(lo, v); hi = math.max(hi, v) }
        hi += 1e-12
        val c = chart(title, xl, "amplitude left in the residual (%)")
        for (s <- Seq(b, a); (r, u, ch) <- Seq[(Array[Double], Int => Double, String)]((s.resS, e.us(_), "sin"), (s.resC, e.uc(_), "cos"))) {
          val st = s.stride
          val (x, num) = binned(j => xf(j * st), j => r(j) * u(j * st), s.size, lo, hi, 48); val (_, den) = binned(j => xf(j * st), j => u(j * st) * u(j * st), s.size, lo, hi, 48)
          line(c, s"$ch, ${s.label}", x, num.zip(den).map { case (p, q) => 100 * p / q })
        }
        save(c, path)
      case effects.PlotKind.MechanicalAngle =>
        val l = e.rec.linesPerRev.getOrElse(1.0)
        val c = chart(title, "mechanical angle (degree)", "amplitude left in the residual (%)")
        for (s <- Seq(b, a)) {
          val st = s.stride
          val w = (j: Int) => { val i = j * st; e.us(i) * e.us(i) + e.uc(i) * e.uc(i) }
          val ang = (j: Int) => { val m = e.phase(j * st) / l; 360 * (m - math.floor(m)) }
          val (x, num) = binned(ang, j => s.resS(j) * e.us(j * st) + s.resC(j) * e.uc(j * st), s.size, 0, 360, 36)
          val (_, den) = binned(ang, w, s.size, 0, 360, 36)
          line(c, s.label, x, num.zip(den).map { case (p, q) => 100 * p / q })
        }
        save(c, path)
      case effects.PlotKind.Level =>
        val c = chart(title, "predicted value (full scale)", "mean residual (LSB)")
        for (s <- Seq(b, a); (r, p, ch) <- Seq[(Array[Double], Int => Double, String)]((s.resS, e.predSAt(_), "sin"), (s.resC, e.predCAt(_), "cos"))) {
          val (x, y) = binned(j => p(j * s.stride), j => r(j) / lsb, s.size, -1, 1, 128); line(c, s"$ch, ${s.label}", x, y)
        }
        save(c, path)
      case effects.PlotKind.Spectrum => spectrum(title, Seq(b, a), e, path)
      case _ =>
        val c = chart(title, "fringe phase (degree)", "mean residual (LSB)")
        for (s <- Seq(b, a); (r, ch) <- Seq((s.resS, "sin"), (s.resC, "cos")) if f.channel == "both" || f.channel == ch) {
          val (x, y) = binned(j => fringeDeg(e, j * s.stride), j => r(j) / lsb, s.size, 0, 360, 72); line(c, s"$ch, ${s.label}", x, y)
        }
        save(c, path)
    }
  }
}
