package moire.explain.evidence

import java.util.Random

/** A fibre interferometer read by a 3x3 coupler: three detector outputs I_k = D_k (1 + V cos(phi - 2 pi k / 3 + e_k)),
  * each averaged over 1 s (`sub` sub-samples a second), turned into quadrature by the usual sums
  * sin = sqrt(3) (I_1 - I_2), cos = 2 I_0 - I_1 - I_2, scaled to `fill` of a 16-bit range. The motion is a slow
  * wander of the arm (temperature), `totalPeriods` over the record, plus a random walk.
  */
object Coupler {
  final case class Spec(n: Int = 600, totalPeriods: Double = 7.5, walkPeriods: Double = 0.004, fill: Double = 0.6, noiseLsb: Double = 3.0,
                        sub: Int = 20, seed: Long = 1)

  def text(s: Spec): String = {
    val rnd = new Random(s.seed)
    val fine = Motions.wander(s.n * s.sub, s.sub.toDouble, s.totalPeriods, s.walkPeriods / math.sqrt(s.sub), 30.0 * s.sub, s.seed)
    val d = Array(1.0, 0.94, 1.07); val e = Array(0.0, math.toRadians(2.1), math.toRadians(-1.4)); val vis = 0.93
    val half = 1 << 15
    def code(v: Double) = math.max(0, math.min(2 * half - 1, math.floor(v * half + 0.5).toInt + half))
    val cs = new Array[Int](s.n); val cc = new Array[Int](s.n)
    for (i <- 0 until s.n) {
      val mean = Array(0.0, 0.0, 0.0)
      for (j <- 0 until s.sub; k <- 0 until 3) {
        val phi = 2 * math.Pi * fine.periods(i * s.sub + j)
        mean(k) += d(k) * (1 + vis * math.cos(phi - 2 * math.Pi * k / 3 + e(k))) / s.sub
      }
      val scale = s.fill / (3 * vis) // both sums are 3 V times the fringe
      cs(i) = code(scale * math.sqrt(3) * (mean(1) - mean(2)) + s.noiseLsb / half * rnd.nextGaussian())
      cc(i) = code(scale * (2 * mean(0) - mean(1) - mean(2)) + s.noiseLsb / half * rnd.nextGaussian())
    }
    BenchText("3x3 coupler interferometer, 1 s means", 1.0, 16, (cs, cc), Seq("adc" -> "24-bit DAQ, 16-bit export"))
  }
}
