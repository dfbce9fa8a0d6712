package moire.calibration

import moire.harmonic._

import org.knowm.xchart.{BitmapEncoder, XYChartBuilder, XYSeries}
import org.knowm.xchart.style.markers.SeriesMarkers

/** PNG plot of calibration data, the harmonic fit and the residual (XChart, headless). */
object CalibrationPlot {
  /** One direction's data and fit ("" when the file has no direction column). */
  final case class Curve(direction: String, points: Seq[CalPoint], fit: HarmonicFitResult)

  def write(path: os.Path, title: String, curves: Seq[Curve]): Unit = moire.files.SafeWrite(path)(png(title, curves))

  /** Points per series drawn as they are; a finer table is drawn as each of `Bins` angle bins' lowest and highest
    * point (what 1000 pixels can show: a 0.001 degree table's 360,000 markers took minutes to draw).
    */
  val Bins = 1000
  def thin(x: Array[Double], y: Array[Double]): (Array[Double], Array[Double]) = if (x.length <= 2 * Bins) (x, y) else {
    val lo = x.min; val span = math.max(1e-12, x.max - lo)
    val keep = scala.collection.mutable.ArrayBuffer.empty[Int]
    x.indices.groupBy(i => math.min(Bins - 1, ((x(i) - lo) / span * Bins).toInt)).toSeq.sortBy(_._1).foreach { case (_, is) =>
      val a = is.minBy(y(_)); val b = is.maxBy(y(_)); keep ++= Seq(a, b).distinct.sorted
    }
    (keep.map(x(_)).toArray, keep.map(y(_)).toArray)
  }

  /** The plot, as a writer of a PNG file at the path it is given. */
  def png(title: String, curves: Seq[Curve]): os.Path => Unit = {
    System.setProperty("java.awt.headless", "true")
    val chart = new XYChartBuilder().width(1000).height(600).title(title)
      .xAxisTitle("angle (deg)").yAxisTitle("position error (arcsec)").build()
    chart.getStyler.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS)
    chart.getStyler.setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Horizontal)
    val grid = (0 to 720).map(_ * 0.5)
    for (c <- curves) {
      val tag = if (c.direction.isEmpty) "" else s" ${c.direction}"
      val pts = c.points.sortBy(_.angleDeg)
      val (dx, dy) = thin(pts.map(_.angleDeg).toArray, pts.map(_.errorArcsec).toArray)
      val d = chart.addSeries(s"data$tag", dx, dy)
      d.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter)
      val f = chart.addSeries(s"fit$tag (${c.fit.harmonics.map(_.order).mkString(",")})", grid.toArray, grid.map(c.fit(_)).toArray)
      f.setMarker(SeriesMarkers.NONE)
      val byLine = c.points.zip(c.fit.residuals).sortBy(_._1.angleDeg)
      val (rx, ry) = thin(byLine.map(_._1.angleDeg).toArray, byLine.map(_._2).toArray)
      val r = chart.addSeries(s"residual$tag", rx, ry)
      r.setMarker(SeriesMarkers.DIAMOND)
    }
    t => { val o = new java.io.FileOutputStream(t.toIO); try BitmapEncoder.saveBitmap(chart, o, BitmapEncoder.BitmapFormat.PNG) finally o.close() }
  }
}
