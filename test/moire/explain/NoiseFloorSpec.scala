package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** `Adequacy.floorOf` (its passes made without the squares' array, the count without a pass, the threshold by
  * selection) against the floor's definition, written plainly: every square made, a strided sample sorted.
  */
class NoiseFloorSpec extends AnyFlatSpec with Matchers {
  private def definition(rs: Array[Double], rc: Array[Double], a: Int, b: Int, k: Int, skip: Array[Boolean], minCount: Int): Double = {
    val c = Array.tabulate(k + 1)(j => (if (j % 2 == 0) 1.0 else -1.0) * (0 until j).foldLeft(1.0)((x, m) => x * (k - m) / (m + 1)))
    val sq = Array.newBuilder[Double]
    for (i <- math.max(0, a) until b - k if skip == null || !(i to i + k).exists(skip(_)); r <- Seq(rs, rc) if r != null) {
      var s = 0.0; for (j <- 0 to k) s += c(j) * r(i + j); sq += s * s
    }
    val v = sq.result(); val m = v.length
    if (m < minCount) return Double.NaN
    if (m == 0) return 0.0
    val stride = math.max(1, m / 40000)
    val smp = v.indices.by(stride).map(v).toArray.sorted
    val thr = smp(math.min(smp.length - 1, ((1 - Adequacy.Trim) * smp.length).toInt))
    val kept = v.filter(_ <= thr); var s = 0.0; kept.foreach(s += _)
    val p = kept.length.toDouble / m
    val ms = if (kept.isEmpty) 0.0 else if (p >= 1) s / kept.length else {
      val q = new org.hipparchus.distribution.continuous.NormalDistribution(0, 1).inverseCumulativeProbability(0.5 + 0.5 * p)
      val cc = 1 - 2 * q * math.exp(-0.5 * q * q) / math.sqrt(2 * math.Pi) / p
      if (cc > 0) s / kept.length / cc else s / kept.length
    }
    math.sqrt(ms / c.map(x => x * x).sum)
  }

  "Adequacy.floorOf" should "give the definition's floor to the bit: both channels or one, 2nd and 4th differences, windows, skipped samples" in {
    val rnd = new scala.util.Random(7)
    val n = 150001 // more than 40,000 squares: a strided sample
    // Gaussian noise with a few outliers (the trim matters) and a slow misfit
    def channel() = Array.tabulate(n)(i => 1e-3 * rnd.nextGaussian() + (if (rnd.nextInt(500) == 0) 0.05 * rnd.nextGaussian() else 0.0) + 1e-3 * math.sin(i * 1e-3))
    val rs = channel(); val rc = channel()
    val skip = Array.tabulate(n)(_ => rnd.nextInt(50) == 0)
    for (k <- Seq(Adequacy.JudgeOrder, Adequacy.NoiseOrder); both <- Seq(true, false); sk <- Seq(null, skip);
         (a, b) <- Seq((0, n), (-3, n), (1000, 5687), (n - 40, n), (77, 80), (5, 5))) withClue(s"k $k, both $both, skip ${sk != null}, [$a, $b): ") {
      val r2 = if (both) rc else null
      val got = Adequacy.floorOf(rs, r2, a, b, k, sk); val want = definition(rs, r2, a, b, k, sk, 0)
      java.lang.Double.doubleToLongBits(got) shouldBe java.lang.Double.doubleToLongBits(want)
    }
    Adequacy.floorOf(rs, null, 0, 60, 4, skip, minCount = 64).isNaN shouldBe true
    definition(rs, null, 0, 60, 4, skip, 64).isNaN shouldBe true
  }
}
