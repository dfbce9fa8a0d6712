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

  it should "see none in a clean record, moving, or turning back slowly with little noise" in {
    val moving = explain(FringeGenerator.recording(spec))
    val still = explain(FringeGenerator.recording(spec.copy(travel = 2, rateHz = 5, noiseLsb = 0.3)))
    for ((name, r) <- Seq("moving" -> moving, "turning slowly" -> still)) withClue(name) { lossNote(r) shouldBe None }
  }
}
