package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A term's channel variants read off its family's per-channel sums against the plain fit of each variant's own
  * columns: the same coefficients and residual sums of squares.
  */
class LinearFamilySpec extends AnyFlatSpec with Matchers {
  "LinearFamily" should "give each channel variant the fit of its own columns" in {
    val rnd = new scala.util.Random(11); val n = 6000
    def col() = Array.fill(n)(rnd.nextGaussian())
    val base = IndexedSeq(Col(Array.fill(n)(1.0), null), Col(col(), null), Col(col(), null), Col(null, Array.fill(n)(1.0)), Col(null, col()), Col(null, col()))
    // a harmonic-like family (two columns on each channel) and an INL-like one (two columns on both channels)
    val harm = IndexedSeq(Col(col(), null), Col(col(), null), Col(null, col()), Col(null, col()))
    val inl = IndexedSeq(Col(col(), col()), Col(col(), col()))
    val ys = Array.tabulate(n)(i => 0.3 * base(1).s(i) + 0.02 * harm(0).s(i) + 0.01 * inl(1).s(i) + 0.1 * rnd.nextGaussian())
    val yc = Array.tabulate(n)(i => -0.2 * base(5).c(i) + 0.03 * harm(3).c(i) + 0.1 * rnd.nextGaussian())
    def ss(a: Array[Double]) = a.map(x => x * x).sum
    var checked = 0
    for (fam <- Seq(harm, inl); ch <- Seq("sin", "cos", "both")) {
      val all = base ++ fam
      val f = LinearFamily(all, ys, yc, ss(ys), ss(yc))
      def sin(j: Int) = (j < 6 || ch != "cos") && f.hasSin(j); def cos(j: Int) = (j < 6 || ch != "sin") && f.hasCos(j)
      val use = all.indices.filter(j => sin(j) || cos(j))
      val (s, a, b) = f.fit(use, sin, cos)
      // the variant's own columns: the family's with the other channel's parts left out
      val own = use.map(j => Col(if (sin(j)) all(j).s else null, if (cos(j)) all(j).c else null))
      val plain = LinearFit.solve(own, ys, yc)
      for (k <- use.indices) s.beta(k) shouldBe plain.beta(k) +- 1e-9 * (1 + math.abs(plain.beta(k)))
      a shouldBe LinearFit.rss(own, plain.beta, ys, sinCh = true) +- 1e-9 * a
      b shouldBe LinearFit.rss(own, plain.beta, yc, sinCh = false) +- 1e-9 * b
      checked += 1
    }
    checked shouldBe 6
  }
}
