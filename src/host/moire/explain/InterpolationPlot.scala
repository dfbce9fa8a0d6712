package moire.explain

import org.knowm.xchart.XYChart

/** The interpolation error against the fringe phase, before and after the Heydemann correction, in counts (and in um
  * or arcsec on a second axis scale in the title when the recording states its scale).
  */
object InterpolationPlot {
  def chart(title: String, ie: InterpolationError): XYChart = {
    val unit = ie.unit + ie.scaleUnit.zip(ie.perCount).fold("")({ case (u, f) => f"; 1 ${ie.unit.stripSuffix("s")} = $f%.4g $u" })
    val c = Plots.chart(title, "fringe phase (degree)", s"interpolation error (${ie.unit})")
    c.setTitle(s"$title ($unit)")
    val deg = (i: Int) => 360 * (ie.fringe(i) - math.floor(ie.fringe(i)))
    for ((a, label) <- Seq(ie.before -> "before correction (raw codes)", ie.after -> "after correction (fitted ellipse)")) {
      val (x, y) = Plots.binned(deg, a(_), a.length, 0, 360, 90)
      Plots.line(c, f"$label, rms ${math.sqrt(a.map(v => v * v).sum / a.length)}%.3g ${ie.unit}", x, y)
    }
    c
  }
}
