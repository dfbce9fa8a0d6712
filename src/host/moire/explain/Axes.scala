package moire.explain

import scala.jdk.CollectionConverters._
import org.knowm.xchart.XYChart

/** Axis ranges at round values (1, 2, 2.5 or 5 times a power of ten), so that XChart's ticks fall on round numbers
  * (left alone, it starts the ticks at the data's first value, e.g. a bin centre) and every curve stays inside its axis.
  */
object Axes {
  /** A round tick step giving about `ticks` intervals over `range`. */
  def step(range: Double, ticks: Int = 8): Double = {
    val raw = range / ticks; val p = math.pow(10, math.floor(math.log10(raw)))
    Seq(1.0, 2.0, 2.5, 5.0, 10.0).map(_ * p).find(_ >= raw * (1 - 1e-9)).get
  }
  /** The range [lo, hi] widened to multiples of a round step; a flat range gets a margin. A range below a millionth of
    * its values' size, or of 1 (the plots' units: LSB, degree, arcsec, %), is flat: XChart's tick search never ended
    * on an axis of +-1e-9 with a decimal pattern (every label "0"), nor where a step does not change the value (5 +
    * 1e-16 is 5); a constant calibration table's plots hung so.
    */
  def span(lo: Double, hi: Double): (Double, Double) = {
    val size = math.max(math.abs(lo), math.abs(hi))
    val (a, b) = if (hi - lo > MinRange * math.max(size, 1.0)) (lo, hi)
      else { val c = 0.5 * (lo + hi); val m = math.max(math.abs(c) * 0.1, MinRange); (c - m, c + m) }
    val s = step(b - a)
    (math.floor(a / s + 1e-9) * s, math.ceil(b / s - 1e-9) * s)
  }
  /** The narrowest range an axis spans, relative to its values' size (and at least this much). */
  val MinRange = 1e-6
  private def finite(a: Iterable[Double]) = a.filter(v => !v.isNaN && !v.isInfinite)

  def round(c: XYChart): Unit = {
    val series = c.getSeriesMap.values.asScala.toSeq
    val xs = finite(series.flatMap(_.getXData))
    // a phase or angle axis over most of a turn: 0 to 360
    val turn = xs.nonEmpty && xs.min >= 0 && xs.max <= 360 && xs.max - xs.min > 180 && c.getStyler.getXAxisDecimalPattern != null &&
      c.getXAxisTitle.contains("(degree)")
    if (turn) { c.getStyler.setXAxisMin(0.0); c.getStyler.setXAxisMax(360.0) }
    else if (xs.nonEmpty) { val (lo, hi) = span(xs.min, xs.max); c.getStyler.setXAxisMin(lo); c.getStyler.setXAxisMax(hi) }
    for ((g, ss) <- series.groupBy(_.getYAxisGroup)) {
      val ys = finite(ss.flatMap(_.getYData))
      if (ys.nonEmpty) { val (lo, hi) = span(ys.min, ys.max); c.getStyler.setYAxisMin(g, lo); c.getStyler.setYAxisMax(g, hi) }
    }
  }

  /** Both axes over one round range (for a figure whose shape matters: the Lissajous). */
  def square(c: XYChart): Unit = {
    val series = c.getSeriesMap.values.asScala.toSeq
    val v = finite(series.flatMap(s => s.getXData.toSeq ++ s.getYData.toSeq))
    if (v.nonEmpty) {
      val (lo, hi) = span(v.min, v.max)
      c.getStyler.setXAxisMin(lo); c.getStyler.setXAxisMax(hi); c.getStyler.setYAxisMin(lo); c.getStyler.setYAxisMax(hi)
    }
  }
}
