package moire.explain

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The channel response without atan (half-angle formulas) against its definition: lags atan(f / fc), the mean lag of
  * the two channels left to the phase, the skew's half-delay on each channel.
  */
class ChannelResponseSpec extends AnyFlatSpec with Matchers {
  private def direct(sp: ModelSpec, f: Double, sn: Double, cs: Double): Array[Double] = {
    def fc(ch: String) = sp.bw.getOrElse(ch, Double.PositiveInfinity)
    val gB = 1 / math.sqrt(1 + math.pow(f / fc("both"), 2))
    val gs = gB / math.sqrt(1 + math.pow(f / fc("sin"), 2)); val gc = gB / math.sqrt(1 + math.pow(f / fc("cos"), 2))
    val lagS = math.atan(f / fc("sin")); val lagC = math.atan(f / fc("cos")); val m = 0.5 * (lagS + lagC)
    val w = 2 * math.Pi * sp.skewS
    val ls = -0.5 * w * f + m - lagS; val lc = 0.5 * w * f + m - lagC
    Array(gs * (sn * math.cos(ls) + cs * math.sin(ls)), gs * (cs * math.cos(ls) - sn * math.sin(ls)),
      gc * (sn * math.cos(lc) + cs * math.sin(lc)), gc * (cs * math.cos(lc) - sn * math.sin(lc)))
  }

  "ChannelResponse" should "equal its definition for skews, cut-offs on either channel and both, at any speed" in {
    val rnd = new scala.util.Random(3)
    val specs = Seq(ModelSpec(), ModelSpec(hasSkew = true, skewS = 20e-9), ModelSpec(bw = Map("sin" -> 600e3)),
      ModelSpec(bw = Map("cos" -> 80e3, "both" -> 1e6)),
      ModelSpec(hasSkew = true, skewS = 20e-9, bw = Map("both" -> 600e3)), ModelSpec(hasSkew = true, skewS = -3e-7, bw = Map("sin" -> 5e3, "cos" -> 2e6)))
    var worst = 0.0
    for (sp <- specs; _ <- 0 until 2000) {
      val f = (if (rnd.nextBoolean()) -1 else 1) * math.pow(10, 6 * rnd.nextDouble()); val a = 2 * math.Pi * rnd.nextDouble()
      val o = new Array[Double](4); new ChannelResponse(sp)(f, math.sin(a), math.cos(a), o)
      val d = direct(sp, f, math.sin(a), math.cos(a))
      for (j <- 0 until 4) worst = math.max(worst, math.abs(o(j) - d(j)))
    }
    worst should be < 1e-13
  }
}
