package moire.monitor

import moire.lissajous.Ellipse

/** The readouts of one ellipse against the tolerances: each value, its limits, and how much of its tolerance it uses.
  * Signal quality = 100 % x (1 - the largest use / 2), clipped to 0..100: 100 % a perfect circle, 50 % a readout at its
  * tolerance mark, 0 % at twice the tolerance.
  */
object Readout {
  final case class Item(key: String, label: String, value: Double, unit: String, lo: Double, hi: Double, nominal: Double) {
    /** |departure from nominal| over the tolerance on that side. */
    def use: Double = if (value >= nominal) (value - nominal) / (hi - nominal) else (nominal - value) / (nominal - lo)
    def json: ujson.Obj = ujson.Obj("key" -> key, "label" -> label, "value" -> value, "unit" -> unit, "lo" -> lo, "hi" -> hi,
      "nominal" -> nominal, "ok" -> (value >= lo && value <= hi))
  }

  def items(e: Ellipse, t: Tolerances): Seq[Item] = {
    val amp = (t.amplitudeMinPct + t.amplitudeMaxPct) / 2
    Seq(
      Item("amplitude_sin", "sin amplitude", 100 * e.ampSin, "% FS", t.amplitudeMinPct, t.amplitudeMaxPct, amp),
      Item("amplitude_cos", "cos amplitude", 100 * e.ampCos, "% FS", t.amplitudeMinPct, t.amplitudeMaxPct, amp),
      Item("ratio", "amplitude ratio sin/cos", e.ratio, "", 1 - t.ratioPct / 100, 1 + t.ratioPct / 100, 1),
      Item("offset_sin", "sin offset", 100 * e.offsetSin, "% FS", -t.offsetPct, t.offsetPct, 0),
      Item("offset_cos", "cos offset", 100 * e.offsetCos, "% FS", -t.offsetPct, t.offsetPct, 0),
      Item("phase_error", "phase error (90 degree departure)", e.phaseErrorDeg, "degree", -t.phaseDeg, t.phaseDeg, 0))
  }

  def quality(items: Seq[Item]): Double = math.max(0, math.min(100, 100 * (1 - items.map(_.use).max / 2)))
}
