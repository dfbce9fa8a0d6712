package moire.explain.evidence

import moire.recording.{Recording, RecordingError}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Issue 28, Format: files other tools write. A header comment without a key (a scope's export line) is kept as a
  * comment, not refused; a two's-complement file may hold signed codes (-2048 .. 2047) as well as pin patterns, and
  * both read to the same values; an error shows the offending line whole.
  */
class FilesOthersWriteSpec extends AnyFlatSpec with Matchers {
  private val scope = ScopeDump.text(Motions.chirp(2000, 2e6, 10e3, 30e3), 2e6, 0.8, 0.4, seed = 91)
  private def lines(t: String) = t.split("\n").toIndexedSeq

  "a recording" should "read with a scope's export line in the header (a comment without a key)" in {
    val withComment = lines(scope).patch(1, Seq("# exported by scope-dump rev 7 (CH1 = sin, CH2 = cos)"), 0)
    val r = Recording.parse("scope", withComment)
    val plain = Recording.parse("scope", lines(scope))
    r.length shouldBe plain.length
    r.sin shouldBe plain.sin
    r.cos shouldBe plain.cos
  }

  it should "read a two's-complement file holding signed codes, to the same values as its pin patterns" in {
    val b = Bench(seed = 92)
    val (s, c) = b.codes(Motions.chirp(3000, 1e6, 10e3, 30e3), 1e6)
    def file(f: Int => Int) = BenchText("signed", 1e6, 12, (s.map(f), c.map(f)), Seq("adc_format" -> "twos-complement"))
    val signed = Recording.parse("signed", lines(file(_ - 2048)))
    val pins = Recording.parse("pins", lines(file(v => (v - 2048) & 0xfff)))
    signed.values(signed.sin) shouldBe pins.values(pins.sin)
    signed.values(signed.cos) shouldBe pins.values(pins.cos)
    s.exists(_ < 2048) shouldBe true // the signed file has negative codes
  }

  it should "show the offending line whole in an error" in {
    val bad = "2051,20x7,extra text that tells what went wrong in this export"
    val e = intercept[RecordingError](Recording.parse("bad", lines(scope).patch(9, Seq(bad), 1)))
    e.getMessage should include(bad)
  }
}
