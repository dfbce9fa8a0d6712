package moire.calibration

import moire.harmonic._

/** The `calibrate` subcommand: calibration CSV -> harmonic fit -> coefficient file, register listing, plot. */
object Calibrate {
  /** Per-direction fit and the cw - ccw difference at the shared angles. */
  final case class Reversal(meanArcsec: Double, maxAbsArcsec: Double, shared: Int)

  final case class Result(data: CalibrationData, maxOrder: Int, fit: HarmonicFitResult,
                          byDirection: Seq[(String, HarmonicFitResult)], reversal: Option[Reversal], files: Seq[os.Path])

  def run(input: os.Path, out: os.Path, p: HarmonicParams, maxOrderOpt: Int): Result = {
    val (jf, rf, pf) = outputs(input, out)
    val data = CalibrationData.read(input)
    val distinct = data.points.map(a => math.round(a.angleDeg * 1e6)).distinct.size
    if (maxOrderOpt < -1) throw new CalibrationError(s"--max-order must be at least 1 (or left out for the default), got $maxOrderOpt")
    val maxOrder = if (maxOrderOpt < 0) HarmonicFit.defaultMaxOrder(distinct) else maxOrderOpt
    if (maxOrder < 1) throw new CalibrationError(s"--max-order must be at least 1, got $maxOrder")
    if (maxOrderOpt < 0 && maxOrder < p.harmonics)
      throw new CalibrationError(s"${data.file}: $distinct distinct angles support harmonics up to order $maxOrder, fewer than --harmonics ${p.harmonics}")
    val fit = HarmonicFit.analyse(data.points.map(_.angleDeg), data.points.map(_.errorArcsec), maxOrder, p.harmonics)
    val dirs = data.directions.filter(_.nonEmpty)
    val byDir = if (dirs.size > 1) dirs.map { d =>
      val ps = data.of(d)
      val need = 2 * fit.harmonics.size + 1
      if (ps.size < need) throw new CalibrationError(s"${data.file}: direction $d has ${ps.size} point${if (ps.size == 1) "" else "s"} " +
        s"(first on line ${ps.head.line}); each direction is fitted on its own and needs at least $need for the ${fit.harmonics.size} " +
        "harmonics kept: give it its full set of angles, or fewer --harmonics")
      d -> HarmonicFit.fit(ps.map(_.angleDeg), ps.map(_.errorArcsec), fit.harmonics.map(_.order))
    } else Nil
    val reversal = if (dirs.toSet == Set("cw", "ccw")) {
      val ccw = data.of("ccw").map(q => math.round(q.angleDeg * 1e6) -> q.errorArcsec).toMap
      val diffs = data.of("cw").flatMap(q => ccw.get(math.round(q.angleDeg * 1e6)).map(q.errorArcsec - _))
      if (diffs.isEmpty) None else Some(Reversal(diffs.sum / diffs.size, diffs.map(math.abs).max, diffs.size))
    } else None

    val extra = Seq.newBuilder[(String, ujson.Value)]
    extra += "analysis" -> ujson.Obj("points" -> data.points.size, "max_order" -> maxOrder, "method" -> "least squares (QR)",
      "metadata" -> ujson.Obj.from(data.meta.toSeq.sortBy(_._1).map { case (k, v) => k -> ujson.Str(v) }))
    if (data.notes.nonEmpty) extra += "notes" -> ujson.Arr.from(data.notes.map(ujson.Str(_)))
    if (byDir.nonEmpty) extra += "directions" -> ujson.Obj.from(byDir.map { case (d, f) =>
      d -> ujson.Obj("offset_arcsec" -> f.offset, "rms_residual_arcsec" -> f.rms,
        "harmonics" -> ujson.Arr(f.harmonics.map(h => ujson.Obj("order" -> h.order, "c_arcsec" -> h.c, "phi_deg" -> h.phiDeg)): _*))
    })
    reversal.foreach(r => extra += "reversal_cw_minus_ccw" -> ujson.Obj("mean_arcsec" -> r.meanArcsec,
      "max_abs_arcsec" -> r.maxAbsArcsec, "shared_angles" -> r.shared))

    // a harmonic beyond the compensator's coefficient range: one line naming the file
    val (json, listing) = try (CoefficientFile.json(p, data.file, fit, extra.result()), CoefficientFile.listing(p, fit))
      catch { case e: CalibrationError => throw new CalibrationError(s"${data.file}: ${e.getMessage}") }
    val curves = if (byDir.nonEmpty) byDir.map { case (d, f) => CalibrationPlot.Curve(d, data.of(d), f) }
      else Seq(CalibrationPlot.Curve("", data.points, fit))
    // the three files as one: a failed write is one FileError naming the file, all three old files kept
    moire.files.SafeWrite.made(Seq(jf -> (t => os.write(t, ujson.write(json, indent = 2) + "\n")), rf -> (t => os.write(t, listing)),
      pf -> CalibrationPlot.png(s"${data.file}: ${p.harmonics} largest harmonics up to order $maxOrder", curves)), earlier(jf))
    Result(data, maxOrder, fit, byDir, reversal, Seq(jf, rf, pf))
  }

  /** The coefficient file, register listing and plot `run` writes for `input`, each checked before the work: new, or
    * as moire wrote it (`SafeWrite.checkMade`), and of the kind written (a user's JSON, notes or image is refused).
    */
  def outputs(input: os.Path, out: os.Path): (os.Path, os.Path, os.Path) = {
    moire.files.SafeWrite.checkNameOf(input)
    val stem = moire.files.Stem.of(input)
    val (jf, rf, pf) = (out / s"$stem.coefficients.json", out / s"$stem.registers.txt", out / s"$stem.png")
    for ((f, kind) <- Seq(jf -> "JSON", rf -> "a moire-harmonic-registers file", pf -> "a PNG image")) {
      moire.files.SafeWrite.checkKind(f, kind)
      moire.files.SafeWrite.checkMade(f, earlier(jf))
    }
    (jf, rf, pf)
  }

  /** A file the folder's list does not name is calibrate's from before the lists when `SafeWrite.earlier` says so, and a
    * plot only beside such a coefficient file: an image alone in a folder without a list is a user's, not a plot of ours.
    */
  private def earlier(jf: os.Path)(t: os.Path): Boolean =
    moire.files.SafeWrite.earlier(t) && (t.ext != "png" || (os.isFile(jf, followLinks = false) && moire.files.SafeWrite.earlier(jf)))

  /** The summary printed to stdout. */
  def report(r: Result): String = {
    val pts = r.data.points.map(_.errorArcsec)
    val mean = pts.sum / pts.size
    val rmsData = math.sqrt(pts.map(e => (e - mean) * (e - mean)).sum / pts.size)
    val b = new StringBuilder
    b ++= f"${r.data.file}: ${r.data.points.size} points, harmonics up to order ${r.maxOrder} fitted, ${r.fit.harmonics.size} kept\n"
    b ++= f"  offset c0 ${r.fit.offset}%+.4f arcsec (not compensated)\n"
    for (h <- r.fit.harmonics) b ++= f"  k=${h.order}%-3d c=${h.c}%9.4f arcsec  phi=${h.phiDeg}%+9.3f deg\n"
    // every error the same: the amplitudes kept are rounding errors and their phases mean nothing
    if (!(rmsData > 1e-9 * math.max(1.0, math.abs(mean))))
      b ++= "  note: the errors do not vary with the angle: there is no harmonic to compensate (the amplitudes above are rounding errors, their phases meaningless)\n"
    b ++= f"  rms about the mean ${rmsData}%.4f arcsec, residual rms ${r.fit.rms}%.4f arcsec, max |residual| ${r.fit.maxAbs}%.4f arcsec\n"
    for ((d, f) <- r.byDirection) b ++= f"  $d%-4s offset ${f.offset}%+.4f arcsec, residual rms ${f.rms}%.4f arcsec\n"
    r.reversal.foreach(v => b ++= f"  reversal cw - ccw over ${v.shared} angles: mean ${v.meanArcsec}%+.4f arcsec, max |d| ${v.maxAbsArcsec}%.4f arcsec\n")
    for ((d, step, missing) <- r.data.gridGaps) {
      val dir = if (d.isEmpty) "" else s" ($d)"
      b ++= f"  note$dir: the angles look like a $step%.6g degree grid missing ${missing.map(a => f"$a%.6g").mkString(", ")}; " +
        f"add '# step_deg: $step%.6g' to make gaps an error\n"
    }
    r.data.notes.foreach(n => b ++= s"  note: $n\n")
    r.files.foreach(f => b ++= s"wrote $f\n")
    b.result()
  }
}
