package moire.calibration

import moire.harmonic._

/** The coefficient file the board loads: JSON with the harmonics in arcsec and degrees, the register
  * words of [[HarmonicCompensator]], and a plain register-write listing (`addr data`, hex).
  */
object CoefficientFile {
  val format = "moire-harmonic-coefficients v1"

  /** The slots for a fit: harmonics in fit order, unused slots switched off (order 0, c 0). */
  def slots(p: HarmonicParams, fit: HarmonicFitResult): Seq[HarmonicSlot] = {
    if (fit.harmonics.size > p.harmonics)
      throw new CalibrationError(s"${fit.harmonics.size} harmonics do not fit a compensator with m = ${p.harmonics}")
    fit.harmonics.map { h =>
      if (h.order > p.maxOrder) throw new CalibrationError(s"order ${h.order} exceeds the compensator's max order ${p.maxOrder}")
      try HarmonicSlot.of(p, h.order, h.c, h.phiDeg)
      catch { case e: IllegalArgumentException => throw new CalibrationError(e.getMessage.stripPrefix("requirement failed: ")) }
    } ++ Seq.fill(p.harmonics - fit.harmonics.size)(HarmonicSlot.off)
  }

  /** Register writes (address, 32-bit data) in the order to apply them. */
  def writes(p: HarmonicParams, slots: Seq[HarmonicSlot]): Seq[(Int, Long)] =
    slots.zipWithIndex.flatMap { case (s, j) =>
      Seq((p.regsPerSlot * j) -> s.order.toLong, (p.regsPerSlot * j + 1) -> (s.c & ((1L << p.coefWidth) - 1)),
        (p.regsPerSlot * j + 2) -> s.phi)
    }

  private def hex(v: Long) = f"0x$v%08x"

  def json(p: HarmonicParams, source: String, fit: HarmonicFitResult, extra: Seq[(String, ujson.Value)]): ujson.Obj = {
    val ss = slots(p, fit)
    val o = ujson.Obj(
      "format" -> format,
      "source" -> source,
      "compensator" -> ujson.Obj(
        "module" -> p.moduleName, "lines" -> p.lines, "subdivision" -> p.subdivision,
        "counts_per_turn" -> p.countsPerTurn.toDouble, "harmonics" -> p.harmonics, "max_order" -> p.maxOrder,
        "coef_width" -> p.coefWidth, "coef_frac" -> p.coefFrac, "phase_bits" -> p.countBits,
        "out_frac" -> p.outFrac, "latency" -> p.latency),
      "convention" -> "error_arcsec = reading - true angle; f(theta) = sum c_k sin(k theta + phi_k); the board outputs theta - f(theta)",
      "offset_arcsec" -> fit.offset,
      "harmonics" -> ujson.Arr(ss.zipWithIndex.map { case (s, j) =>
        val h = fit.harmonics.lift(j)
        ujson.Obj("slot" -> j, "order" -> s.order, "c_arcsec" -> h.fold(0.0)(_.c), "phi_deg" -> h.fold(0.0)(_.phiDeg),
          "c_word" -> hex(s.c & ((1L << p.coefWidth) - 1)), "phi_word" -> hex(s.phi))
      }: _*),
      "fit" -> ujson.Obj("rms_residual_arcsec" -> fit.rms, "max_abs_residual_arcsec" -> fit.maxAbs),
      "registers" -> ujson.Arr(writes(p, ss).map { case (a, d) => ujson.Obj("addr" -> a, "data" -> hex(d)) }: _*)
    )
    extra.foreach { case (k, v) => o(k) = v }
    o
  }

  /** One write per line, `addr data` in hex, comments with `#`. */
  def listing(p: HarmonicParams, fit: HarmonicFitResult): String = {
    val ss = slots(p, fit)
    // the format named on the first line (`SafeWrite.kind`: a user's notes of the same name are another kind of file)
    val head = Seq(s"# moire-harmonic-registers v1 for ${p.moduleName}", "# addr data (hex); fields: slot*4 + 0 order, 1 c_k, 2 phi_k")
    (head ++ writes(p, ss).map { case (a, d) => f"$a%02x ${d}%08x" }).mkString("", "\n", "\n")
  }
}
