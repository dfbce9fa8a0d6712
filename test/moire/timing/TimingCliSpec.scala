package moire.timing

import moire.cli.CliProcess
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** `timing`'s bad options: one line naming the option, the value and what is allowed; exit code 2. */
class TimingCliSpec extends AnyFlatSpec with Matchers {
  private def bad(args: String*)(words: String*): Unit = {
    val (code, _, err) = CliProcess.run("timing" +: args: _*)
    code shouldBe 2
    err.trim.linesIterator.size shouldBe 1
    words.foreach(w => err should include(w))
    err should not include "Exception"
  }

  "timing" should "name an unknown design and the designs allowed" in bad("--design", "nope")("'nope'", "subdiv", "corrected")
  it should "want a design or --all" in bad()("--design", "--all")
  it should "reject a speed grade the LFE5U has not" in bad("--design", "subdiv", "--speeds", "6,5")("--speeds", "'5'", "6, 7, 8")
  it should "reject an unknown router" in bad("--design", "subdiv", "--router", "fast")("--router", "'fast'", "router2")
  it should "reject a target that is no frequency" in bad("--design", "subdiv", "--target-mhz", "-3")("--target-mhz", "-3")
}
