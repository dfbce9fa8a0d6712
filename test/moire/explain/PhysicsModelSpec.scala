package moire.explain

import moire.signal._
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class PhysicsModelSpec extends AnyFlatSpec with Matchers {
  private val base = SignalParams(amplitude = 0.8, offsetSin = 0.01, gainCos = 1.02, phaseErrorDeg = 1.0,
    harmonics = Seq(Harmonic(3, 0.002)), noiseRms = 0.0007, seed = 9)

  "simulate's default model" should "be the project's signal simulator, code for code" in {
    val m = PhysicsModel(base, Motion.Oscillate(30, 500), 5e6, 20000, Adc(12, AdcFormat.TwosComplement))
    val (rec, truth) = m.generate()
    val s = SignalSim.generate(base, Motion.Oscillate(30, 500), Adc(12, AdcFormat.TwosComplement), 5e6, 20000)
    rec.sin.toSeq shouldBe s.sin.toSeq
    rec.cos.toSeq shouldBe s.cos.toSeq
    truth.toSeq shouldBe s.truePeriods.toSeq
  }

  it should "round-trip through its JSON" in {
    val m = PhysicsModel(base, Motion.Ramp(1e3, 2e3, 0.1), 1e6, 1000, Adc(14), Some(2500.0),
      Seq(EffectSpec("channel_skew", Map("skew_s" -> 2e-8)), EffectSpec("bandwidth", Map("cutoff_hz" -> 3e5), "cos")))
    val back = PhysicsModel.fromJson(ujson.write(m.json), "m.json", m.copy(effects = Nil, motion = Motion.Constant(1)))
    back.copy(base = back.base.copy(harmonics = base.harmonics)) shouldBe m
  }

  "a skew at 30 ns" should "turn into the cos phase the physics says (360 f tau degrees)" in {
    val p = SignalParams(amplitude = 0.9, noiseRms = 0, seed = 1)
    val m = PhysicsModel(p, Motion.Constant(100e3), 10e6, 2000, Adc(16), None, Seq(EffectSpec("channel_skew", Map("skew_s" -> 30e-9))))
    val (rec, truth) = m.generate()
    val lsb = rec.adc.lsb
    val err = (0 until 2000).map { i =>
      val expect = 2 * math.Pi * truth(i); val c = math.cos(expect + 2 * math.Pi * 100e3 * 30e-9) * 0.9
      math.abs(rec.adc.fromPins(rec.cos(i)) * lsb - c)
    }.max
    err should be < 2 * lsb
  }

  "explain --model" should "fit the effects the simulation already has without reporting them" in {
    val m = PhysicsModel(base.copy(harmonics = Nil), Motion.Ramp(20e3, 200e3, 0.01), 10e6, 60000, Adc(12), None,
      Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 0.003), "sin")))
    val rec = m.generate()._1
    SignalExplain.run("r", rec, Nil, Progress.none).report.findings.map(_.effect) shouldBe Seq("harmonic")
    SignalExplain.run("r", rec, m.effects, Progress.none).report.findings shouldBe empty
  }

  "bad effect options" should "be one-line usage errors" in {
    intercept[moire.explain.ExplainError](EffectSpec.parse("skew:skew_s=1")).getMessage should include("'skew' is not an effect")
    intercept[moire.explain.ExplainError](EffectSpec.parse("channel_skew:skew=1")).getMessage should include("key in skew_s")
    intercept[moire.explain.ExplainError](EffectSpec.parse("channel_skew:skew_s=abc")).getMessage should include("'abc' is not a finite number")
    intercept[moire.explain.ExplainError](EffectSpec.parse("harmonic:order=NaN")).getMessage should include("'NaN' is not a finite number")
    intercept[moire.explain.ExplainError](PhysicsModel(base, Motion.Constant(1), 1e6, 10, Adc(12), None,
      Seq(EffectSpec("amplitude_modulation", Map("depth" -> 0.01)))).generate()).getMessage should include("lines_per_rev")
  }
}
