package moire.explain

import moire.explain.effects._

import moire.recording.{Recording, Reference}

/** One accepted effect, as reported. `before`/`after` are the residuals around its acceptance (for plots). */
final case class Finding(effect: String, channel: String, summary: String, params: Map[String, Double], unc: Map[String, Double],
                         deltaBic: Double, rmsBefore: Double, rmsAfter: Double, where: String, sizeLsb: Double = Double.NaN,
                         lookAlikes: Seq[String] = Nil) {
  def json: ujson.Obj = ujson.Obj("effect" -> effect, "channel" -> channel, "summary" -> summary,
    "params" -> Report.nums(params), "uncertainty" -> Report.nums(unc), "delta_bic" -> Report.num(deltaBic),
    "rms_before" -> Report.num(rmsBefore), "rms_after" -> Report.num(rmsAfter), "where" -> where,
    "size_lsb" -> Report.num(sizeLsb), "look_alikes" -> ujson.Arr(lookAlikes.map(ujson.Str(_)): _*))
}

/** Residuals for the plots: every `stride`-th sample (at most `Snapshot.MaxPoints`), and the first
  * `Snapshot.SpectrumPoints` samples in full for the spectrum. A long record's plots cost a bounded copy.
  */
final case class Snapshot(label: String, stride: Int, resS: Array[Double], resC: Array[Double], headS: Array[Double], headC: Array[Double]) {
  /** Points held; point j is sample j * stride. */
  def size: Int = resS.length
  /** The first samples in full, for a spectrum. */
  def headSin: Array[Double] = if (headS == null) resS else headS
  def headCos: Array[Double] = if (headC == null) resC else headC
}
object Snapshot {
  val MaxPoints: Int = 1 << 19
  val SpectrumPoints: Int = 1 << 18
  def of(label: String, rs: Array[Double], rc: Array[Double]): Snapshot = {
    val n = rs.length
    val stride = (n + MaxPoints - 1) / MaxPoints
    if (stride == 1) Snapshot(label, 1, rs.clone(), rc.clone(), null, null)
    else {
      def every(a: Array[Double]) = Doubles.tabulate((n + stride - 1) / stride)(j => a(j * stride))
      val h = math.min(n, SpectrumPoints)
      Snapshot(label, stride, every(rs), every(rc), java.util.Arrays.copyOf(rs, h), java.util.Arrays.copyOf(rc, h))
    }
  }
}

/** explain for signal recordings: default fit, locate, greedy effect search by BIC, final locate. */
object SignalExplain {
  /** Accept an effect only when it lowers BIC by more than this (strong evidence on the Kass-Raftery scale). */
  val Threshold = 10.0
  /** Candidates refitted per round before the search stops (each costs a joint refit and its replication). */
  val MaxTries = 3


  /** `rerun`: the windows where the model does not follow, when the search is to be made again without them. */
  final case class Result(report: Report, engine: SignalEngine, before: Snapshot, steps: Seq[(Finding, Snapshot, Snapshot)],
                          rerun: Seq[Adequacy.Window] = Nil, glitches: Seq[(Int, Double)] = Nil, dropouts: Seq[(Int, Int)] = Nil)

  /** The backward model of given effects; an effect named twice is one term. */
  def specOf(model: Seq[EffectSpec]): ModelSpec = {
    val sp = model.foldLeft(ModelSpec())((sp, e) => Effects(e.effect).fold(sp)(_.backward(sp, e)))
    sp.copy(terms = sp.terms.distinct, faults = sp.faults.distinct, clips = sp.clips.distinct)
  }

  /** Explains a recording. A long one is searched on an interleaved subsample and confirmed on the others
    * (`Interleaved`; `searchSamples` is the longest searched whole). `searched` gets the search's result while its
    * engine and snapshots are alive (plots are made from them); a long record's result returned holds them no more
    * (null: the confirmation's fits need their memory).
    */
  def run(file: String, rec: Recording, model: Seq[EffectSpec], progress: Progress, maxFindings: Int = 8,
          holdBytes: Long = SignalEngine.HoldBytes, materiality: Materiality = Materiality(),
          searchSamples: Int = Interleaved.SearchSamples, searched: Result => Unit = _ => ()): Result = {
    val t0 = System.nanoTime()
    def all(r: Recording) = whole(file, r, model, progress, maxFindings, holdBytes, materiality)
    val d = Interleaved.factor(rec, searchSamples)
    // the fitted ellipse, for the steps of the phase over all samples (a step in a subsample is d samples wide)
    var base: Array[Double] = null
    def seen(r: Result): Unit = { base = r.engine.base.clone(); searched(r) }
    val res = if (d == 1) { val r = all(rec); seen(r); r } else Interleaved.explain(file, rec, d, progress, holdBytes, all, seen)
    val steps = if (base == null) None else Jumps.note(Laps("steps")(Jumps.inRecord(rec, base, badRows(rec.length, res))), rec.sampleRateHz)
    res.copy(report = res.report.copy(seconds = (System.nanoTime() - t0) / 1e9, notes = res.report.notes ++ steps))
  }

  /** The rows of bad data (glitches, runs lost) of a result, as a test. */
  private def badRows(n: Int, r: Result): Int => Boolean = {
    val m = new java.util.BitSet(n)
    r.glitches.foreach { case (i, _) => m.set(i) }
    r.dropouts.foreach { case (a, b) => m.set(a, b) }
    i => m.get(i)
  }

  /** Explains a recording on all its samples. Adequacy first: where the final model does not follow the signal in some
    * windows but does in others, the search is made again with those windows weighted out (effects fitted and judged
    * where it follows).
    */
  private def whole(file: String, rec: Recording, model: Seq[EffectSpec], progress: Progress, maxFindings: Int,
                    holdBytes: Long, materiality: Materiality): Result = {
    val t0 = System.nanoTime()
    var res = search(file, rec, model, progress, maxFindings, holdBytes, materiality, Nil, 0)
    var depth = 0
    // the last search's engine goes before the next is made (two at once: twice the heap)
    while (res.rerun.nonEmpty && depth < MaxReruns) { depth += 1; val prior = res.rerun; res = null; res = search(file, rec, model, progress, maxFindings, holdBytes, materiality, prior, depth) }
    res.copy(report = res.report.copy(seconds = (System.nanoTime() - t0) / 1e9))
  }
  /** Two candidates whose gains differ by less than this share of the larger predict the same signal here (a 0.3 % 2nd
    * harmonic on both channels at a constant 5 kHz and a line at 10.00001 kHz: 718002 and 718021).
    */
  val SameSignal = 1e-3

  /** Searches made again with more windows weighted out, at most. */
  val MaxReruns = 2

  /** One search with the windows `prior` weighted out after the default fit; the result's `rerun` lists the windows
    * to leave out when the search should be made again without them (empty: this one stands).
    */
  private def search(file: String, rec: Recording, model: Seq[EffectSpec], progress: Progress, maxFindings: Int,
                     holdBytes: Long, materiality: Materiality, prior: Seq[Adequacy.Window], depth: Int): Result = {
    val t0 = System.nanoTime()
    val timing = sys.props.contains("moire.timing")
    var tl = t0
    def lap(what: String): Unit = if (timing) { val now = System.nanoTime(); System.err.println(f"$what ${(now - tl) / 1e6}%.0f ms"); tl = now }
    val e = new SignalEngine(rec, Reference.of(rec).fold(m => throw new ExplainError(s"$file: $m"), identity), holdBytes)
    progress.phase("default fit", 4)
    e.init(); progress.step(4)
    noFringe(e).foreach(why => throw new ExplainError(s"$file: $why"))
    val givenModel = specOf(model)
    if (givenModel != ModelSpec()) { e.spec = givenModel; e.converge(); settle(e) }
    // isolated samples far off the signal: glitches of the data, out of the fit from here on (and named in the notes)
    // (a second look once they are out: a glitch pulls the fit's phase, and its neighbours' residual with it)
    // runs of samples lost (both channels held still, or at an end code, while the signal moves on): out, and named
    val (dropouts, glitches0) = badData(e)
    var glitches = glitches0
    val glitchMask = Glitches.union(Glitches.mask(e.n, glitches), Dropouts.mask(e.n, dropouts))
    val baseRms = e.rms; val baseBic = e.bic
    // the noise of the default part where the model does not follow somewhere (or nowhere): the floor, not the misfit
    val noiseMask = Glitches.union(Adequacy.maskOf(e, prior), glitchMask)
    val floorNoise = (Adequacy.noiseOf(e.resS, noiseMask), Adequacy.noiseOf(e.resC, noiseMask))
    val baseParams0 = baselineParams(e)
    val before = Snapshot.of("default model", e.resS, e.resC)
    if (prior.nonEmpty) { e.exclude(noiseMask); settle(e) }
    lap("default fit")
    val located = Locate.all(e)
    val negligible = Seq.newBuilder[Negligible]
    lap("locate")
    val steps = Seq.newBuilder[(Finding, Snapshot, Snapshot)]
    var done = false; var round = 0
    val rejected = scala.collection.mutable.ArrayBuffer.empty[Located]
    // material structure that replicates but that the record cannot tell from an alternative (a drift at one speed in one
    // direction, or a contrast change along that travel): fitted, so that the model follows the signal and the rest is
    // assessed, and listed as unexplained with what it cannot be told from, never as a finding
    val unnamed = scala.collection.mutable.ArrayBuffer.empty[Located]; val unnamedEffects = scala.collection.mutable.Set.empty[String]
    while (!done && round < maxFindings) {
      val cands = new Candidates(e)
      progress.phase(s"effects, round ${round + 1}", cands.steps)
      val all = cands.all(() => progress.step(1))
      lap("candidates")
      // (the round's parameter count: a trial's refit adds its own, and a reject after it told a gain of 25 as -39)
      val bic0 = e.bic; val params0 = e.params
      def dbic(c: Cand) = bic0 - (c.m2ll + (params0 + c.extraK) * e.lnN)
      // Candidates whose parameters the recording cannot support are not findings; what still fits that way after
      // the last accepted effect is unexplained structure (earlier rounds' rejects may be another effect's shadow).
      rejected.clear()
      val (ok, impossible) = all.filter(c => !dbic(c).isNaN && Identifiable.why(c, e, cands.fMin, cands.fMax).isEmpty)
        .partition(c => unsupported(c, e, cands).isEmpty)
      impossible.filter(c => dbic(c) > Threshold && !rejected.exists(_.where.startsWith(c.effect + " "))).foreach { c =>
        rejected += Located(s"${c.effect} (${c.channel})", s"structure of this shape lowers BIC by ${"%.0f".format(dbic(c))}, but not physically: " +
          unsupported(c, e, cands).get, c.params, significant = true)
      }
      // The strongest candidates in turn: the first that the record can support is the finding. Quantization and
      // identifiability are checked on the candidate; replication on the halves after the joint refit that accepts it
      // (before it, the trajectory and the default part still hold part of the effect, differently in each half).
      val passing = ok.filter(c => dbic(c) > Threshold)
      if (SignalEngine.debug) System.err.println(s"round ${round + 1}: passing " + passing.sortBy(-dbic(_)).map(c => f"${c.effect}/${c.channel} ${dbic(c)}%.0f").mkString(", ") + s"; all ${all.size}: " + all.map(c => f"${c.effect}/${c.channel} ${dbic(c)}%.0f").mkString(", "))
      // A pile-up at one code is direct evidence in the histogram that no smooth effect makes: such repairs go first. An effect that yields to a look-alike predicting the same signal (within the
      // threshold, or `SameSignal` of what the two explain) stands back for it: it is tried after the look-alike (when that fails its tests); the finding names it.
      def yields(c: Cand) = Effects(c.effect).exists(f => passing.exists(o => o != c && f.yieldsTo(c, o, e) &&
        dbic(o) > dbic(c) - math.max(Threshold, SameSignal * dbic(c))))
      val ordered = passing.sortBy(c => (!Effects(c.effect).exists(_.direct), yields(c), -dbic(c))).iterator
      def reject(c: Cand, why: String): Unit =
        if (!rejected.exists(_.where.startsWith(c.effect + " ")))
          rejected += Located(s"${c.effect} (${c.channel}): ${c.where}", s"structure of this shape lowers BIC by ${"%.0f".format(dbic(c))}, but $why",
            c.params, significant = true)
      var accepted = false; var tries = 0; var smallTries = 0
      // effects this round's joint refits showed not to replicate: the record refutes them, so they are no alternative
      // that a change in time or along the travel could not be told from
      val refuted = scala.collection.mutable.Set.empty[String]
      while (!accepted && tries < MaxTries && ordered.hasNext) {
        val c = ordered.next()
        // what the record cannot tell from an alternative is still measured when the budget for small ones allows: too
        // small to matter, it is negligible (a drift of 0.08 LSB was "unexplained: cannot tell it from a contrast change")
        val quant = Quantization.why(e, c)
        val confound = if (quant.isDefined) None else Identify.confound(e, c, refuted.toSet)
        val ident = confound.map(_._2)
        (if (quant.isDefined) quant else if (ident.isDefined && smallTries >= MaxTries) ident else None) match {
          case Some(why) => if (SignalEngine.debug) System.err.println(s"not tried ${c.effect}/${c.channel}: $why"); reject(c, why)
          case None =>
            // (an unidentifiable one's trial is paid from the budget for small ones, not the round's tries)
            if (ident.isDefined) smallTries += 1 else tries += 1
            val snapB = Snapshot.of(s"before ${c.effect}", e.resS, e.resC)
            val rmsB = e.rms; val predB = Materiality.Points.of(e)
            // the located departures the effect claims, before and after (only those tests are run)
            val claims = Effects(c.effect).map(_.claims).getOrElse(Nil)
            def claimedNow = if (claims.isEmpty) Nil else Locate.all(e, w => claims.exists(w.startsWith))
            val before = claimedNow
            val prev = e.spec
            // the fit before the trial, to go back to when it is not kept (the reference path fits the old spec again)
            val back = if (FitPath.isReference) None else e.save()
            e.spec = c.spec; e.converge(tune = lineTune(e, prev)); settle(e)
            val c1 = retune(e, prev, demote(e, prev, c))
            lap("refit")
            // materiality first: the change it makes to the signal, against the floor. What lowers the criterion but is
            // smaller is too small to matter, whatever its halves say (and their refits are not needed)
            val fx = Effects(c1.effect)
            lazy val size = fx.map(_.size(c1, e)).filter(!_.isNaN).orElse(termSize(e, prev))
              .getOrElse(Materiality.size(predB, Materiality.Points.of(e)))
            // the noise is the floor from neighbouring samples: the model's residual still holds the effects not yet fitted
            lazy val floor = materiality.floor(e.lsb, Adequacy.floor(e))
            // no finding when the joint refit does not lower the criterion, the effect is negligible or does not replicate
            val why = if (!(bic0 - e.bic > 0)) Some("") else if (size < floor) Some("negligible")
              else if (ident.isDefined) ident
              else { val r = Replicate.why(e, prev); if (r.isDefined) refuted += c.effect; r }
            // (a linear change in time that the record cannot tell from a linear one along the travel, or the reverse, is
            // kept, unnamed, when it is material and replicates: the two are one column at one speed. One it cannot tell
            // from harmonics of the fringe or from a change with speed stays out: those are candidates of their own, found
            // in their turn; and so does a warm-up, whose five parameters a partial likeness would let take up other
            // structure: a 0.1 LSB drift on a chirp was fitted as a warm-up of 0.12 s)
            val linear = c.spec.terms.diff(prev.terms).headOption.exists(t => t == Term.Drift || t == Term.Contrast)
            val unnamedNow = linear && ident.isDefined && why == ident && confound.exists(x => x._1 == Identify.Travel || x._1 == Identify.Time) &&
              Replicate.why(e, prev).isEmpty
            lap("replicate")
            if (SignalEngine.debug) System.err.println(s"tried ${c.effect}/${c.channel}: " + why.orElse(claimed(claims, before, claimedNow)).fold("kept")(w => if (w.isEmpty) "no gain" else w))
            // what the model now follows because of the change: glitches its misfit hid stand out; the motion may not
            // need the shorter segments its misfit asked for (only after a change in time, which the default fit's phase
            // may have followed as motion: after clipping, the longer segments won by BIC while the other channel's
            // clipping was still in the residual, and a slow back-and-forth ended misfit)
            def changed(): Unit = {
              round += 1; accepted = true
              glitches = Glitches.more(e, glitches)
              if (Effects(c1.effect).exists(x => x.domain == effects.Domain.Settling || x.domain == effects.Domain.Time) && e.relengthen()) {
                researchWarmup(e); lap("longer segments")
              }
            }
            if (unnamedNow) {
              // named by both effects, in one order whichever of the two was tried (its parameters are the one's fitted)
              val both = Seq(c1.effect, if (confound.get._1 == Identify.Travel) effects.ContrastAlongTravel.name else effects.Drift.name).distinct.sorted
              unnamedEffects ++= both
              unnamed += Located(s"${both.mkString(" or ")} (${c1.channel}): ${c1.where}", f"structure of this shape lowers BIC by ${bic0 - e.bic}%.0f and changes " +
                f"the signal by ${size / e.lsb}%.1f LSB, but ${ident.get}; fitted, unnamed, so that the rest of the record is assessed", c1.params, significant = true)
              changed()
            } else
            why.orElse(claimed(claims, before, claimedNow)) match {
              case Some(w) =>
                if (w == "negligible") {
                  // too small is not failed evidence: it does not use up the round's tries (its own budget bounds the cost)
                  if (ident.isEmpty && smallTries < MaxTries) { smallTries += 1; tries -= 1 }
                  val g = refresh(Finding(c1.effect, c1.channel, "", c1.params, c1.unc, bic0 - e.bic, rmsB, e.rms, c1.where), e)
                  val what = fx.fold(c1.where)(_.summary(g.params, g.channel, cands.fMin, cands.fMax))
                  negligible += Negligible(g.effect, g.channel, size / e.lsb, floor / e.lsb, bic0 - e.bic, g.params, what)
                }
                else if (w.nonEmpty) reject(c, w)
                back match { case Some(r) => r(); case None => e.spec = prev; e.converge(); settle(e) }
              case None =>
                val snapA = Snapshot.of(s"after ${c.effect}", e.resS, e.resC)
                steps += ((Finding(c1.effect, c1.channel, "", c1.params, c1.unc, bic0 - e.bic, rmsB, e.rms, c1.where, size / e.lsb), snapB, snapA))
                changed()
            }
        }
      }
      if (!accepted) done = true
    }
    // each finding must still matter in the final joint fit: one whose linear part an effect found after it took over
    // (the two predict nearly the same signal in this record) is listed as negligible, naming that effect
    val floorEnd = materiality.floor(e.lsb, Adequacy.floor(e))
    val found = steps.result()
    val taken = found.zipWithIndex.flatMap { case ((f, _, _), j) =>
      termOf(e, f).flatMap(t => partSize(e, t)).filter(_ < floorEnd).map(sz => j -> sz)
    }.toMap
    val cands = new Candidates(e)
    taken.toSeq.sortBy(_._1).foreach { case (j, sz) =>
      val g = refresh(found(j)._1, e)
      negligible += Negligible(g.effect, g.channel, sz / e.lsb, floorEnd / e.lsb, g.deltaBic, g.params,
        Effects(g.effect).fold(g.where)(_.summary(g.params, g.channel, cands.fMin, cands.fMax)), found.drop(j + 1).map(_._1.effect).distinct)
    }
    val fin = found.zipWithIndex.filterNot(x => taken.contains(x._2)).map(_._1).map { case (f, b, a) =>
      val g = refresh(f, e)
      val fx = Effects(g.effect)
      (g.copy(summary = fx.fold(g.effect)(_.summary(g.params, g.channel, cands.fMin, cands.fMax)),
        lookAlikes = fx.toSeq.flatMap(_.lookAlikes(g, e))), b, a)
    }
    // negligible structure (significant, below the floor) stays in the residual: its located departure is listed there
    val small = negligible.result().groupBy(x => (x.effect, x.channel)).values.map(_.last).toSeq
    val smallClaims = small.flatMap(x => Effects(x.effect).toSeq.flatMap(_.claims))
    // a significant departure smaller than the floor is no structure to explain: a note (a clean S-curve's dwells: the
    // trajectory's phase at a standstill left "sin amplitude -33.6 %, 802 sd" of a fundamental 2e-5 of full scale there)
    // (a departure a negligible effect claims is its: unless it is itself above the floor, which that effect is not; a
    // 2 LSB line sweeping 5 to 8 kHz left 0.26 LSB in one bin beside a negligible 0.12 LSB pickup, listed nowhere)
    def material(l: Located) = l.params.get(Locate.SizeLsb).forall(_ >= floorEnd / e.lsb)
    def above(l: Located) = l.params.get(Locate.SizeLsb).orElse(l.params.get(Locate.AtLeastLsb)).exists(_ >= floorEnd / e.lsb)
    val (left, tiny) = Locate.all(e).filter(l => l.significant && (!smallClaims.exists(l.where.startsWith) || above(l))).partition(material)
    val tinyNotes = tiny.map(l => f"${l.where}: ${l.summary}; the residual departs by ${l.params(Locate.SizeLsb)}%.3g LSB there " +
      f"(floor ${floorEnd / e.lsb}%.3g LSB): significant, too small to matter")
    // with a free motion that bends within a period, what is left cannot be told from the motion: not tested, not unexplained
    val confounded = Identifiable.motionConfounded(e)
    val finalRms = e.rms; val finalBic = e.bic
    // adequacy: where the model does not follow the signal. Where it follows over less than half the record, nothing
    // fitted is a finding; where it follows over more, the search is made again on the windows that follow (the caller)
    // and this one is dropped.
    // Windows that stand out are left out first (the rest may hold an effect the misfit kept the search from fitting).
    val (stand, rest) = Adequacy.judge(e, prior)
    val notHere = (prior ++ stand ++ rest).sortBy(_.a)
    val again = depth < MaxReruns
    val rerun = if (stand.nonEmpty && again && Adequacy.assessable(e, prior ++ stand)) (prior ++ stand).sortBy(_.a)
      else if ((stand ++ rest).nonEmpty && again && Adequacy.assessable(e, notHere)) notHere else Nil
    val follows = Adequacy.assessable(e, notHere) || rerun.nonEmpty
    val misfit = Adequacy.misfit(e, notHere)
    val withdrawn = if (follows) Nil else fin.map { case (f, _, _) =>
      Located(s"${f.effect} (${f.channel}): ${f.where}", f"fitted while the default model does not follow the signal over more than ${100 * (1 - Adequacy.MinFollowed)}%.0f %% of " +
        f"the record (residual rms above ${Adequacy.Margin}%.0f x the noise floor from neighbouring samples): not assessed", f.params, significant = true)
    }
    val baseParams = if (misfit.isEmpty) baseParams0 else baseParams0 ++ Map("noise_sin_fs" -> floorNoise._1, "noise_cos_fs" -> floorNoise._2)
    val unexplained = (if (confounded || !follows) Nil else left) ++ unnamed ++ rejected.filterNot(r => unnamedEffects(r.where.takeWhile(_ != ' '))) ++ withdrawn
    val coarse = CoarseQuantization.finding(e)
    val shown = if (follows) fin else Nil
    val report = Report(file, "signals", baseRms, baseBic, baseParams, located, coarse ++ shown.map(_._1), unexplained, finalRms, finalBic,
      rec.length, (System.nanoTime() - t0) / 1e9, notes(e) ++ tinyNotes ++ Glitches.note(glitches) ++ Dropouts.note(dropouts), Coverage.untested(e, cands.fMin, cands.fMax) ++
        (if (confounded) Identifiable.leftOver(left) else Nil), small, misfit)
    Result(report, e, before, shown, rerun, glitches, dropouts)
  }

  /** Runs of lost samples and isolated glitches of a fitted engine, weighted out of its fit from here on. */
  private[explain] def badData(e: SignalEngine): (Seq[(Int, Int)], Seq[(Int, Double)]) = {
    val dropouts = Dropouts.find(e)
    if (dropouts.nonEmpty) { e.lost = Dropouts.mask(e.n, dropouts); e.badData = e.lost; e.exclude(null) }
    var glitches = Glitches.find(e)
    if (glitches.nonEmpty) { e.badData = Glitches.union(e.badData, Glitches.mask(e.n, glitches)); e.exclude(null); glitches = Glitches.more(e, glitches) }
    // the motion's local changes that the uniform segments miss, with the bad data out (then a look for more of them)
    if (Laps("split segments")(e.splitSegments())) glitches = Glitches.more(e, glitches)
    (dropouts, glitches)
  }

  /** A new linear term's own part of the prediction (its columns times its coefficients): its size. */
  private def termSize(e: SignalEngine, prev: ModelSpec): Option[Double] = e.spec.terms.diff(prev.terms).headOption.flatMap(partSize(e, _))

  /** The linear term of the current fit that a finding is, if it is one. */
  private def termOf(e: SignalEngine, f: Finding): Option[Term] =
    e.termIndex.keys.find(t => t.name == f.effect && termMatches(t, f))

  /** A linear term's own part of the prediction (its columns times its coefficients in the current fit): its size.
    * Read at the size's points only; a term made a block at a time is never made whole (at 20 M samples its columns
    * and the two parts took 1.3 GB).
    */
  private def partSize(e: SignalEngine, t: Term): Option[Double] =
    Some(t).filter(e.termIndex.contains).map { t =>
      val st = Materiality.strideOf(e.n); val at = e.termIndex(t)
      val part = e.termGen(t).filter(_ => !FitPath.isReference) match {
        case Some(g) => Materiality.Points.ofTerm(e.n, st, g, e.sol.beta.slice(at, at + g.size))
        case None =>
          val cols = e.termCols(t); val b = e.sol.beta.slice(at, at + cols.size)
          def of(sinCh: Boolean)(i: Int): Double = {
            var v = 0.0; var k = 0
            while (k < cols.size) { val a = if (sinCh) cols(k).s else cols(k).c; if (a != null && b(k) != 0) v += b(k) * a(i); k += 1 }
            v
          }
          Materiality.Points(e.n, st, of(sinCh = true), of(sinCh = false))
      }
      // about its mean on each channel: the default part's offsets take that back (a warm-up at its 0.3 s bound on a
      // 0.1 s record, a 0.2 LSB offset step, was "1.06 LSB": the whole step it settles by, not what it changes here)
      def mean(a: Array[Double]) = if (a.isEmpty) 0.0 else a.sum / a.length
      val (ms, mc) = (mean(part.s), mean(part.c))
      Materiality.size(Materiality.Points(st, Array.fill(part.s.length)(ms), Array.fill(part.c.length)(mc)), part)
    }

  /** None when the located departures an effect claims (their chi-square or peak-to-mean, summed) fell from `before`
    * to `after`, or when it claims none that was measured; else why it is not a finding.
    */
  private def claimed(claims: Seq[String], before: Seq[Located], after: Seq[Located]): Option[String] = {
    def stat(ls: Seq[Located]) = ls.filter(l => claims.exists(l.where.startsWith))
      .flatMap(l => l.params.get("chi2_sd").orElse(l.params.get("peak_to_mean"))).filter(!_.isNaN)
    val b = stat(before); val a = stat(after)
    // a test that located nothing before or after says nothing either way: its departure is not what the effect changes
    // there (a 2 % gain drift leaves the residual's means in time at -6.3 sd, and was refused at -0.5 sd after)
    def located(ls: Seq[Located]) = ls.exists(l => l.significant && claims.exists(l.where.startsWith))
    if (b.isEmpty || a.size != b.size || a.sum < b.sum || !located(before) && !located(after)) None
    else Some(f"it does not lower the located departure it claims (${claims.mkString(", ")}: ${b.sum}%.1f before, ${a.sum}%.1f after)")
  }

  /** Why the record cannot support a candidate's parameters (its effect's physics), or None. */
  private def unsupported(c: Cand, e: SignalEngine, cands: Candidates): Option[String] =
    Effects(c.effect).flatMap(_.unsupported(c, e, cands.fMin, cands.fMax))

  /** Parameters of a finding from the final joint fit (linear terms) or the final spec (nonlinear). */
  private[explain] def refresh(f: Finding, e: SignalEngine): Finding = {
    val v = e.meanSquare
    e.termIndex.find { case (t, _) => t.name == f.effect && termMatches(t, f) } match {
      case Some((t, at)) =>
        val cols = e.termCols(t); val k = cols.size
        val b = e.sol.beta.slice(at, at + k)
        val sd = (at until at + k).map(i => math.sqrt(math.max(0, e.sol.inv(i)(i)) * v / e.informationLeft(cols(i - at)))).toArray
        val (p, u, _, _) = t.effect.describe(t, b, sd, e)
        f.copy(params = p, unc = u.map { case (k, x) => k -> (if (x.isNaN) f.unc.getOrElse(k, x) else x) })
      case None => Effects(f.effect).fold(f)(_.refresh(f, e))
    }
  }
  private def termMatches(t: Term, f: Finding): Boolean = t match {
    case Term.Harm(k, ch) => f.params.get("order").contains(k.toDouble) && ch == f.channel
    case Term.Interference(hz) => f.params.get("frequency_hz").contains(hz)
    case Term.Inl(ch) => ch == f.channel
    case Term.ContrastSpline(k) => f.params.get("knots").contains(k.size.toDouble)
    case Term.Contrast => !f.params.contains("knots")
    case Term.AngleHarm(m) => m == 1 || f.params.get("order").contains(m.toDouble)
    case _ => true
  }

  /** A harmonic accepted on both channels whose part on one channel is not significant after the refit
    * (the phase trajectory had leaked it there) becomes a one-channel harmonic. Only the candidate's own harmonic (one
    * that `prev`, the spec before it, does not hold): an effect found after a harmonic leaves it as it was accepted,
    * and its finding keeps its own channel and where.
    */
  private[explain] def demote(e: SignalEngine, prev: ModelSpec, c: Cand): Cand = e.spec.terms.lastOption match {
    case Some(t @ Term.Harm(k, "both")) if e.termIndex.contains(t) && !prev.terms.contains(t) =>
      val at = e.termIndex(t); val v = e.meanSquare
      def chi2(j: Int) = (j until j + 2).map(i => e.sol.beta(i) * e.sol.beta(i) / math.max(1e-300, e.sol.inv(i)(i) * v)).sum
      val need = 2 * e.lnN + Threshold
      val keep = Seq("sin" -> chi2(at), "cos" -> chi2(at + 2)).filter(_._2 > need).map(_._1)
      if (keep.size != 1) c
      else {
        val t1 = Term.Harm(k, keep.head)
        e.spec = e.spec.copy(terms = e.spec.terms.init :+ t1); e.converge()
        c.copy(channel = keep.head, spec = e.spec, where = s"against fringe phase: ${keep.head} channel, order $k")
      }
    case _ => c
  }

  /** A new line's frequency checked after its round: `lineTune` moved it along with the refits; while a Gauss-Newton
    * step from the fit's residual is still above a quarter of the frequency's uncertainty (at most 3), the step is
    * taken and the fit converges again. The trajectory takes up some 30 % of each step: the second is divided by one
    * less the ratio of the two. Its search runs on a subsample of 50,000 samples: the bench's 50 kHz line at 20 M
    * samples came out 44 sd low without these steps. Only the candidate's own line (one that `prev`, the spec before
    * it, does not hold): an effect found after a line leaves it, and its finding has no frequency.
    */
  private def retune(e: SignalEngine, prev: ModelSpec, c: Cand): Cand = if (!newLine(e, prev)) c else {
    var k = 0; var moved = true; var last = 0.0
    while (k < 3 && moved) {
      // the steps shrink geometrically (the trajectory takes up a part of each): the second goes the rest of the way
      moved = lineStep(e, "retune", { s => val r = s / last; last = s; if (r > 0 && r < 0.7) s / (1 - r) else s }) > 0
      if (moved) e.converge(moved = true)
      k += 1
    }
    effects.Interference.at(c.copy(spec = e.spec), e.spec.terms.last.asInstanceOf[Term.Interference].hz)
  }

  /** A new line's frequency moved along with the round's refits (`SignalEngine.converge`'s `tune`): most of the way
    * to the whole record's optimum is made there, before `retune` checks it; null for other effects.
    */
  private def lineTune(e: SignalEngine, prev: ModelSpec): () => Double =
    if (newLine(e, prev)) () => lineStep(e, "tune", identity) else null

  /** The spec's last term is a line that `prev` does not hold: the candidate tried adds it. */
  private def newLine(e: SignalEngine, prev: ModelSpec): Boolean = e.spec.terms.lastOption.exists {
    case t: Term.Interference => !prev.terms.contains(t)
    case _ => false
  }

  /** The Gauss-Newton step of the last term's frequency (a line's) from the fit as it stands, as `take` scales it: the
    * step taken in the frequency's sd, 0 when the step is below a quarter of it (nothing moved).
    */
  private def lineStep(e: SignalEngine, what: String, take: Double => Double): Double = {
    val t = e.spec.terms.last.asInstanceOf[Term.Interference]
    e.termIndex.get(t).fold(0.0) { at =>
      val (step0, sd) = effects.Interference.frequencyStep(e, t.hz, e.sol.beta.slice(at, at + 4))
      val step = take(step0)
      if (SignalEngine.debug) System.err.println(f"$what: ${t.hz}%.6f Hz, step $step0%.3g (taken $step%.3g), sd $sd%.3g")
      if (!(math.abs(step0) > 0.25 * sd)) 0.0
      else { e.spec = e.spec.copy(terms = e.spec.terms.init :+ Term.Interference(t.hz + step)); math.abs(step) / sd }
    }
  }

  /** Alternates polishing the nonlinear parameters and refitting until BIC settles (at most 4 times). */
  def settle(e: SignalEngine): Unit = {
    if (!e.spec.hasSkew && e.spec.bw.isEmpty) return
    var prev = Double.PositiveInfinity; var k = 0
    while (k < 4 && prev - e.bic > 0.5) {
      prev = e.bic
      val before = e.spec
      // a polish that lowers the profile's -2 ln L by less than the loop's step leaves the fit as it stands (its refit
      // would not move the criterion by more either); the reference path refits after every polish
      if (Laps("settle: polish")(polish(e)) < 0.5 && !FitPath.isReference) { e.spec = before; return }
      Laps("settle: converge")(e.converge(moved = true)); k += 1
    }
  }

  /** A warm-up's time constant searched again on the fit without it (`Candidates.warmup`), once the trajectory has
    * longer segments (`SignalEngine.relengthen`): it was searched on the shorter ones, which had taken up part of it.
    */
  private def researchWarmup(e: SignalEngine): Unit = e.spec.terms.collectFirst { case w: Term.Warmup => w }.foreach { w0 =>
    val full = e.spec
    e.spec = full.copy(terms = full.terms.filterNot(_ == w0)); e.converge()
    val w1 = new Candidates(e).warmup().flatMap(_.spec.terms.collectFirst { case w: Term.Warmup => w }).getOrElse(w0)
    if (SignalEngine.debug) System.err.println(f"warm-up searched again: ${w0.tauS}%.5g s -> ${w1.tauS}%.5g s")
    e.spec = full.copy(terms = full.terms.map(t => if (t == w0) w1 else t)); e.converge(); settle(e)
  }

  /** Re-optimises the nonlinear parameters (skew, cut-offs) of the current spec together (`Candidates.joint`); returns
    * how much they lowered the profile's -2 ln L (scaled to all samples).
    */
  def polish(e: SignalEngine): Double = {
    val (sp, gain) = new Candidates(e).joint(e.spec, math.max(1, e.n / 50000))
    e.spec = sp
    gain
  }

  /** Signals whose spread (both channels' rms about their means) is below this (full scale) stand still: a fringe of
    * 1.4 % of full scale or more moving over a period spreads them further.
    */
  val StillFs = 0.01

  /** The fringe's amplitude must stand above the noise by this factor for the record to hold a fringe at all. */
  val MinAmplitudeNoise = 2.0

  /** Why the record holds no fringe to explain (inputs floating, random codes, a head off the scale), or None: the
    * default fit's amplitude is within `MinAmplitudeNoise` of the noise, so the fit's phase follows the noise. The
    * noise is the floor from neighbouring samples of the residual (`Adequacy.floor`), not the fit's: where the model
    * does not follow the motion (stick-slip) the fit's residual is the misfit, not noise.
    */
  def noFringe(e: SignalEngine): Option[String] = {
    val a = 0.5 * (e.ampS + e.ampC); val sd = Adequacy.floor(e)
    // both channels within a few noise widths or StillFs of where they are: a head standing still (or two inputs with
    // no fringe); told as that, not as one input unconnected (a still head had its sin at 388 +- 13 LSB from mid-scale
    // and its cos at -1653 +- 3: "is the cos input connected?")
    def spread(y: Array[Double]) = { var m = 0.0; var i = 0; while (i < e.n) { m += y(i); i += 1 }; m /= e.n
      var v = 0.0; i = 0; while (i < e.n) { v += (y(i) - m) * (y(i) - m); i += 1 }; (m, math.sqrt(v / e.n)) }
    val ((ms, ss), (mc, sc)) = (spread(e.ys), spread(e.yc))
    // (both at mid-scale is floating inputs: a still fringe puts at least one channel 0.7 of its amplitude off the middle)
    val mid = math.max(5 * sd, 2 * StillFs)
    if (math.hypot(ss, sc) < math.max(3 * sd, StillFs) && !(math.abs(ms) < mid && math.abs(mc) < mid))
      Some(f"no fringe: the signals stand still (sin at ${ms / e.lsb}%.0f +- ${ss / e.lsb}%.2g LSB, cos at ${mc / e.lsb}%.0f +- ${sc / e.lsb}%.2g " +
        f"LSB from mid-scale, noise ${sd / e.lsb}%.3g LSB rms): the read head did not move; record while " +
        "the head moves over at least one fringe period")
    else if (!(a > MinAmplitudeNoise * sd))
      Some(f"no fringe: the fitted amplitude ${a / e.lsb}%.3g LSB is not above ${MinAmplitudeNoise}%.0f x the noise " +
        f"(${sd / e.lsb}%.3g LSB rms); are the inputs connected, and the read head over the scale and moving?")
    // a head that creeps over part of a period draws an arc, not the ellipse: offsets, amplitudes and the phase error
    // trade against each other along it (another generator's creep of 0.3 period was fitted with offsets of 0.37 FS).
    // The arc's extent is the fit's, from an ellipse the arc does not fix: no figure of it is given
    else if (shortArc(e)) Some(ShortArc)
    else {
      // one channel without its fringe (a dead or unconnected input that only carries noise): the other's phase is then
      // fitted against noise, and what is left looks like pickup of half the full scale
      // (the residual's rms first: the floor is below it, and only a channel that fails it pays for the floor's passes)
      def floorOf(r: Array[Double]) = Adequacy.floorOf(r, null, 0, e.n, Adequacy.JudgeOrder, null)
      Seq(("sin", e.ampS, e.resS, e.noise.varS, e.yc), ("cos", e.ampC, e.resC, e.noise.varC, e.ys)).collectFirst {
        case (ch, amp, res, v, other) if !(amp > MinAmplitudeNoise * math.sqrt(v)) && !(amp > MinAmplitudeNoise * floorOf(res)) =>
        // the other channel that never goes up and down across its middle has no fringe either: the head moved over a
        // small part of a period (1 % of one was "is the cos input connected?"), and one channel barely changes there
        if (crossings(other, 3 * sd) < 2) ShortArc else {
        val f = floorOf(res)
        f"no fringe on the $ch channel: its fitted amplitude ${amp / e.lsb}%.3g LSB is not above ${MinAmplitudeNoise}%.0f x its noise " +
          f"(${f / e.lsb}%.3g LSB rms) while the other channel's is ${(if (ch == "sin") e.ampC else e.ampS) / e.lsb}%.3g LSB; is the $ch input connected?"
        }
      }
    }
  }
  private val ShortArc = "too short an arc: the read head moved over less than one fringe period, so the signals trace an arc of the " +
    "ellipse, not the whole of it, and an arc does not fix its offsets, amplitudes and phase error; record while the " +
    "head moves over at least one whole fringe period"
  /** Times a channel crosses the middle of its range, by more than `margin` each way (a fringe period: two). */
  private def crossings(y: Array[Double], margin: Double): Int = {
    var lo = Double.PositiveInfinity; var hi = Double.NegativeInfinity; var i = 0
    while (i < y.length) { lo = math.min(lo, y(i)); hi = math.max(hi, y(i)); i += 1 }
    val mid = 0.5 * (lo + hi); var side = 0; var k = 0; i = 0
    while (i < y.length) {
      if (y(i) > mid + margin) { if (side < 0) k += 1; side = 1 } else if (y(i) < mid - margin) { if (side > 0) k += 1; side = -1 }
      i += 1
    }
    k
  }

  /** The fitted phase spans less than a fringe period and visits less than `MinArc` of it (in bins of 10 degrees).
    * The span first: at exactly 5 samples a period the phase of a long record visits 5 bins (such records were refused).
    */
  def shortArc(e: SignalEngine): Boolean = {
    val (lo, hi) = Doubles.range(e.n)(i => e.phase(i))
    !(hi - lo >= 1) && {
      val seen = new Array[Boolean](36); var i = 0
      while (i < e.n) { val p = e.phase(i); if (!p.isNaN && !p.isInfinite) seen(((p - math.floor(p)) * 36).toInt min 35) = true; i += 1 }
      seen.count(identity) < MinArc * 36
    }
  }
  /** The share of the period an arc must visit (`shortArc`): less than this (of a record that spans less than a period)
    * fixes no ellipse; clean back-and-forth records over 0.6 and 0.8 of a period were reported as misfit.
    */
  val MinArc = 0.8

  /** Warnings about the recording itself. */
  def notes(e: SignalEngine): Seq[String] = {
    val sd = math.sqrt(math.min(e.noise.varS, e.noise.varC)) / e.step
    val unit = if (e.coarseBits == 0) "LSB" else s"steps of ${1 << e.coarseBits} LSB"
    (if (sd < 0.5) Seq(f"noise is ${Effect.below(sd, 0.5)} $unit rms, below 0.5: the quantization error is not white noise here; value-bound structure below ${Quantization.biasBound(e) / e.step}%.2f of a step is taken for quantization, not physics") else Nil) ++
      (if (e.typicalHz * 4 > e.fs && e.reference.isEmpty) Seq("fewer than 4 samples per fringe period: the phase trajectory is poorly sampled") else Nil) ++
      railNote(e).toSeq ++ RefReport.notes(e)
  }

  /** Samples at an ADC's end codes: the signal beyond the converter's range there. They are fitted as censored (at or
    * beyond the rail), which no effect reports, so the user is told when they are more than `RailShare` of a channel.
    */
  def railNote(e: SignalEngine): Option[String] = {
    def share(y: Array[Double]): Double =
      Par.sum(y.length) { (a, b) => var k = 0; var i = a; while (i < b) { if (e.atRail(y(i))) k += 1; i += 1 }; k.toDouble } / y.length
    val s = share(e.ys); val c = share(e.yc)
    if (math.max(s, c) < RailShare) None
    else Some(f"the sin channel is at the ADC's end codes on ${100 * s}%.1f %% of the samples and the cos channel on ${100 * c}%.1f %%: " +
      "the signal exceeds the converter's range there; those samples are fitted as at or beyond the end (censored), and a " +
      "lower gain before the ADC would measure them")
  }
  /** A channel's share of samples at the end codes above which `railNote` speaks. */
  val RailShare = 1e-3

  /** The default part's parameters. The noise is the model's residual where the model follows the signal, else the
    * noise floor from neighbouring samples (a misfit is not noise); `residual_*_fs` is always the model's.
    */
  def baselineParams(e: SignalEngine): Map[String, Double] = {
    val follows = !(Adequacy.ratio(e) > Adequacy.Margin)
    def floorOf(r: Array[Double]) = Adequacy.floorOf(r, null, 0, e.n, Adequacy.JudgeOrder, null)
    val (ns, nc) = if (follows) (math.sqrt(e.noise.varS), math.sqrt(e.noise.varC)) else (floorOf(e.resS), floorOf(e.resC))
    Map(
      "offset_sin_fs" -> e.base(0), "offset_cos_fs" -> e.base(3), "amplitude_sin_fs" -> e.ampS, "amplitude_cos_fs" -> e.ampC,
      "phase_error_deg" -> e.phaseErrorDeg, "noise_sin_fs" -> ns, "noise_cos_fs" -> nc,
      "residual_sin_fs" -> math.sqrt(e.noise.varS), "residual_cos_fs" -> math.sqrt(e.noise.varC),
      "typical_fringe_hz" -> e.typicalHz, "noise_floor_fs" -> Adequacy.floor(e), "trajectory_segments" -> e.traj.nseg.toDouble) ++ RefReport.params(e)
  }
}
