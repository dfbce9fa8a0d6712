package moire.harmonic

import moire.calibration._

import org.scalatest.flatspec.AnyFlatSpec

/** The bit-accurate model against double precision, within the a priori bound, over a parameter sweep. */
class HarmonicModelSpec extends AnyFlatSpec {
  val sweep: Seq[HarmonicParams] = Seq(
    HarmonicParams(),
    HarmonicParams(harmonics = 8, iterations = 12, dataBits = 14),
    HarmonicParams(lines = 4096, subdivision = 256, harmonics = 2, iterations = 20, dataBits = 24, outFrac = 20),
    HarmonicParams(lines = 1 << 20, subdivision = 4096, harmonics = 3, coefWidth = 32, coefFrac = 16, kFrac = 32),
    HarmonicParams(lines = 64, subdivision = 16, harmonics = 1, iterations = 8, dataBits = 10, coefWidth = 16, coefFrac = 6,
      maxOrder = 7, outFrac = 2, kFrac = 10))

  for (p <- sweep) {
    p.moduleName should "stay within its bound against double precision for random coefficients" in {
      val rnd = new scala.util.Random(p.hashCode)
      val model = new HarmonicModel(p)
      var worstRatio = 0.0
      for (_ <- 0 until 20) {
        val cMax = math.pow(2, p.coefWidth - 1 - p.coefFrac) / p.harmonics
        val slots = Seq.fill(p.harmonics)(HarmonicSlot.of(p, rnd.nextInt(math.min(p.maxOrder, 64) + 1),
          (rnd.nextDouble() * 2 - 1) * cMax, rnd.nextDouble() * 360))
        val sumC = slots.map(s => math.abs(s.c) * math.pow(2, -p.coefFrac)).sum
        val bound = HarmonicBound.arcsec(p, sumC)
        for (_ <- 0 until 200) {
          val theta = rnd.nextLong() >>> (64 - p.countBits)
          val err = math.abs(model.fArcsec(theta, model(theta, slots).out) - HarmonicReference.ofSlots(p, theta, slots))
          assert(err <= bound, s"theta $theta slots $slots: error $err > bound $bound arcsec")
          worstRatio = math.max(worstRatio, err / bound)
        }
      }
      info(f"largest error / bound = $worstRatio%.3f")
      assert(worstRatio > 0.05, "the bound should not be vacuous")
    }
  }

  "The eq. 19 bound" should "cover the measured eq. 19 error" in {
    val b = HarmonicBound.arcsec(HarmonicParams(), moire.cordic.PaperBounds.seed001Eq19.map(c => math.abs(c._2)).sum)
    val m = HarmonicReproduce.modelMax()
    info(f"measured $m%.4e arcsec, our bound $b%.4e arcsec (worst-case rounding per step), paper P_max 1.19e-3")
    assert(m < b)
  }
}
