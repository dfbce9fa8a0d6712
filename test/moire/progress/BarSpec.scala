package moire.progress

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class BarSpec extends AnyFlatSpec with Matchers {
  "Bar" should "print plain lines without escape codes when stderr is no terminal: start, each tenth, end" in {
    val err = new java.io.ByteArrayOutputStream(); val e0 = System.err
    System.setErr(new java.io.PrintStream(err, true))
    try {
      val b = new Bar("cost sweep", 1000, terminal = false)
      (1 to 1000).foreach(_ => b.step())
      b.setExtraMessage(" last")
      b.close(); b.close()
    } finally System.setErr(e0)
    val lines = err.toString.linesIterator.toSeq
    lines should have size 12
    lines.head should startWith("cost sweep: 0/1000, ")
    lines(5) should startWith("cost sweep: 500/1000, ")
    lines.last should (startWith("cost sweep: 1000/1000, ") and endWith("elapsed last"))
    err.toString.exists(c => c == '\u001b' || c == '\r') shouldBe false
  }

  it should "space its plain lines by plainGapS seconds, and still say the start and the end" in {
    val err = new java.io.ByteArrayOutputStream(); val e0 = System.err
    System.setErr(new java.io.PrintStream(err, true))
    try {
      val b = new Bar("record", 40, " s", 10, terminal = false, plainGapS = 10)
      (1 to 40).foreach { _ => b.step(); Thread.sleep(5) }
      b.close()
    } finally System.setErr(e0)
    val lines = err.toString.linesIterator.toSeq
    lines should have size 2
    lines.head should startWith("record: 0.0/4.0 s, ")
    lines.last should startWith("record: 4.0/4.0 s, ")
  }
}
