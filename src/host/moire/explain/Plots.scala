package moire.explain

import org.knowm.xchart.{BitmapEncoder, XYChart, XYChartBuilder}
import org.knowm.xchart.BitmapEncoder.BitmapFormat
import org.knowm.xchart.style.markers.SeriesMarkers

/** PNG plots of an explained recording: residual before/after against time, phase and frequency,
  * and one plot per finding showing the structure it removed against its natural axis.
  */
object Plots {
  System.setProperty("java.awt.headless", "true")

  /** The thread a record's plots are drawn on, beside its fit. */
  lazy val Pool: java.util.concurrent.ExecutorService = java.util.concurrent.Executors.newCachedThreadPool { r =>
    val t = new Thread(r, "moire-plots"); t.setDaemon(true); t
  }

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
  /** A plot drawn and encoded, not yet written: its file's name and its PNG bytes. */
  type Drawn = (String, Array[Byte])

  /** The chart as PNG under `name`, its axes at round values first (unless the chart set its own). */
  def draw(c: XYChart, name: String): Drawn = {
    if (c.getStyler.getXAxisMin == null) Axes.round(c)
    name -> Laps("plots: draw and encode")(BitmapEncoder.getBitmapBytes(c, BitmapFormat.PNG))
  }

  /** The plots' writes into `dir`, for `SafeWrite.made` to write as one (all of them, or none when a write fails). */
  def writes(dir: os.Path, plots: Seq[Drawn]): Seq[(os.Path, os.Path => Unit)] = plots.map { case (n, b) => (dir / n) -> ((t: os.Path) => os.write(t, b)) }

  /** Whether `name` is one of the plots `signals` makes for the record `stem` (the record `rec` only, not `rec_2`). */
  def ofStem(stem: String)(name: String): Boolean = name.startsWith(stem + "_") && {
    val rest = name.drop(stem.length + 1)
    Fixed.contains(rest) || effects.Effects.all.exists(f => rest.matches(s"effect_[0-9]+_${java.util.regex.Pattern.quote(f.name)}\\.png"))
  }
  // the names of the plots every record gets (after its stem and "_"), and each finding's (`effect_K_NAME.png`)
  private val ResidualTime = "residual_time.png"; private val ResidualPhase = "residual_phase.png"
  private val ResidualSpectrum = "residual_spectrum.png"; private val LissajousBefore = "lissajous_before.png"
  private val LissajousAfter = "lissajous_after.png"; private val InterpolationErr = "interpolation_error.png"
  private val Fixed = Set(ResidualTime, ResidualPhase, ResidualSpectrum, LissajousBefore, LissajousAfter, InterpolationErr)

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

  /** The engine's values at the snapshots' points (sample j * stride for point j), each gathered in one pass when a
    * plot first needs it: a long record's plots read compact arrays, not the engine's at a stride (a cache miss per
    * point on arrays of 160 MB at 20 M samples, for each plot and each curve; about 7 s of CPU then).
    */
  final class Points(e: SignalEngine, val stride: Int) {
    val size: Int = (e.n + stride - 1) / stride
    // on the asking thread (the plots run side by side on the pool: a lazy value's lock held across work on all cores
    // could hold the pool's only worker on a 2-core machine; see `Candidates.binned`)
    private def gather(f: Int => Double): Array[Double] = {
      val out = new Array[Double](size); var j = 0
      while (j < size) { out(j) = f(j * stride); j += 1 }
      out
    }
    /** Fringe phase in degrees (0 to 360), position from the start (fringe periods), |fringe frequency| (Hz). */
    lazy val fringeDeg: Array[Double] = gather { i => val p = e.phase(i); 360 * (p - math.floor(p)) }
    lazy val position: Array[Double] = { val p0 = e.phase(0); gather(i => e.phase(i) - p0) }
    lazy val absFreq: Array[Double] = gather(i => math.abs(e.freq(i)))
    /** The fitted fundamental (u) and its derivative by the phase (v) per channel, the prediction per channel. */
    lazy val us: Array[Double] = gather(e.us); lazy val vs: Array[Double] = gather(e.vs)
    lazy val uc: Array[Double] = gather(e.uc); lazy val vc: Array[Double] = gather(e.vc)
    lazy val predS: Array[Double] = gather(e.predSAt); lazy val predC: Array[Double] = gather(e.predCAt)
  }

  /** The record's plots, drawn side by side on all cores; nothing is written (the caller writes them as one). */
  def signals(r: SignalExplain.Result, stem: String, ie: InterpolationError): Seq[Drawn] = {
    val e = r.engine; val n = e.n; val lsb = e.lsb
    val after = Snapshot.of("final model", e.resS, e.resC)
    val snaps = Seq(r.before, after)
    // every snapshot is of the record's length: one stride, one set of points
    val pts = new Points(e, after.stride)
    // each plot drawn on its own: side by side on all cores, listed in this order
    val plots = Seq.newBuilder[() => Drawn]
    // time
    plots += { () =>
      val ct = chart(s"$stem: residual rms against time", "time (s)", "residual rms (LSB)")
      for (s <- snaps; (res, ch) <- Seq((s.resS, "sin"), (s.resC, "cos"))) {
        val (x, y) = binned(j => j * s.stride / e.fs, j => res(j) / lsb, s.size, 0, n / e.fs, 64, rms = true); line(ct, s"$ch, ${s.label}", x, y)
      }
      draw(ct, s"${stem}_$ResidualTime")
    }
    // fringe phase
    plots += { () =>
      val cp = chart(s"$stem: mean residual against fringe phase", "fringe phase (degree)", "mean residual (LSB)")
      for (s <- snaps; (res, ch) <- Seq((s.resS, "sin"), (s.resC, "cos"))) {
        val (x, y) = binned(pts.fringeDeg(_), j => res(j) / lsb, s.size, 0, 360, 72); line(cp, s"$ch, ${s.label}", x, y)
      }
      draw(cp, s"${stem}_$ResidualPhase")
    }
    // spectrum
    plots += (() => spectrum(s"$stem: residual spectrum", snaps, e, s"${stem}_$ResidualSpectrum"))
    // effects
    for (((f, b, a), k) <- r.steps.zipWithIndex) plots += (() => effect(f, b, a, e, pts, s"${stem}_effect_${k + 1}_${f.effect}.png", stem))
    // the Lissajous figure before and after the Heydemann correction, the interpolation error
    plots += (() => draw(LissajousPlot.before(s"$stem: Lissajous figure", e.yc, e.ys, ie.ellipse), s"${stem}_$LissajousBefore"))
    ie.ellipse.foreach(el => plots += (() => draw(LissajousPlot.after(s"$stem: Lissajous figure after correction", e.yc, e.ys, el), s"${stem}_$LissajousAfter")))
    plots += (() => draw(InterpolationPlot.chart(s"$stem: interpolation error", ie), s"${stem}_$InterpolationErr"))
    val todo = plots.result().toArray
    val out = new Array[Drawn](todo.length)
    // every plot runs to its end; the first failure is thrown after
    val failed = new Array[Throwable](todo.length)
    java.util.stream.IntStream.range(0, todo.length).parallel().forEach(k => try out(k) = Laps("plots: each")(todo(k)()) catch { case x: Throwable => failed(k) = x })
    failed.find(_ != null).foreach(x => throw x)
    out.toSeq
  }

  def spectrum(title: String, snaps: Seq[Snapshot], e: SignalEngine, name: String): Drawn = {
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
    draw(c, name)
  }

  private def effect(f: Finding, b: Snapshot, a: Snapshot, e: SignalEngine, pts: Points, name: String, stem: String): Drawn = {
    val lsb = e.lsb
    // the speed range over the points, made only for the panels against speed
    lazy val (fLo, fHi) = { val (lo, hi) = Doubles.range(pts.size)(pts.absFreq(_)); (lo, hi + 1e-9) }
    def phaseDev(s: Snapshot, u: Array[Double], v: Array[Double], res: Snapshot => Array[Double]) = {
      // per speed bin: phase (degree) = sum r v / sum v^2 ; amplitude (%) = sum r u / sum u^2
      val bins = 24; val pv = new Array[Double](bins); val vv = new Array[Double](bins); val pu = new Array[Double](bins); val uu = new Array[Double](bins)
      val r = res(s); val fa = pts.absFreq; var j = 0
      while (j < s.size) {
        val k = math.min(bins - 1, ((fa(j) - fLo) / (fHi - fLo) * bins).toInt)
        pv(k) += r(j) * v(j); vv(k) += v(j) * v(j); pu(k) += r(j) * u(j); uu(k) += u(j) * u(j); j += 1
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
          val (x, ps, as) = phaseDev(s, pts.us, pts.vs, _.resS); val (_, pc, ac) = phaseDev(s, pts.uc, pts.vc, _.resC)
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
        draw(c, name)
      case effects.PlotKind.Slope =>
        val c = chart(title, "|signal slope| (full scale per microsecond)", "residual rms (LSB)")
        // each channel's slope against time (as `SignalEngine.slopes`)
        def ds(j: Int) = math.abs(pts.vs(j) * 2 * math.Pi * pts.absFreq(j)); def dc(j: Int) = math.abs(pts.vc(j) * 2 * math.Pi * pts.absFreq(j))
        val hi = Doubles.range(pts.size)(j => math.max(ds(j), dc(j)))._2 * 1e-6 + 1e-12
        for (s <- Seq(b, a)) {
          val (x, y) = binned(j => ds(j) * 1e-6, j => s.resS(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"sin, ${s.label}", x, y)
          val (x2, y2) = binned(j => dc(j) * 1e-6, j => s.resC(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"cos, ${s.label}", x2, y2)
        }
        draw(c, name)
      case kind @ (effects.PlotKind.Time | effects.PlotKind.Position) =>
        // the amplitude left in the residual (sum r u / sum u^2 per bin), against time or the position along the travel
        val (xf, xl): (Int => Double, String) =
          if (kind == effects.PlotKind.Position) (pts.position(_), "position from the start (fringe periods)")
          else (j => j.toDouble * pts.stride / e.fs, "time (s)")
        // (the time's range is the record's; the position's, over the points)
        val (lo, hi0) = if (kind == effects.PlotKind.Position) Doubles.range(pts.size)(xf) else (0.0, (e.n - 1) / e.fs); val hi = hi0 + 1e-12
        val c = chart(title, xl, "amplitude left in the residual (%)")
        for (s <- Seq(b, a); (r, u, ch) <- Seq[(Array[Double], Array[Double], String)]((s.resS, pts.us, "sin"), (s.resC, pts.uc, "cos"))) {
          val (x, num) = binned(xf, j => r(j) * u(j), s.size, lo, hi, 48); val (_, den) = binned(xf, j => u(j) * u(j), s.size, lo, hi, 48)
          line(c, s"$ch, ${s.label}", x, num.zip(den).map { case (p, q) => 100 * p / q })
        }
        draw(c, name)
      case effects.PlotKind.MechanicalAngle =>
        val l = e.rec.linesPerRev.getOrElse(1.0)
        val c = chart(title, "mechanical angle (degree)", "amplitude left in the residual (%)")
        val p0 = e.phase(0)
        for (s <- Seq(b, a)) {
          val w = (j: Int) => pts.us(j) * pts.us(j) + pts.uc(j) * pts.uc(j)
          val ang = (j: Int) => { val m = (pts.position(j) + p0) / l; 360 * (m - math.floor(m)) }
          val (x, num) = binned(ang, j => s.resS(j) * pts.us(j) + s.resC(j) * pts.uc(j), s.size, 0, 360, 36)
          val (_, den) = binned(ang, w, s.size, 0, 360, 36)
          line(c, s.label, x, num.zip(den).map { case (p, q) => 100 * p / q })
        }
        draw(c, name)
      case effects.PlotKind.Level =>
        val c = chart(title, "predicted value (full scale)", "mean residual (LSB)")
        for (s <- Seq(b, a); (r, p, ch) <- Seq[(Array[Double], Array[Double], String)]((s.resS, pts.predS, "sin"), (s.resC, pts.predC, "cos"))) {
          val (x, y) = binned(p(_), j => r(j) / lsb, s.size, -1, 1, 128); line(c, s"$ch, ${s.label}", x, y)
        }
        draw(c, name)
      case effects.PlotKind.SignalValue =>
        val c = chart(title, "|signal value less its offset| (full scale)", "residual rms (LSB)")
        val hi = Doubles.range(pts.size)(j => math.max(math.abs(pts.us(j)), math.abs(pts.uc(j))))._2 + 1e-12
        for (s <- Seq(b, a)) {
          val (x, y) = binned(j => math.abs(pts.us(j)), j => s.resS(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"sin, ${s.label}", x, y)
          val (x2, y2) = binned(j => math.abs(pts.uc(j)), j => s.resC(j) / lsb, s.size, 0, hi, 24, rms = true); line(c, s"cos, ${s.label}", x2, y2)
        }
        // the noise the finding predicts: its white part and its share growing with the value
        val (r, w) = (f.params.getOrElse("intensity_noise_rel", 0.0), f.params.getOrElse("white_noise_fs", 0.0))
        val xs = Array.tabulate(25)(k => hi * k / 24)
        line(c, "fitted noise", xs, xs.map(x => math.sqrt(w * w + r * r * x * x) / lsb))
        draw(c, name)
      case effects.PlotKind.Spectrum => spectrum(title, Seq(b, a), e, name)
      case _ =>
        val c = chart(title, "fringe phase (degree)", "mean residual (LSB)")
        for (s <- Seq(b, a); (r, ch) <- Seq((s.resS, "sin"), (s.resC, "cos")) if f.channel == "both" || f.channel == ch) {
          val (x, y) = binned(pts.fringeDeg(_), j => r(j) / lsb, s.size, 0, 360, 72); line(c, s"$ch, ${s.label}", x, y)
        }
        draw(c, name)
    }
  }
}
