package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The families of one pass (`LinearSweep`) against the same families from their columns (`termCols`): every variant's
  * coefficients and residual sums of squares agree, with plain fundamentals and with skewed ones.
  */
class LinearSweepSpec extends AnyFlatSpec with Matchers {
  import ExplainSupport._

  "LinearSweep" should "give every family's variants the fits their columns give" in {
    val rec = sim(Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 5e-4), "sin"),
      EffectSpec("drift", Map("offset_sin_per_s" -> 0.02, "gain_cos_per_s" -> 0.05)),
      EffectSpec("channel_skew", Map("skew_s" -> 30e-9))), n = 60000)
    val e = new SignalEngine(rec)
    e.init()
    var checked = 0
    for (sp <- Seq(ModelSpec(), ModelSpec(hasSkew = true, skewS = 30e-9, terms = Vector(Term.Harm(3, "sin"))))) {
      if (sp != ModelSpec()) { e.spec = sp; e.converge() }
      val yy = (e.sumSq(e.resS), e.sumSq(e.resC))
      val swept = LinearSweep(e, Seq(2, 3, 5), yy._1, yy._2)
      swept.keySet shouldBe LinearSweep.terms(Seq(2, 3, 5)).toSet
      for ((t, fam) <- swept; ch <- Seq("sin", "cos", "both")) {
        val cols = e.baseCols(e.s1, e.s2, e.c1, e.c2) ++ e.termCols(t)
        val plain = LinearFamily(cols, e.resS, e.resC, yy._1, yy._2)
        def sin(j: Int) = (j < 6 || ch != "cos") && fam.hasSin(j); def cos(j: Int) = (j < 6 || ch != "sin") && fam.hasCos(j)
        fam.hasSin shouldBe plain.hasSin; fam.hasCos shouldBe plain.hasCos
        val use = fam.hasSin.indices.filter(j => sin(j) || cos(j))
        val (a, as, ac) = fam.fit(use, sin, cos); val (b, bs, bc) = plain.fit(use, sin, cos)
        withClue(s"$t $ch") {
          a.ok shouldBe b.ok
          for (j <- use.indices) a.beta(j) shouldBe b.beta(j) +- 1e-8 * (1e-6 + math.abs(b.beta(j)))
          as shouldBe bs +- 1e-9 * bs; ac shouldBe bc +- 1e-9 * bc
        }
        checked += 1
      }
    }
    checked shouldBe 2 * 7 * 3
  }
}
