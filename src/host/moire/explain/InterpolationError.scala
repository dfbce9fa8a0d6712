package moire.explain

import moire.lissajous.{Ellipse, EllipseFit}
import moire.recording.Recording

/** The interpolation error a subdivider would make on a recording: the fringe phase from atan2 of the signals minus
  * explain's fitted trajectory (the smooth motion), before correction (the raw codes about mid-scale) and after the
  * Heydemann correction (offsets, gains and phase error of the fitted ellipse), with its harmonics of the fringe.
  * In counts when the recording states `counts_per_period`, else in thousandths of a period; in um with `period_um`,
  * in arcsec with `lines_per_rev`.
  */
final case class InterpolationError(unit: String, perPeriod: Double, scaleUnit: Option[String], perCount: Option[Double],
                                    ellipse: Option[Ellipse], before: Array[Double], after: Array[Double], fringe: Array[Double]) {
  private def rms(a: Array[Double]) = math.sqrt(a.map(v => v * v).sum / math.max(1, a.length))
  private def pp(a: Array[Double]) = if (a.isEmpty) Double.NaN else a.max - a.min
  /** Amplitude of harmonic k of the fringe in `a` (in the error's unit). */
  def harmonic(a: Array[Double], k: Int): Double = {
    var c = 0.0; var s = 0.0; var i = 0
    while (i < a.length) { val t = 2 * math.Pi * k * fringe(i); c += a(i) * math.cos(t); s += a(i) * math.sin(t); i += 1 }
    2 * math.hypot(c, s) / math.max(1, a.length)
  }
  def json: ujson.Obj = {
    def part(a: Array[Double]) = ujson.Obj("rms" -> Report.num(rms(a)), "peak_to_peak" -> Report.num(pp(a)),
      "harmonics" -> ujson.Obj.from((1 to 4).map(k => k.toString -> Report.num(harmonic(a, k)))),
      "rms_scaled" -> perCount.fold[ujson.Value](ujson.Null)(f => Report.num(rms(a) * f)))
    ujson.Obj("unit" -> unit, "scaled_unit" -> scaleUnit.fold[ujson.Value](ujson.Null)(ujson.Str(_)),
      "before_correction" -> part(before), "after_correction" -> part(after),
      "ellipse" -> ellipse.fold[ujson.Value](ujson.Null)(e => ujson.Obj("offset_sin_fs" -> e.offsetSin, "offset_cos_fs" -> e.offsetCos,
        "amplitude_sin_fs" -> e.ampSin, "amplitude_cos_fs" -> e.ampCos, "ratio" -> e.ratio, "phase_error_deg" -> e.phaseErrorDeg)))
  }
}

object InterpolationError {
  /** Points kept (evenly spread over the record). */
  val MaxPoints = 100000

  def of(rec: Recording, e: SignalEngine): InterpolationError = {
    val n = rec.length; val stride = math.max(1, n / MaxPoints); val m = (n + stride - 1) / stride
    // the engine's measured values when it fitted this recording (two arrays of the record's length fewer)
    val (ys, yc) = if (e.rec eq rec) (e.ys, e.yc) else (rec.values(rec.sin), rec.values(rec.cos))
    val el = EllipseFit.fit(yc, ys, n)
    val cpp = rec.meta.get("counts_per_period").flatMap(_.toDoubleOption).filter(_ > 0)
    val (unit, per) = cpp.fold(("milliperiod", 1000.0))(c => ("counts", c))
    val scaled = (rec.meta.get("period_um").flatMap(_.toDoubleOption).filter(_ > 0).map(p => ("um", p / per)) orElse
      rec.linesPerRev.filter(_ > 0).map(l => ("arcsec", 1296000.0 / l / per)))
    val fr = Array.tabulate(m)(j => e.phase(j * stride))
    def err(theta: Int => Double): Array[Double] = {
      val d = Array.tabulate(m)(j => theta(j * stride) / (2 * math.Pi) - fr(j))
      val mc = math.atan2(d.map(v => math.sin(2 * math.Pi * v)).sum, d.map(v => math.cos(2 * math.Pi * v)).sum) / (2 * math.Pi)
      d.map(v => { val w = v - mc; (w - math.rint(w)) * per })
    }
    val mid = 0.0
    val before = err(i => math.atan2(ys(i) - mid, yc(i) - mid))
    val after = el.fold(before)(el => err(i => el.phase(yc(i), ys(i))))
    InterpolationError(unit, per, scaled.map(_._1), scaled.map(_._2), el, before, after, fr)
  }
}
