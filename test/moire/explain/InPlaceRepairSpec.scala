package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A refit's repair writes the repaired channel and its weights' spread over the fit's own arrays (at 20 M samples
  * 240 MB a refit less), and into new ones while a saved state holds them. Both must give the same fit to the bit.
  */
class InPlaceRepairSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "a stuck bit's repair" should "give the same fit over its own arrays as into new ones" in {
    for ((bit, noise) <- Seq((1, 1.2), (4, 1.5))) withClue(s"bit $bit stuck, $noise LSB of noise: ") {
      val rec = sim(Seq(EffectSpec("adc_bit_fault", Map("bit" -> bit, "stuck_at" -> 0), "cos")), n = 60000, noiseLsb = noise)
      val sp = ModelSpec(faults = Vector(Fault(1, bit, 0, -1)))
      val (a, b) = (new SignalEngine(rec), new SignalEngine(rec))
      for (e <- Seq(a, b)) { e.init(); e.spec = sp; e.refit(2, refineTraj = true) }
      val (own, bOwn) = (a.repC, b.repC)
      for (k <- 2 until 8) {
        a.refit(k + 1, refineTraj = true, from = k)
        b.save() // its arrays held: the next repair makes new ones
        b.refit(k + 1, refineTraj = true, from = k)
      }
      a.repC shouldBe theSameInstanceAs(own) // the repairs wrote over the fit's arrays
      b.repC should not be theSameInstanceAs(bOwn)
      a.cens.pvC should not be null
      a.repC shouldBe b.repC
      a.cens.pvC shouldBe b.cens.pvC
      a.sol.beta shouldBe b.sol.beta
      a.bic shouldBe b.bic
    }
  }
}
