package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Runs of samples the converter or the transfer lost (a FIFO repeating its last word, both converters reading 0) are
  * left out of the fit and named in the notes, never an effect or a misfit (another generator's holds of 40 samples
  * were misfit windows and a jitter of 1400 ps; its runs of 30 zeros a jitter of 380 ps); a clean record, moving or
  * standing, has none.
  */
class DataLossSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private val spec = FringeGenerator.Spec(n = 200000, fs = 2e6, motion = "reverse", travel = 300, rateHz = 15, seed = 51)
  private def lossNote(r: Report) = r.notes.find(_.contains("hold both channels still"))
  /** The samples lost a step's text gives ("about 36.9 samples lost"). */
  private def lostOf(s: String) = "about ([0-9.]+) samples lost".r.findFirstMatchIn(s).map(_.group(1).toDouble).getOrElse(Double.NaN)

  "explain" should "leave runs of lost samples out of the fit and name them" in {
    val holds = explain(FringeGenerator.recording(spec.copy(holds = Seq(60000 -> 60040, 140000 -> 140040))))
    val zeros = explain(FringeGenerator.recording(spec.copy(zeros = Seq(40000 -> 40030, 100000 -> 100030, 160000 -> 160030))))
    for ((name, r, k) <- Seq(("holds", holds, 2), ("zeros", zeros, 3))) {
      info(s"$name: ${describe(r)}; ${lossNote(r).getOrElse("no note")}")
      withClue(s"$name: ${describe(r)}; misfit ${r.misfit.map(_.summary)}; unexplained ${r.unexplained.map(_.where)}") {
        r.findings shouldBe empty
        r.misfit shouldBe empty
        lossNote(r).getOrElse(fail("no note")) should startWith(s"$k runs of samples")
      }
    }
  }

  // Samples cut out of the capture (the rows go on with no gap): a step of the phase no trajectory follows. Before, it was
  // a window where the model does not follow and nothing more; now the window names the step and the samples lost.
  it should "name a step of the phase where samples were cut out of the capture" in {
    // 20 kHz at 2 MS/s: 100 samples a period; 37 cut out step the phase on by 0.37 period
    val r = explain(FringeGenerator.recording(spec.copy(motion = "constant", f0 = 20e3, cuts = Seq(120000 -> 120037))))
    withClue(clue(r)) {
      r.findings shouldBe empty
      val m = r.misfit.find(_.params.contains("phase_step_periods")).getOrElse(fail("no step named"))
      m.params("phase_step_periods") shouldBe 0.37 +- 0.01
      m.params("phase_step_s") shouldBe 120000 / spec.fs +- 2 / spec.fs
      lostOf(m.summary) shouldBe 37.0 +- 0.5
      // the window's fringe frequency is the data's (the fitted trajectory there read 0.56..37 kHz on another record)
      m.params("f0_hz") should be > 19e3
      m.params("f1_hz") should be < 21e3
      // and the record's note, which names steps where no window is left too (a step on a segment's end)
      val note = r.notes.find(_.contains("phase steps")).getOrElse(fail("no note"))
      note should include("once: +0.370 period between data rows 120000 and 120001")
      lostOf(note) shouldBe 37.0 +- 0.5
    }
    // without the cut: no window, no step
    val clean = explain(FringeGenerator.recording(spec.copy(motion = "constant", f0 = 20e3)))
    withClue(clue(clean)) { clean.misfit shouldBe empty; clean.notes.filter(_.contains("phase steps")) shouldBe empty }
  }

  it should "name steps where they leave no misfit window, and none in a glitch or a run held" in {
    // 5 steps of 13 samples (0.13 period) over a reversing motion, and the held runs and zeros of the first test
    val cuts = Seq(30000, 70000, 95000, 130000, 170000).map(a => a -> (a + 13))
    val r = explain(FringeGenerator.recording(spec.copy(cuts = cuts)))
    val note = r.notes.find(_.contains("phase steps")).getOrElse(fail(s"no note: ${clue(r)}"))
    withClue(note) { note should include("5 times") }
    for (s <- Seq(spec.copy(holds = Seq(60000 -> 60040)), spec.copy(zeros = Seq(40000 -> 40030)))) {
      val q = explain(FringeGenerator.recording(s))
      withClue(q.notes) { q.notes.filter(_.contains("phase steps")) shouldBe empty }
    }
  }

  it should "see none in a clean record, moving, or turning back slowly with little noise" in {
    val moving = explain(FringeGenerator.recording(spec))
    val still = explain(FringeGenerator.recording(spec.copy(travel = 2, rateHz = 5, noiseLsb = 0.3)))
    for ((name, r) <- Seq("moving" -> moving, "turning slowly" -> still)) withClue(name) { lossNote(r) shouldBe None }
  }
}
