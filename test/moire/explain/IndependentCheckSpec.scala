package moire.explain

import moire.recording.Recording
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** explain against recordings of the second generator, so the fit is not only checked against its own model. */
class IndependentCheckSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport.{describe, within}

  private def run(s: SecondGenerator.Spec): Report = {
    val rec = Recording.parse("second", SecondGenerator.text(s).split("\n").toIndexedSeq)
    val r = SignalExplain.run("second", rec, Nil, Progress.none).report
    info(describe(r))
    r
  }

  "explain on the second generator" should "find its channel skew behind a phase error" in {
    val r = run(SecondGenerator.Spec(skewS = 40e-9, phaseErrDeg = 3))
    r.findings.map(_.effect) shouldBe Seq("channel_skew")
    assert(within(r.findings.head.params("skew_s"), 40e-9), r.findings.head.params)
  }

  it should "find the cut-off of a real IIR low-pass on a chirp" in {
    val r = run(SecondGenerator.Spec(iirCutoffHz = 400e3, f1 = 260e3))
    r.findings.map(_.effect) shouldBe Seq("bandwidth")
    r.findings.head.channel shouldBe "both"
    assert(within(r.findings.head.params("cutoff_hz"), 400e3), r.findings.head.params)
  }

  it should "find a third harmonic below the noise" in {
    val r = run(SecondGenerator.Spec(h3Sin = 6e-4))
    withClue(describe(r)) { r.findings.map(_.effect) shouldBe Seq("harmonic") }
    r.findings.head.params("order") shouldBe 3.0
    assert(within(r.findings.head.params("amplitude_rel"), 6e-4), r.findings.head.params)
  }

  it should "report an offset jump, which no catalogued effect explains, as located and unexplained" in {
    val r = run(SecondGenerator.Spec(stepLsb = 2.0))
    info(r.unexplained.map(u => s"${u.where}: ${u.summary}").mkString("; "))
    r.unexplained.map(_.where) should contain("against time, sin channel")
    val u = r.unexplained.find(_.where == "against time, sin channel").get
    math.abs(u.params("mean_lsb")) should be > 0.3
  }

  it should "name nothing in its clean recordings" in {
    for (seed <- 1 to 3) run(SecondGenerator.Spec(seed = seed)).findings shouldBe empty
  }
}
