package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** `bounds` tells a vacuous bound apart from a met one, and passes the few-iterations rows it used to fail. */
class BoundsCmdSpec extends AnyFlatSpec with Matchers {
  import CliInProcess.runCliOut

  "bounds" should "mark a bound beyond half the output's range vacuous, not yes" in {
    val (code, out, err) = runCliOut("bounds", "--mode", "atan2", "--iterations", "40", "--widths", "8")
    withClue(err) { code shouldBe 0 }
    val row = out.linesIterator.find(_.trim.startsWith("atan2")).get
    row should endWith("vacuous")
    out should include("1 configuration has a vacuous bound")
  }

  it should "hold the conventional arcsine at 4 iterations and 44 bits" in {
    val (code, out, err) = runCliOut("bounds", "--mode", "acos", "--iterations", "4", "--widths", "44,48")
    withClue(err + out) { code shouldBe 0 }
    out.linesIterator.count(_.trim.endsWith("yes")) shouldBe 2
  }
}
