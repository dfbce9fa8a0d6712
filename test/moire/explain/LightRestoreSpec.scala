package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A trial that is not kept goes back to the fit before it. A long record's saved state holds no copy of the residual
  * (`SignalEngine.save(light = true)`): the residual is made again from the solution and the columns it was made from.
  * That must be the same fit, to the bit, as the copy gives, with the terms' columns held or made a block at a time.
  */
class LightRestoreSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "a light restore" should "give the fit before the trial to the bit" in {
    val rec = sim(Seq(EffectSpec("channel_skew", Map("skew_s" -> 20e-9)), EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 2e-3), "sin"),
      EffectSpec("interference", Map("frequency_hz" -> 50e3, "amplitude_fs" -> 1e-3)),
      EffectSpec("adc_bit_fault", Map("bit" -> 2, "stuck_at" -> 0), "cos")), n = 60000)
    val sp = ModelSpec(skewS = 20e-9, hasSkew = true, terms = Vector(Term.Harm(3, "sin"), Term.Interference(50e3)),
      faults = Vector(Fault(1, 2, 0, -1)))
    // the terms' columns held (a large holdBytes) and made a block at a time where they are read (none held)
    for (hold <- Seq(1L << 30, 0L)) withClue(s"holdBytes $hold: ") {
      val (a, b) = (new SignalEngine(rec, None, hold), new SignalEngine(rec, None, hold))
      for (e <- Seq(a, b)) { e.init(); e.spec = sp; e.converge() }
      val (resS, resC, bic, beta) = (a.resS.clone(), a.resC.clone(), a.bic, a.sol.beta.clone())
      val backA = a.save(light = true).get; val backB = b.save(light = false).get
      // a trial each: a drift added and fitted, then not kept
      for (e <- Seq(a, b)) { e.spec = sp.copy(terms = sp.terms :+ Term.Drift); e.converge() }
      a.resS should not be resS
      backA(); backB()
      a.resS shouldBe resS; a.resC shouldBe resC
      a.bic shouldBe bic; a.sol.beta shouldBe beta
      // and the fits go on alike from there
      for (e <- Seq(a, b)) e.refit(2, refineTraj = true, from = 1)
      a.resS shouldBe b.resS; a.resC shouldBe b.resC
      a.sol.beta shouldBe b.sol.beta; a.bic shouldBe b.bic
    }
  }

  it should "not be offered where the residual cannot be made again" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 2e-3), "sin")), n = 30000)
    val e = new SignalEngine(rec); e.init(); e.spec = ModelSpec(terms = Vector(Term.Inl("sin"))); e.converge()
    e.save(light = true) shouldBe None
    e.save(light = false) should not be None
  }
}
