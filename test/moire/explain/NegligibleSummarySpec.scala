package moire.explain

import moire.explain.effects.Interference
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A `negligible` entry says what the structure is (the effect's own sentence) beside its size and the floor. */
class NegligibleSummarySpec extends AnyFlatSpec with Matchers {
  "a line's frequency in a summary" should "have 6 significant digits in Hz, kHz or MHz" in {
    Interference.hz(20999990.8) shouldBe "21.0000 MHz"
    Interference.hz(50.00012) shouldBe "50.0001 Hz"
    Interference.hz(12345.678) shouldBe "12.3457 kHz"
    Interference.hz(Double.NaN) shouldBe "NaN Hz"
  }

  "a negligible entry" should "name what it is, its size and the floor" in {
    val p = Map("frequency_hz" -> 20999990.8, "amplitude_fs" -> 4.98e-5)
    val n = Negligible("interference", "both", 0.102, 0.25, 897.0, p, Interference.summary(p, "both", 0, 0))
    val s = n.json("summary").str
    s should startWith("interference: pickup at 21.0000 MHz")
    s should include("0.102 LSB (floor 0.250 LSB): too small to matter")
    Negligible("interference", "both", 0.102, 0.25, 897.0, p).json("summary").str should startWith("interference: lowers BIC")
  }

  it should "name the effects that took its part when it was found before them" in {
    val n = Negligible("contrast_along_travel", "both", 0.056, 0.25, 958120.0, Map.empty, "contrast changes along the travel", Seq("drift"))
    n.json("summary").str shouldBe "contrast_along_travel: contrast changes along the travel: lowered BIC by 958120 when found, but drift, " +
      "found after it, took its part: in the final fit it changes the signal by only 0.0560 LSB (floor 0.250 LSB), too small to matter " +
      "(the two predict nearly the same signal here)"
    n.json("taken_by").arr.map(_.str) shouldBe Seq("drift")
  }
}
