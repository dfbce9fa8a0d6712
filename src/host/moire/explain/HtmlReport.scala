package moire.explain

import java.util.Base64

/** One self-contained HTML page of an explain report: every section rendered from the report's JSON (a list or an
  * object the renderer does not know gets a generic table, so new report keys show without a change here), the
  * familiar readouts, and the plots inline as base64 PNG. Opens offline, prints on A4.
  */
object HtmlReport {
  def esc(s: String): String = s.flatMap {
    case '<' => "&lt;"; case '>' => "&gt;"; case '&' => "&amp;"; case '"' => "&quot;"; case c => c.toString
  }
  private def title(k: String) = esc(k.replace('_', ' ').capitalize)

  /** A number to 5 significant digits, or the JSON value as text. */
  def value(v: ujson.Value): String = v match {
    case ujson.Num(d) if d == math.rint(d) && math.abs(d) < 1e12 => d.toLong.toString
    case ujson.Num(d) => val a = math.abs(d); if (a != 0 && (a < 1e-3 || a >= 1e6)) f"$d%.4e" else f"$d%.5g"
    case ujson.Str(s) => esc(s)
    case ujson.Null => "-"
    case ujson.Bool(b) => if (b) "yes" else "no"
    case ujson.Arr(a) => a.map(value).mkString(", ")
    case o: ujson.Obj => o.value.map { case (k, x) => s"${esc(k)} ${value(x)}" }.mkString("; ")
  }

  /** A generic rendering: a list of strings as bullets, a list of objects as a table, an object as key-value rows. */
  def generic(v: ujson.Value): String = v match {
    case ujson.Arr(a) if a.isEmpty => "<p class=\"none\">none</p>"
    case ujson.Arr(a) if a.forall(_.objOpt.isDefined) =>
      val cols = a.flatMap(_.obj.keys).distinct
      s"<table><tr>${cols.map(c => s"<th>${title(c)}</th>").mkString}</tr>" +
        a.map(r => "<tr>" + cols.map(c => s"<td>${r.obj.get(c).map(value).getOrElse("")}</td>").mkString + "</tr>").mkString + "</table>"
    case ujson.Arr(a) => "<ul>" + a.map(x => s"<li>${value(x)}</li>").mkString + "</ul>"
    case o: ujson.Obj => "<table>" + o.value.map { case (k, x) => s"<tr><th>${title(k)}</th><td>${value(x)}</td></tr>" }.mkString + "</table>"
    case x => s"<p>${value(x)}</p>"
  }

  def img(name: String, png: Array[Byte]): String =
    s"""<figure><img alt="${esc(name)}" src="data:image/png;base64,${Base64.getEncoder.encodeToString(png)}"><figcaption>${esc(name)}</figcaption></figure>"""

  private val css =
    """body{font-family:system-ui,sans-serif;max-width:1000px;margin:1em auto;padding:0 1em;color:#222}
      |h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;margin-top:1.6em}table{border-collapse:collapse;margin:.5em 0}
      |th,td{border:1px solid #ccc;padding:.2em .5em;text-align:left;font-variant-numeric:tabular-nums}th{background:#f3f3f3}
      |figure{margin:.5em 0;display:inline-block;max-width:100%}img{max-width:100%}figcaption{font-size:.8em;color:#555}
      |.pair figure{max-width:49%}.finding{border:1px solid #ddd;padding:.5em 1em;margin:1em 0}.none{color:#777}.sum{font-size:1.1em}
      |@media print{body{max-width:none}h2{break-after:avoid}.finding,figure,table{break-inside:avoid}img{max-width:90%}}""".stripMargin

  /** Keys with a section of their own; the rest are rendered generically, in their order. */
  private val Known = Set("file", "kind", "criterion", "samples", "seconds", "baseline", "findings", "final", "not_tested",
    "unexplained", "notes", "interpolation_error", "html", "plots")

  /** The page. `plots`: (file name, PNG bytes); a finding's plot is the one named `<stem>_effect_<k>_<effect>.png`. */
  def render(report: ujson.Obj, plots: Seq[(String, Array[Byte])]): String = {
    val r = report.value
    def get(k: String) = r.getOrElse(k, ujson.Null)
    def plot(suffix: String) = plots.find(_._1.endsWith(suffix)).map { case (n, b) => img(n, b) }.getOrElse("")
    val findings = get("findings").arrOpt.getOrElse(Nil).toSeq
    val sb = new StringBuilder
    sb ++= s"""<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>explain: ${value(get("file"))}</title><style>$css</style></head><body>"""
    sb ++= s"<h1>explain: ${esc(get("file").strOpt.fold("-")(_.split('/').last))}</h1>"
    sb ++= s"<p>${value(get("file"))}: ${value(get("kind"))}, ${value(get("samples"))} samples, explained in ${value(get("seconds"))} s. ${value(get("criterion"))}.</p>"
    // summary
    val base = get("baseline"); val fin = get("final")
    val named = findings.map(f => s"${value(f("effect"))} (${value(f.obj.getOrElse("channel", ujson.Null))})")
    sb ++= "<h2>Summary</h2><p class=\"sum\">"
    sb ++= (if (named.isEmpty) "No effect beyond the default model was found." else s"Found: ${named.mkString(", ")}.")
    base.objOpt.foreach(b => sb ++= s" Residual rms ${value(b.getOrElse("rms", ujson.Null))} with the default model")
    fin.objOpt.foreach(f => sb ++= s", ${value(f.getOrElse("rms", ujson.Null))} with the final model.")
    val unexpl = get("unexplained").arrOpt.map(_.size).getOrElse(0)
    if (unexpl > 0) sb ++= s" $unexpl structure(s) left unexplained (below)."
    sb ++= "</p>"
    // readouts
    val bp = base.objOpt.flatMap(_.get("params")).flatMap(_.objOpt)
    bp.foreach { p =>
      def n(k: String) = p.get(k).flatMap(_.numOpt)
      val rows = Seq(
        n("offset_sin_fs").map(v => "sin offset" -> f"${100 * v}%.3f %% FS"), n("offset_cos_fs").map(v => "cos offset" -> f"${100 * v}%.3f %% FS"),
        n("amplitude_sin_fs").map(v => "sin amplitude" -> f"${100 * v}%.3f %% FS"), n("amplitude_cos_fs").map(v => "cos amplitude" -> f"${100 * v}%.3f %% FS"),
        n("amplitude_sin_fs").zip(n("amplitude_cos_fs")).map { case (s, c) => "amplitude ratio sin/cos" -> f"${s / c}%.5f" },
        n("phase_error_deg").map(v => "phase error (departure from 90 degree)" -> f"$v%.4f degree"),
        n("noise_sin_fs").map(v => "noise sin (rms)" -> f"${100 * v}%.4f %% FS"), n("noise_cos_fs").map(v => "noise cos (rms)" -> f"${100 * v}%.4f %% FS"),
        n("typical_fringe_hz").map(v => "typical fringe frequency" -> f"$v%.6g Hz")).flatten
      if (rows.nonEmpty) sb ++= "<h2>Readouts</h2><table>" + rows.map { case (k, v) => s"<tr><th>${esc(k)}</th><td>${esc(v)}</td></tr>" }.mkString + "</table>"
    }
    get("interpolation_error").objOpt.foreach { ie =>
      val u = value(ie("unit")); val su = ie.get("scaled_unit").flatMap(_.strOpt)
      sb ++= s"<h3>Interpolation error ($u)</h3><table><tr><th></th><th>rms</th><th>peak to peak</th>" +
        (1 to 4).map(k => s"<th>harmonic $k</th>").mkString + su.fold("")(s => s"<th>rms ($s)</th>") + "</tr>"
      for ((k, label) <- Seq("before_correction" -> "before correction", "after_correction" -> "after correction (Heydemann)"); part <- ie.get(k).flatMap(_.objOpt)) {
        sb ++= s"<tr><th>$label</th><td>${value(part("rms"))}</td><td>${value(part("peak_to_peak"))}</td>" +
          (1 to 4).map(h => s"<td>${part("harmonics").obj.get(h.toString).map(value).getOrElse("-")}</td>").mkString +
          su.fold("")(_ => s"<td>${value(part("rms_scaled"))}</td>") + "</tr>"
      }
      sb ++= "</table>"
      sb ++= plot("_interpolation_error.png")
    }
    val liss = plot("_lissajous_before.png") + plot("_lissajous_after.png")
    if (liss.nonEmpty) sb ++= s"<h2>Lissajous figure, before and after correction</h2><div class=\"pair\">$liss</div>"
    // findings
    sb ++= "<h2>Findings</h2>"
    if (findings.isEmpty) sb ++= "<p class=\"none\">none: the default model explains the recording</p>"
    for ((f, k) <- findings.zipWithIndex; o <- f.objOpt) {
      val eff = value(o("effect"))
      sb ++= s"<div class=\"finding\"><h3>${k + 1}. $eff (${value(o.getOrElse("channel", ujson.Null))})</h3><p>${value(o.getOrElse("summary", ujson.Null))}</p>"
      val params: ujson.Obj = o.get("params").flatMap(_.objOpt).map(ujson.Obj.from(_)).getOrElse(ujson.Obj()); val unc = o.get("uncertainty").flatMap(_.objOpt)
      if (params.value.nonEmpty) sb ++= "<table><tr><th>parameter</th><th>value</th><th>uncertainty (1 sigma)</th></tr>" +
        params.value.map { case (p, v) => s"<tr><td>${esc(p)}</td><td>${value(v)}</td><td>${unc.flatMap(_.get(p)).map(value).getOrElse("-")}</td></tr>" }.mkString + "</table>"
      val rest = ujson.Obj.from(o.value.filterNot { case (kk, _) => Set("effect", "channel", "summary", "params", "uncertainty")(kk) })
      if (rest.value.nonEmpty) sb ++= generic(rest)
      sb ++= plot(s"_effect_${k + 1}_$eff.png") + "</div>"
    }
    sb ++= s"<h2>Unexplained structure</h2>${generic(get("unexplained"))}"
    sb ++= s"<h2>What was not tested, and why</h2>${generic(get("not_tested"))}"
    sb ++= s"<h2>Notes</h2>${generic(get("notes"))}"
    for ((k, v) <- r if !Known(k)) sb ++= s"<h2>${title(k)}</h2>${generic(v)}"
    val residual = Seq("_residual_time.png", "_residual_phase.png", "_residual_spectrum.png").map(plot).mkString
    if (residual.nonEmpty) sb ++= s"<h2>Residual</h2>$residual"
    val shown = Seq("_interpolation_error.png", "_lissajous_before.png", "_lissajous_after.png", "_residual_time.png", "_residual_phase.png",
      "_residual_spectrum.png") ++ findings.zipWithIndex.map { case (f, k) => s"_effect_${k + 1}_${value(f("effect"))}.png" }
    val others = plots.filterNot(p => shown.exists(p._1.endsWith))
    if (others.nonEmpty) sb ++= "<h2>Other plots</h2>" + others.map { case (n, b) => img(n, b) }.mkString
    sb ++= "<h2>Baseline (default model)</h2>" + generic(base) + "</body></html>"
    sb.toString
  }
}
