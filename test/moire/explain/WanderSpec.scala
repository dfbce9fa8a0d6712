package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A random walk of the offsets (1/f-like wander): no line, no effect of the catalogue. */
class WanderSpec extends AnyFlatSpec with Matchers {
  "explain" should "call a wander of the offsets a wander, not a line, and name no pickup" in {
    // 2.5 LSB of random walk over 0.4 s at one speed: its power sits in the spectrum's lowest bins. Before, the report
    // read "strongest line 3.8 Hz" (1 cycle in the span)
    val s = FringeGenerator.Spec(n = 400000, fs = 1e6, f0 = 3e3, noiseLsb = 1.2, wanderLsb = 0.004)
    val r = SignalExplain.run("wander", FringeGenerator.recording(s), Nil, Progress.none).report
    val spectra = r.located.filter(l => l.where.startsWith("spectrum") && l.significant)
    println(s"wander: findings [${ExplainSupport.describe(r)}]; spectrum: ${spectra.map(_.summary).mkString(" | ")}")
    spectra should not be empty
    all(spectra.map(_.summary)) should include("a slow wander, not a line")
    r.findings.map(_.effect) should not contain "interference"
  }
}
