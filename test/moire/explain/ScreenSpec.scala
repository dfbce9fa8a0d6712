package moire.explain

import moire.signal.Motion
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A long record's linear candidates are screened on a spread subsample and those significant there fitted on all
  * samples (`Candidates.confirmed`). Here with the screen lowered to short records: the same findings, each parameter
  * within its stated uncertainty, as the search that fits every candidate on all samples.
  */
class ScreenSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "a subsample's family" should "give the fits of all samples when the subsample is all of them" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 1e-3), "sin")), n = 60000)
    val e = new SignalEngine(rec); e.init()
    val yy = (e.sumSq(e.resS), e.sumSq(e.resC))
    val terms = LinearSweep.terms(Seq(2, 3))
    val all = LinearSweep.of(e, terms, yy._1, yy._2); val sub = LinearSweep.of(e, terms, yy._1, yy._2, Array.range(0, e.n))
    for (t <- terms; use <- Seq(IndexedSeq(0, 1, 2, 3, 4, 5), (0 until 6) ++ (6 until 6 + all(t).hasSin.size - 6))) {
      val (s1, a1, b1) = all(t).fit(use, _ => true, _ => true); val (s2, a2, b2) = sub(t).fit(use, _ => true, _ => true)
      withClue(s"$t $use: ") {
        for ((x, y) <- s1.beta.zip(s2.beta)) x shouldBe y +- 1e-9 * math.max(1.0, math.abs(x))
        // the default part's own fit leaves the residual's sum of squares, whichever samples
        a2 shouldBe a1 +- 1e-9 * a1; b2 shouldBe b1 +- 1e-9 * b1
      }
    }
  }

  "the screen" should "fit the candidates significant on the subsample on all samples and drop the rest" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 1e-3), "sin")), n = 300000)
    val e = new SignalEngine(rec); e.init()
    // the linear families' candidates, and the warm-up's and the pickup line's (linear once searched)
    def linear(cs: Seq[Cand]) = cs.filter(c => c.spec.terms.lastOption.exists(Candidates.screened))
    val full = linear(new Candidates(e).all(() => ()))
    val screened = linear(Candidates.screening(100000, 30000)(new Candidates(e).all(() => ())))
    screened.map(c => (c.effect, c.channel, c.spec)) shouldBe full.map(c => (c.effect, c.channel, c.spec))
    val (kept, dropped) = screened.zip(full).partition(_._1.m2ll != e.noise.m2ll)
    withClue(kept.map(_._1.where).mkString("; ")) { kept.map(_._1.spec.terms.last) should contain (Term.Harm(3, "sin")) }
    for ((s, f) <- kept) s.m2ll shouldBe f.m2ll +- 1e-9 * math.abs(f.m2ll)
    // the dropped ones do not lower BIC on all samples either
    dropped should not be empty
    Seq("warmup", "interference").foreach(x => withClue(x) { screened.map(_.effect) should contain (x) })
    for ((_, f) <- dropped) withClue(f.where) { e.bic - (f.m2ll + (e.params + f.extraK) * e.lnN) should be < SignalExplain.Threshold }
  }

  "the slope-noise candidates" should "be fitted on all samples when the subsample shows them, and left out when it does not" in {
    // jitter of 300 ps: its variance is a fifth of the white noise's at 200 kHz, plain on the subsample too; of 100 ps,
    // the search on all samples fits some but it does not lower BIC there, nor on the subsample
    for ((rec, shown) <- Seq(300e-12 -> true, 100e-12 -> false).map { case (j, s) => (sim(Seq(EffectSpec("jitter", Map("jitter_s" -> j))), n = 300000), s) }) {
      val e = new SignalEngine(rec); e.init()
      def noise(cs: Seq[Cand]) = cs.filter(c => Seq("jitter", "phase_noise").contains(c.effect)).map(c => c.effect -> c).toMap
      val full = noise(new Candidates(e).all(() => ()))
      val screened = noise(Candidates.screening(100000, 30000)(new Candidates(e).all(() => ())))
      def gain(c: Cand) = e.bic - (c.m2ll + (e.params + c.extraK) * e.lnN)
      withClue(s"shown $shown: full ${full.view.mapValues(gain).toMap}, screened ${screened.view.mapValues(gain).toMap}: ") {
        // what the screen passes is the search on all samples, to the bit
        for ((k, c) <- screened) c.m2ll shouldBe full(k).m2ll
        if (shown) { screened.keySet should contain ("jitter"); gain(screened("jitter")) should be > 100.0 }
        // what it leaves out does not lower BIC on all samples either
        for ((k, c) <- full if !screened.contains(k)) gain(c) should be < SignalExplain.Threshold
        if (!shown) { full should not be empty; screened shouldBe empty }
      }
    }
  }

  "explain" should "find the same effects with the linear candidates screened on a subsample" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 1e-3), "sin"),
      EffectSpec("harmonic", Map("order" -> 2, "amplitude_rel" -> 4e-4), "both"),
      EffectSpec("drift", Map("offset_sin_per_s" -> 0.05, "gain_cos_per_s" -> 0.2))), motion = Motion.Ramp(20e3, 200e3, 0.03), n = 300000)
    def run() = SignalExplain.run("screen", rec, Nil, Progress.none).report
    val full = run(); val screened = Candidates.screening(100000, 30000)(run())
    withClue(s"full: ${describe(full)}\nscreened: ${describe(screened)}\n") {
      full.findings.size should be >= 3
      screened.findings.map(f => (f.effect, f.channel)).sorted shouldBe full.findings.map(f => (f.effect, f.channel)).sorted
      for (f <- full.findings; g <- screened.findings.find(g => g.effect == f.effect && g.channel == f.channel && g.params.get("order") == f.params.get("order"));
           (k, v) <- f.params) {
        val u = math.max(f.unc.getOrElse(k, 0.0), g.unc.getOrElse(k, 0.0))
        withClue(s"${f.effect} $k: ") { math.abs(g.params(k) - v) should be <= (if (u.isNaN) 1e-6 * math.abs(v) else u + 1e-9 * math.abs(v)) }
      }
      screened.finalBic shouldBe full.finalBic +- 1.0
    }
  }

  it should "fit a warm-up and a pickup line found on the subsample on all samples, with the same findings" in {
    val rec = sim(Seq(EffectSpec("interference", Map("frequency_hz" -> 12345.0, "amplitude_fs" -> 6e-4)),
      EffectSpec("warmup", Map("offset_sin_step_fs" -> 0.002, "gain_cos_step_rel" -> 0.004, "time_constant_s" -> 0.004))), n = 300000)
    def run() = SignalExplain.run("screen", rec, Nil, Progress.none).report
    val full = run(); val screened = Candidates.screening(100000, 30000)(run())
    withClue(s"full: ${describe(full)}\nscreened: ${describe(screened)}\n") {
      full.findings.map(_.effect).sorted shouldBe Seq("interference", "warmup")
      screened.findings.map(f => (f.effect, f.channel)).sorted shouldBe full.findings.map(f => (f.effect, f.channel)).sorted
      for (f <- full.findings; g <- screened.findings.find(_.effect == f.effect); (k, v) <- f.params) {
        val u = math.max(f.unc.getOrElse(k, 0.0), g.unc.getOrElse(k, 0.0))
        withClue(s"${f.effect} $k: ") { math.abs(g.params(k) - v) should be <= (if (u.isNaN) 1e-6 * math.abs(v) else u + 1e-9 * math.abs(v)) }
      }
      // the time constant's uncertainty comes from the search: kept when the fit is made again on all samples
      def tau(r: Report) = r.findings.find(_.effect == "warmup").get.unc.get("time_constant_s")
      tau(screened) shouldBe tau(full)
      screened.finalBic shouldBe full.finalBic +- 1.0
    }
  }
}
