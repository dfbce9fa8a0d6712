package moire.explain

import org.knowm.xchart.{XYChart, XYChartBuilder}
import org.knowm.xchart.XYSeries.XYSeriesRenderStyle
import org.knowm.xchart.style.markers.SeriesMarkers
import moire.lissajous.Ellipse

/** The Lissajous figure (cos channel across, sin up, full scale) with the fitted ellipse and the ideal circle; after
  * the Heydemann correction the points lie on the unit circle.
  */
object LissajousPlot {
  /** Points drawn at most (evenly spread over the record). */
  val MaxPoints = 4000

  private def square(title: String, x: String, y: String): XYChart = {
    val c = new XYChartBuilder().width(560).height(560).title(title).xAxisTitle(x).yAxisTitle(y).build()
    c.getStyler.setChartBackgroundColor(java.awt.Color.WHITE)
    c.getStyler.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS)
    c.getStyler.setXAxisDecimalPattern("0.###"); c.getStyler.setYAxisDecimalPattern("0.###")
    c
  }
  private def dots(c: XYChart, name: String, xs: Array[Double], ys: Array[Double]): Unit = {
    val s = c.addSeries(name, xs, ys); s.setXYSeriesRenderStyle(XYSeriesRenderStyle.Scatter); s.setMarker(SeriesMarkers.CIRCLE)
    c.getStyler.setMarkerSize(3)
  }
  private def curve(c: XYChart, name: String, pts: Seq[(Double, Double)]): Unit =
    c.addSeries(name, pts.map(_._1).toArray, pts.map(_._2).toArray).setMarker(SeriesMarkers.NONE)
  private def circle(r: Double) = (0 to 96).map(k => (r * math.cos(2 * math.Pi * k / 96), r * math.sin(2 * math.Pi * k / 96)))

  /** Before: the codes in full scale with the fitted ellipse and a centred circle of the mean amplitude. */
  def before(title: String, cos: Array[Double], sin: Array[Double], e: Option[Ellipse]): XYChart = {
    val c = square(title, "cos (full scale)", "sin (full scale)")
    val st = math.max(1, cos.length / MaxPoints)
    dots(c, "records", cos.indices.by(st).map(cos).toArray, cos.indices.by(st).map(sin).toArray)
    e.foreach { el =>
      curve(c, f"fitted ellipse (Heydemann): phase error ${el.phaseErrorDeg}%.2f degree, ratio ${el.ratio}%.4f", el.outline(192))
      curve(c, f"ideal circle, radius ${math.sqrt(el.ampSin * el.ampCos)}%.3f", circle(math.sqrt(el.ampSin * el.ampCos)))
    }
    Axes.square(c)
    c
  }

  /** After: the points corrected with the ellipse (unit radius) and the unit circle. */
  def after(title: String, cos: Array[Double], sin: Array[Double], el: Ellipse): XYChart = {
    val c = square(title, "cos, corrected (amplitude 1)", "sin, corrected (amplitude 1)")
    val st = math.max(1, cos.length / MaxPoints)
    val idx = cos.indices.by(st)
    val ph = idx.map(i => el.phase(cos(i), sin(i))).toArray
    val rr = idx.map { i => val cc = (cos(i) - el.offsetCos) / el.ampCos; val p = math.toRadians(el.phaseErrorDeg)
      val ss = ((sin(i) - el.offsetSin) / el.ampSin + cc * math.sin(p)) / math.cos(p); math.hypot(cc, ss) }.toArray
    dots(c, "records, corrected", ph.indices.map(k => rr(k) * math.cos(ph(k))).toArray, ph.indices.map(k => rr(k) * math.sin(ph(k))).toArray)
    curve(c, "unit circle", circle(1))
    Axes.square(c)
    c
  }
}
