package moire.explain.evidence

import moire.explain.{Finding, Progress, Report, SignalExplain}

/** Running explain on a bench's text, printing what it found, and the places where a spec reads report fields the
  * engine of issue 28 adds (marked "needs:"): one place to connect each.
  */
object Evidence {
  def explain(name: String, text: String): Report = {
    val r = SignalExplain.run(name, BenchText.recording(name, text), Nil, Progress.none).report
    println(s"$name: ${line(r)}")
    r
  }

  def finding(f: Finding): String =
    s"${f.effect}(${f.channel}) " + f.params.toSeq.sortBy(_._1).map { case (k, v) => f"$k=$v%.4g" }.mkString(" ") + f" dBIC=${f.deltaBic}%.1f"

  def line(r: Report): String =
    s"findings [${r.findings.map(finding).mkString("; ")}] unexplained [${r.unexplained.map(u => u.where + ": " + u.summary).mkString("; ")}]" +
      f" rms ${r.baselineRms}%.4g -> ${r.finalRms}%.4g" + misfit(r).map(m => s" misfit [$m]").getOrElse("") + f" (${r.seconds}%.1f s)"

  def effects(r: Report): Seq[String] = r.findings.map(_.effect)

  /** needs: the adequacy statement of issue 28 ("the default model does not follow the signal here", with where:
    * time, position and speed ranges). Looked up in the notes until the report has its own field.
    */
  def misfit(r: Report): Option[String] =
    r.misfit.headOption.map(m => s"${m.where}: ${m.summary}").orElse(r.notes.find(_.contains("does not follow")))

  /** A time range in a text, as "0.012..0.031 s" or "12 .. 31 ms" (where the report says the model does not follow). */
  def hasTimeRange(text: String): Boolean = """[-+\d.e]+\s*(\.\.|to|-)\s*[-+\d.e]+\s*(s|ms|us)\b""".r.findFirstIn(text).isDefined

  /** needs: the "too small to matter" list of issue 28 (significant, below the materiality floor, with its size).
    * Looked up in the notes until the report has its own field.
    */
  def negligible(r: Report): Seq[String] = r.negligible.map(_.json("summary").str) ++ r.notes.filter(_.contains("too small to matter"))

  /** needs: the name of the engine's effect for phase noise of the motion (the look-alike of jitter). */
  def isPhaseNoise(effect: String): Boolean = effect.contains("phase_noise") || effect.contains("vibration")

  /** needs: a finding naming its look-alike and the measurement that would separate them (issue 28, Look-alikes).
    * Looked up in the finding's summary until it has its own field.
    */
  def namesLookAlike(f: Finding, other: String): Boolean = f.summary.contains(other) || f.lookAlikes.exists(_.contains(other))
}
