package moire.cost

import org.knowm.xchart.{BitmapEncoder, XYChartBuilder, XYSeries}
import org.knowm.xchart.style.markers.SeriesMarkers

/** PNG: error bound (log scale) against logic cells, one series per variant, the Pareto front joined by a line. */
object ParetoPlot {
  def write(path: os.Path, function: String, rows: Seq[SweepRow]): Unit = {
    System.setProperty("java.awt.headless", "true")
    val unit = if (function == "sin") "full scale 1.0" else "rad"
    val chart = new XYChartBuilder().width(1000).height(650)
      .title(s"$function CORDIC: error bound against logic cells (yosys synth_intel, Cyclone IV E)")
      .xAxisTitle("logic cells (LUT cells + registers)").yAxisTitle(s"error bound ($unit)").build()
    val st = chart.getStyler
    st.setYAxisLogarithmic(true)
    st.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideS)
    st.setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Horizontal)
    val front = rows.filter(_.pareto).sortBy(_.logicCells)
    if (front.nonEmpty) {
      val f = chart.addSeries("Pareto front (cheapest for its accuracy)", front.map(_.logicCells.toDouble).toArray, front.map(_.errorBound).toArray)
      f.setMarker(SeriesMarkers.CIRCLE)
      f.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line)
    }
    for ((v, rs) <- rows.groupBy(_.variant).toSeq.sortBy(_._1)) {
      val s = chart.addSeries(v, rs.map(_.logicCells.toDouble).toArray, rs.map(_.errorBound).toArray)
      s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter)
    }
    if (function == "sin") {
      val a = chart.addSeries(s"paper: seed 001 Table 1, Quartus LEs (n=16, b=18)", Array(PaperAnchor.logicElements.toDouble), Array(PaperAnchor.accuracy))
      a.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter)
      a.setMarker(SeriesMarkers.DIAMOND)
    }
    os.makeDir.all(path / os.up)
    moire.files.SafeWrite(path)(t => { val o = new java.io.FileOutputStream(t.toIO); try BitmapEncoder.saveBitmap(chart, o, BitmapEncoder.BitmapFormat.PNG) finally o.close() })
  }
}
