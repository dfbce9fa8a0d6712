package moire.explain

import moire.recording.{Recording, Reference}
import org.hipparchus.distribution.continuous.ChiSquaredDistribution
import SignalExplain.Result

/** A long record searched on one interleaved subsample (every d-th sample from the first) and confirmed on the others.
  * Each other subsample (every d-th from the r-th) is fitted again with the model the search found; the findings'
  * parameters are combined over all d (inverse-variance means, all samples' precision) and must agree between them.
  * Where they do not, or a line's phase does not advance between the subsamples as its frequency says (a line above the
  * subsample's Nyquist frequency, seen at its alias), the record is explained again on all its samples. The subsamples
  * are whole records at 1/d of the rate: every effect's model is a function of time, the phase and the codes, not of
  * the sample's neighbours, so each holds every effect of the record over its whole time and speed range.
  */
object Interleaved {
  /** Records longer than this are searched on an interleaved subsample of at most this many samples. A material effect
    * (`Materiality`: 0.25 LSB, 0.1 of the noise) over the whole record stands thousands of BIC units above the noise in
    * 250,000 samples; one over a short stretch of it has a quarter of a 1 M record's evidence (docs/explain.md).
    */
  val SearchSamples = 250000
  /** Records up to this long are searched again on all samples where the subsample's search leaves structure it does
    * not explain: there the search on all samples may (another generator's 60 Hz hum on move-and-dwell motion, 800 k
    * samples: on every 4th sample the hum beside five unexplained items, final rms 0.000564; on all, the hum alone, 0.000506).
    * A longer record keeps the subsample's result and says so (all of 20 M samples would take half an hour).
    */
  val WholeIfUnexplained = 1200000
  /** The fastest fringe keeps this many samples per period in a subsample, at least (the phase is unwrapped from them). */
  val MinSamplesPerFringe = 4.0
  /** Agreement between the subsamples fails at this chi-square tail probability. */
  val Tail = 1e-4

  /** The subsampling factor for a record: 1 (all samples searched) when it is short or its fringe is too fast. */
  def factor(rec: Recording, searchSamples: Int): Int = {
    val n = rec.length
    if (n <= searchSamples) 1
    else {
      val want = (n + searchSamples - 1) / searchSamples
      val f = fastestFringeHz(rec)
      val byFringe = if (f > 0) math.floor(rec.sampleRateHz / (MinSamplesPerFringe * f)).toInt else want
      math.max(1, math.min(want, byFringe))
    }
  }

  /** The fastest fringe frequency of a record (Hz): the 99.9th percentile of the phase step between neighbouring samples,
    * from the signals' angle about their mid-ranges (on pairs a few samples apart, enough for a percentile).
    */
  def fastestFringeHz(rec: Recording): Double = {
    val ys = rec.sin; val yc = rec.cos; val adc = rec.adc; val n = rec.length
    def mid(a: Array[Int]) = { var lo = Int.MaxValue; var hi = Int.MinValue; var i = 0
      while (i < n) { val v = adc.fromPins(a(i)); lo = math.min(lo, v); hi = math.max(hi, v); i += 97 }
      0.5 * (lo + hi) }
    val (ms, mc) = (mid(ys), mid(yc))
    val bins = 4096; val h = new Array[Long](bins); var m = 0L; var i = 0
    def ang(k: Int) = math.atan2(adc.fromPins(ys(k)) - ms, adc.fromPins(yc(k)) - mc)
    while (i + 1 < n) {
      var d = math.abs(ang(i + 1) - ang(i)); if (d > math.Pi) d = 2 * math.Pi - d
      h(math.min(bins - 1, (d / math.Pi * bins).toInt)) += 1; m += 1; i += 7
    }
    var k = 0; var c = 0L
    while (k < bins && c < 0.999 * m) { c += h(k); k += 1 }
    (k.toDouble / bins) * 0.5 * rec.sampleRateHz
  }

  /** Every d-th sample from the r-th (and of every extra column), at 1/d of the sample rate. */
  def pick(rec: Recording, d: Int, r: Int): Recording = {
    val m = (rec.length - r + d - 1) / d
    def every[A: scala.reflect.ClassTag](a: Array[A]): Array[A] = Array.tabulate(m)(j => a(j * d + r))
    val meta = rec.meta ++ rec.meta.get("samples").map(_ => "samples" -> m.toString) ++
      rec.meta.get("sample_rate_hz").map(_ => "sample_rate_hz" -> (rec.sampleRateHz / d).toString)
    rec.copy(sampleRateHz = rec.sampleRateHz / d, sin = every(rec.sin), cos = every(rec.cos), meta = meta,
      extra = rec.extra.map { case (k, v) => k -> every(v) })
  }

  /** One subsample's fit of the searched model: its findings refreshed, rms, samples, bad data (as rows of the whole
    * record), the lines' phases (radian) with their sd, and each line's Gauss-Newton frequency step (Hz) with its sd.
    */
  private final case class Fit(findings: Seq[Finding], rms: Double, n: Int, glitches: Seq[(Int, Double)],
                               dropouts: Seq[(Int, Int)], lines: Seq[(Double, Double, Double)], steps: Map[Double, (Double, Double)],
                               misfit: Int)

  private def fitOf(e: SignalEngine, found: Seq[Finding], d: Int, r: Int, glitches: Seq[(Int, Double)], dropouts: Seq[(Int, Int)]): Fit = {
    val v = e.meanSquare
    // each line's phase on the sin channel: a sin(w t) + b cos(w t) = A sin(w t + atan2(b, a))
    val terms = e.spec.terms.collect { case t: Term.Interference if e.termIndex.contains(t) => t }
    val lines = terms.map { t =>
      val at = e.termIndex(t); val (a, b) = (e.sol.beta(at), e.sol.beta(at + 1))
      val sd = math.sqrt(math.max(0, 0.5 * (e.sol.inv(at)(at) + e.sol.inv(at + 1)(at + 1))) * v)
      (t.hz, math.atan2(b, a), sd / math.max(1e-300, math.hypot(a, b)))
    }
    val steps = terms.map { t => val at = e.termIndex(t); t.hz -> effects.Interference.frequencyStep(e, t.hz, e.sol.beta.slice(at, at + 4)) }.toMap
    Fit(found.map(f => SignalExplain.refresh(f, e)), e.rms, e.n, glitches.map { case (i, l) => (i * d + r, l) },
      dropouts.map { case (a, b) => (a * d + r, (b - 1) * d + r + 1) }, lines, steps,
      // windows where the model does not follow this subsample (`Adequacy`; the search's own passed its judgement)
      if (r == 0) 0 else Laps("confirm: adequacy")(Adequacy.windows(e).count(_.ratio > Adequacy.Margin)))
  }

  /** The searched subsample's result with its findings confirmed on all the others, or the whole record's (`all`). */
  def explain(file: String, rec: Recording, d: Int, progress: Progress, holdBytes: Long, all: Recording => Result,
              searched: Result => Unit): Result =
    search(file, rec, d, all, searched) match {
      case Left(res) => res
      case Right(s) =>
        val fits = s.fit0 +: {
          progress.phase(s"fit again on the other ${d - 1} of $d interleaved subsamples", d - 1)
          (1 until d).map { r =>
            val sub = pick(rec, d, r)
            val e = new SignalEngine(sub, Reference.of(sub).fold(m => throw new ExplainError(s"$file: $m"), identity), holdBytes)
            Laps("confirm: default fit")(e.init())
            val (dropouts, glitches0) = Laps("confirm: bad data")(SignalExplain.badData(e))
            e.spec = s.spec; Laps("confirm: converge")(e.converge()); Laps("confirm: settle")(SignalExplain.settle(e))
            val glitches = Laps("confirm: glitches")(Glitches.more(e, glitches0))
            val f = fitOf(e, s.found, d, r, glitches, dropouts)
            progress.step(1); f
          }
        }
        fits.zipWithIndex.find(_._1.misfit > 0).map { case (f, r) =>
          s"it does not follow subsample $r in ${f.misfit} of ${Adequacy.Windows} windows" }.orElse(disagreement(fits, d, rec.sampleRateHz)) match {
          case Some(why) => whole(rec, all, searched, s"the model found on every $d${ordinal(d)} sample did not hold on the other subsamples ($why)")
          case None => combined(s.result, fits, d, rec.length)
        }
    }

  /** What the search on subsample 0 leaves for the others' fits: its result without engine or snapshots, its fit, the
    * model it found and the findings to refresh.
    */
  private final case class Searched(result: Result, fit0: Fit, spec: ModelSpec, found: Seq[Finding])

  /** The search on subsample 0, or the whole record's result where that search cannot stand for it. The search's engine
    * (hundreds of MB at 20 M samples) is referenced from this method's frame alone: gone once it returns, before the
    * other subsamples are fitted.
    */
  private def search(file: String, rec: Recording, d: Int, all: Recording => Result, searched: Result => Unit): Either[Result, Searched] = {
    // a subsample refused (an arc too short, no fringe) may be the subsample's fault: all samples have their say
    val r1 = try all(pick(rec, d, 0)) catch {
      case x: ExplainError => return Left(whole(rec, all, searched, s"the search on every $d${ordinal(d)} sample refused it (" +
        x.getMessage.stripPrefix(s"$file: ").takeWhile(_ != ':') + ")"))
    }
    // where the model does not follow the searched subsample, nothing there stands for the record: all samples searched
    if (r1.report.misfit.nonEmpty) return Left(whole(rec, all, searched, s"the model found on every $d${ordinal(d)} sample does not follow it in " +
      s"${r1.report.misfit.size} window${if (r1.report.misfit.size == 1) "" else "s"}"))
    // structure the subsample's model does not explain: all samples have their say where that costs no more than a few
    // times the search (the note says the rest)
    if (r1.report.unexplained.nonEmpty && rec.length <= WholeIfUnexplained) return Left(whole(rec, all, searched,
      s"the model found on every $d${ordinal(d)} sample leaves ${r1.report.unexplained.size} departure${if (r1.report.unexplained.size == 1) "" else "s"} unexplained"))
    // a motion that took the subsample's shortest trajectory segments may bend faster than they follow: all samples
    // allow segments of the same length in samples, d times shorter in time (a 2 kHz shake at 1 MS/s on every 2nd
    // sample: 2 x the noise floor left, 1 x on all samples)
    r1.engine.traj match {
      case t: Trajectory if t.nseg > 1 && t.shortest <= Trajectory.MinLength =>
        return Left(whole(rec, all, searched, f"the motion took the shortest trajectory segments on every $d${ordinal(d)} sample " +
          f"(${t.shortest} samples, ${t.shortest * d / rec.sampleRateHz * 1e6}%.0f us): all samples follow it in shorter ones"))
      case _ =>
    }
    val found = r1.report.findings.filterNot(_.deltaBic.isNaN)
    val fit0 = fitOf(r1.engine, found, d, 0, r1.glitches, r1.dropouts)
    // the engine is read by `searched` alone from here (its plots may be drawn beside the other subsamples' fits)
    searched(r1)
    Right(Searched(r1.copy(engine = null, before = null, steps = r1.steps.map { case (f, _, _) => (f, null, null) }),
      fit0, r1.engine.spec, found))
  }

  /** All samples searched, and why. */
  private def whole(rec: Recording, all: Recording => Result, searched: Result => Unit, why: String): Result = {
    val res = all(rec); searched(res)
    res.copy(report = res.report.copy(notes = res.report.notes :+ s"explained on all ${rec.length} samples: $why"))
  }

  private def ordinal(d: Int): String = if (d % 100 / 10 == 1) "th" else d % 10 match { case 1 => "st"; case 2 => "nd"; case 3 => "rd"; case _ => "th" }

  /** Why the subsamples' fits disagree (a finding's parameter, a line's phase), or None. */
  private def disagreement(fits: Seq[Fit], d: Int, fs: Double): Option[String] = {
    val limit = new ChiSquaredDistribution(d - 1).inverseCumulativeProbability(1 - Tail)
    val params = fits.head.findings.indices.iterator.flatMap { j =>
      val f = fits.head.findings(j)
      f.params.keys.toSeq.sorted.iterator.flatMap { k =>
        val (vs, sds) = series(fits, j, k)
        if (vs.exists(_.isNaN)) None
        else if (!stated(sds)) {
          // a discrete value (a bit, an order) must be the same; one without an sd that is no whole number describes
          // the subsample (a contrast change's travel_periods: each subsample's own travel, a sample apart)
          if (vs.forall(v => v == math.rint(v)) && vs.distinct.size > 1) Some(s"${f.effect} $k: ${vs.distinct.mkString(", ")}") else None
        } else {
          val (mean, _, chi2) = pooled(vs, sds)
          if (chi2 > limit) Some(f"${f.effect} $k: ${vs.min}%.5g..${vs.max}%.5g about $mean%.5g, chi-square $chi2%.1f for ${d - 1} degrees of freedom") else None
        }
      }
    }
    // a line's phase in subsample r leads subsample 0's by w r / fs (sample r of the whole record is its first)
    val phases = fits.head.lines.indices.iterator.flatMap { j =>
      val (hz, p0, s0) = fits.head.lines(j)
      val chi2 = fits.zipWithIndex.tail.map { case (f, r) =>
        val (_, p, s) = f.lines(j); val w = p - p0 - 2 * math.Pi * hz * r / fs
        val dw = w - 2 * math.Pi * math.rint(w / (2 * math.Pi))
        dw * dw / (s * s + s0 * s0)
      }.sum
      if (s0 < 0.3 && chi2 > limit) Some(f"the $hz%.1f Hz line's phase does not advance between the subsamples as its frequency says " +
        f"(chi-square $chi2%.1f): a line above ${fs / d / 2}%.4g Hz seen at its alias") else None
    }
    (params ++ phases).nextOption()
  }

  /** Runs of rows joined where they overlap or lie less than d rows apart (each subsample sees every d-th row of one). */
  private def merged(runs: Seq[(Int, Int)], d: Int): Seq[(Int, Int)] =
    runs.foldLeft(List.empty[(Int, Int)]) {
      case ((a, b) :: rest, (c, e)) if c < b + d => (a, math.max(b, e)) :: rest
      case (acc, x) => x :: acc
    }.reverse

  /** Finding j's parameter k in each subsample's fit, and its sd there (the search's where a fit states none). */
  private def series(fits: Seq[Fit], j: Int, k: String): (Seq[Double], Seq[Double]) = {
    val sd = fits.head.findings(j).unc.getOrElse(k, Double.NaN)
    val vs = fits.map(_.findings(j).params.getOrElse(k, Double.NaN))
    // an angle (degree) as near the first subsample's as a whole turn allows: a harmonic's phase at -179.98 and 179.98
    // is one phase (it read as a chi-square of 14,941,776 and all samples searched again)
    val near = if (k.endsWith("_deg") && !vs.head.isNaN) vs.map(v => v - 360 * math.rint((v - vs.head) / 360)) else vs
    (near, fits.map(_.findings(j).unc.getOrElse(k, sd)))
  }
  /** Every sd positive and finite: the values can be pooled. */
  private def stated(sds: Seq[Double]): Boolean = sds.forall(s => s > 0 && !s.isInfinite)

  /** Inverse-variance mean, its sd and the chi-square of the values about it. */
  private def pooled(vs: Seq[Double], sds: Seq[Double]): (Double, Double, Double) = {
    val w = sds.map(s => 1 / (s * s)); val sw = w.sum
    val mean = vs.zip(w).map { case (v, x) => v * x }.sum / sw
    (mean, 1 / math.sqrt(sw), vs.zip(w).map { case (v, x) => (v - mean) * (v - mean) * x }.sum)
  }

  private def combined(r0: SignalExplain.Result, fits: Seq[Fit], d: Int, n: Int): SignalExplain.Result = {
    val rep = r0.report
    val searched = rep.findings.filterNot(_.deltaBic.isNaN)
    val found = fits.head.findings.indices.map { j =>
      val f = fits.head.findings(j)
      // a line's frequency: the search's, moved by the subsamples' Gauss-Newton steps combined; its sd stays the search's
      // (one step goes part of the way: the bench's 20 M line moved from 0.00086 to 0.00067 Hz off, 4 sd of the step's own)
      val line = f.params.get("frequency_hz").filter(_ => f.effect == effects.Interference.name).flatMap(hz =>
        if (fits.forall(_.steps.get(hz).exists { case (st, sd) => !st.isNaN && sd > 0 && !sd.isInfinite })) Some(hz -> fits.map(_.steps(hz))) else None)
      val ps = f.params.map {
        case ("frequency_hz", _) if line.isDefined =>
          val (hz, st) = line.get; val (m, s, chi2) = pooled(st.map(_._1), st.map(_._2))
          ("frequency_hz", (hz + m, math.max(f.unc.getOrElse("frequency_hz", 0.0), s * math.sqrt(math.max(1.0, chi2 / (d - 1))))))
        case (k, _) =>
        val (vs, sds) = series(fits, j, k)
        // a parameter the other fits kept at the search's value (a line's frequency, a warm-up's time constant): the search's
        if (vs.exists(_.isNaN) || !stated(sds) || vs.distinct.size == 1) (k, (vs.head, sds.head))
        else { val (m0, s, chi2) = pooled(vs, sds)
          // an angle back within -180..180 degree
          val m = if (k.endsWith("_deg") && math.abs(m0) > 180) m0 - 360 * math.rint(m0 / 360) else m0
          (k, (m, s * math.sqrt(math.max(1.0, chi2 / (d - 1))))) }
      }
      searched(j).copy(params = ps.map { case (k, v) => k -> v._1 }, unc = ps.map { case (k, v) => k -> v._2 })
    }
    val byOrig = searched.zip(found).toMap
    val rms = math.sqrt(fits.map(f => f.rms * f.rms * f.n).sum / fits.map(_.n).sum)
    val glitches = fits.flatMap(_.glitches).sortBy(_._1); val dropouts = merged(fits.flatMap(_.dropouts).sortBy(_._1), d)
    val old = (Glitches.note(r0.glitches) ++ Dropouts.note(r0.dropouts)).toSet
    val others = if (d == 2) "the other interleaved subsample" else s"the other ${d - 1} interleaved subsamples"
    val note = s"searched on every ${d}${ordinal(d)} sample (${fits.head.n} of $n samples, each at ${d} x the sample interval); the model found " +
      s"was fitted again on $others, and each finding's parameters, the same on all ${d} within their uncertainty, are their " +
      "combined values over all samples (a line's frequency moved by their combined steps, with the search's sd; a warm-up's time constant is the search's). The BIC figures " +
      "and located departures are the searched subsample's; the final rms is over all samples" +
      // a long record's structure left unexplained on the subsample: the search on all samples was not made
      (if (rep.unexplained.isEmpty) "" else s". The departures left unexplained on the subsample were not searched on all samples " +
        s"(above $WholeIfUnexplained samples; --search-samples 0 searches all, in far more time and memory)")
    val report = rep.copy(findings = rep.findings.map(f => byOrig.getOrElse(f, f)), finalRms = rms, samples = n,
      notes = note +: (rep.notes.filterNot(old) ++ Glitches.note(glitches) ++ Dropouts.note(dropouts)))
    val steps = r0.steps.map { case (f, b, a) => (found.find(g => g.effect == f.effect && g.channel == f.channel && g.where == f.where).getOrElse(f), b, a) }
    r0.copy(report = report, steps = steps, glitches = glitches, dropouts = dropouts)
  }
}
