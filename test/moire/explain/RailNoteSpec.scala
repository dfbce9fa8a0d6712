package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A signal beyond the ADC's range is fitted as censored at the end codes; the report says how much of it is there. */
class RailNoteSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "explain" should "say how much of each channel sits at the ADC's end codes, and say nothing when none does" in {
    // an amplitude of 1.3 full scale: the sin channel beyond +-1 over about 40 % of a period
    val over = explain(sim(Nil, n = 40000, amplitude = 1.3))
    val note = over.notes.find(_.contains("end codes")).getOrElse(fail(s"no end-code note: ${over.notes}"))
    val pct = "on ([0-9.]+) %".r.findAllMatchIn(note).map(_.group(1).toDouble).toSeq
    withClue(note) {
      pct should have size 2
      // the share of a sine of amplitude a beyond 1: 1 - (2 / pi) asin(1 / a)
      val want = 100 * (1 - 2 / math.Pi * math.asin(1 / 1.3))
      pct.foreach(p => p shouldBe want +- 3.0)
    }
    explain(sim(Nil, n = 40000)).notes.exists(_.contains("end codes")) shouldBe false
  }
}
