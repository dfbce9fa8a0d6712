package moire.explain

/** A located departure of the residual from white noise. */
final case class Located(where: String, summary: String, params: Map[String, Double], significant: Boolean) {
  def json: ujson.Obj = ujson.Obj("where" -> where, "summary" -> summary, "params" -> Report.nums(params), "significant" -> significant)
}

/** The JSON report of one file. Information criterion: BIC = -2 ln L + k ln n (n = observations). */
final case class Report(file: String, kind: String, baselineRms: Double, baselineBic: Double, baseline: Map[String, Double],
                        located: Seq[Located], findings: Seq[Finding], unexplained: Seq[Located], finalRms: Double, finalBic: Double,
                        samples: Int, seconds: Double, notes: Seq[String] = Nil, untested: Seq[String] = Nil,
                        negligible: Seq[Negligible] = Nil, misfit: Seq[Located] = Nil) {
  def json: ujson.Obj = ujson.Obj(
    "file" -> file, "kind" -> kind, "criterion" -> s"BIC = -2 ln L + k ln n; an effect is accepted when it lowers BIC by more than ${SignalExplain.Threshold}",
    "samples" -> samples,
    "baseline" -> ujson.Obj("rms" -> baselineRms, "bic" -> baselineBic, "params" -> Report.nums(baseline)),
    "located" -> ujson.Arr(located.map(_.json): _*),
    "findings" -> ujson.Arr(findings.map(_.json): _*),
    "unexplained" -> ujson.Arr(unexplained.map(_.json): _*),
    "negligible" -> ujson.Arr(negligible.map(_.json): _*),
    "misfit" -> ujson.Arr(misfit.map(_.json): _*),
    "final" -> ujson.Obj("rms" -> finalRms, "bic" -> finalBic),
    "notes" -> ujson.Arr(notes.map(ujson.Str(_)): _*),
    "not_tested" -> ujson.Arr(untested.map(ujson.Str(_)): _*),
    "seconds" -> seconds)

  /** Short text for the terminal. */
  def text: String = {
    val sb = new StringBuilder
    sb ++= f"$file ($kind, $samples samples): default model rms $baselineRms%.4g, BIC $baselineBic%.6g\n"
    located.filter(_.significant).foreach(l => sb ++= s"  located: ${l.where}: ${l.summary}\n")
    if (findings.forall(_.deltaBic.isNaN)) sb ++= "  no significant effect beyond the default model\n"
    findings.filter(_.deltaBic.isNaN).foreach(f => sb ++= s"  finding ${f.effect} (${f.where}): ${f.summary}\n")
    findings.filterNot(_.deltaBic.isNaN).foreach { f =>
      sb ++= f"  finding ${f.effect} (delta BIC ${f.deltaBic}%.1f, rms ${f.rmsBefore}%.4g -> ${f.rmsAfter}%.4g): ${f.summary}\n"
      f.lookAlikes.foreach(l => sb ++= s"    look-alike: $l\n")
      sb ++= "    " + f.params.toSeq.sortBy(_._1).map { case (k, v) => f"$k = $v%.5g +- ${f.unc.getOrElse(k, Double.NaN)}%.2g" }.mkString(", ") + "\n"
    }
    misfit.foreach(u => sb ++= s"  misfit: ${u.where}: ${u.summary}\n")
    unexplained.foreach(u => sb ++= s"  unexplained: ${u.where}: ${u.summary}\n")
    negligible.foreach(u => sb ++= s"  negligible: ${u.json("summary").str}\n")
    notes.foreach(n => sb ++= s"  note: $n\n")
    untested.foreach(n => sb ++= s"  not tested: $n\n")
    sb ++= f"  final rms $finalRms%.4g, BIC $finalBic%.6g ($seconds%.1f s)\n"
    sb.toString
  }
}

object Report {
  /** A number, or null when it is not finite (JSON has no NaN). */
  def num(v: Double): ujson.Value = if (v.isNaN || v.isInfinite) ujson.Null else ujson.Num(v)
  def nums(m: Map[String, Double]): ujson.Obj = {
    val o = ujson.Obj()
    m.toSeq.sortBy(_._1).foreach { case (k, v) => o(k) = if (v.isNaN || v.isInfinite) ujson.Null else ujson.Num(v) }
    o
  }
}

/** Progress of a long run: phases with a number of steps. */
trait Progress {
  def phase(name: String, steps: Int): Unit
  def step(k: Int): Unit
  def close(): Unit = ()
}
object Progress {
  val none: Progress = new Progress { def phase(name: String, steps: Int): Unit = (); def step(k: Int): Unit = () }
  /** A bar per phase on stderr (plain lines when stderr is no terminal). */
  def bar(task: String): Progress = new Progress {
    private var pb: moire.progress.Bar = _
    def phase(name: String, steps: Int): Unit = {
      if (pb != null) pb.close()
      pb = new moire.progress.Bar(s"${moire.files.Shown.text(task)}: $name", steps.toLong)
    }
    def step(k: Int): Unit = if (pb != null) pb.stepTo(pb.position + k)
    override def close(): Unit = if (pb != null) { pb.close(); pb = null }
  }
}
