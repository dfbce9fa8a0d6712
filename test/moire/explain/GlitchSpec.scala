package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Isolated samples far off the signal are data glitches: left out of the fit and named in the notes, never an
  * effect, a misfit or unexplained structure (another generator's 3 samples at code 0 were taken for samples at the
  * rail, its 10 at mid-scale made misfit windows); a clean record and a stuck bit have none.
  */
class GlitchSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  private val spec = FringeGenerator.Spec(n = 200000, fs = 5e6, motion = "chirp", f0 = 20e3, f1 = 150e3, seed = 41)

  /** The generator's text with data row r (from 1) of channel ch set to code v. */
  private def glitched(rows: Seq[(Int, Int, Int)]): moire.recording.Recording = {
    val lines = FringeGenerator.text(spec).split("\n")
    val first = lines.indexWhere(_.startsWith("sin,cos")) + 1
    for ((r, ch, v) <- rows) { val c = lines(first + r - 1).split(","); c(ch) = v.toString; lines(first + r - 1) = c.mkString(",") }
    moire.recording.Recording.parse("glitched", lines.toIndexedSeq)
  }

  private def glitchNote(r: Report) = r.notes.find(_.contains("isolated sample"))

  "explain" should "leave glitches out of the fit and name them, at the rail and at mid-scale" in {
    for ((name, rows) <- Seq("code 0" -> Seq((12346, 1, 0), (77778, 0, 0), (150002, 1, 0)),
      "mid-scale" -> (0 until 10).map(k => (501 + 19997 * k, k % 2, 2048)),
      "pairs" -> (0 until 5).flatMap(k => Seq((9001 + 19000 * k, k % 2, 0), (9002 + 19000 * k, k % 2, 0))))) {
      val r = explain(glitched(rows))
      info(s"$name: ${describe(r)}; ${glitchNote(r).getOrElse("no note")}")
      withClue(s"$name: ${describe(r)}; misfit ${r.misfit.map(_.summary)}; unexplained ${r.unexplained.map(_.where)}") {
        r.findings shouldBe empty
        r.misfit shouldBe empty
        r.unexplained shouldBe empty
        val note = glitchNote(r).getOrElse(fail("no glitch note"))
        // a glitch to mid-scale where the signal is near it is no glitch to see: most are
        note should startWith(s"${rows.size} isolated samples (data rows ${rows.head._1}, ")
      }
    }
  }

  it should "see none in a clean record or in a stuck bit's" in {
    val clean = explain(FringeGenerator.recording(spec))
    val stuck = explain(sim(Seq(EffectSpec("adc_bit_fault", Map("bit" -> 6, "stuck_at" -> 0), "sin")), n = 200000, fs = 5e6))
    for ((name, r) <- Seq("clean" -> clean, "stuck bit 6" -> stuck)) withClue(name) { glitchNote(r) shouldBe None }
    stuck.findings.map(_.effect) should contain("adc_bit_fault")
  }
}
