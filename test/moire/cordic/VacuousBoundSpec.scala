package moire.cordic

import org.scalatest.flatspec.AnyFlatSpec

/** A bound a constant output would meet says nothing: it is marked, and `design` never picks it. */
class VacuousBoundSpec extends AnyFlatSpec {
  "A bound of half the output's range or more" should "be marked vacuous, and a useful one not" in {
    // n = 40 at b = 8: 39 roundings of 2^-7 swamp the word (atan2 12.6 rad, asin-double 2.65 rad)
    for (mode <- Seq(CordicMode.Atan2, CordicMode.AsinDouble, CordicMode.AcosDouble)) {
      val m = CordicAccuracy.measure(CordicParams(mode, 40, 8))
      assert(m.ok && m.vacuous, f"$mode n=40 b=8: bound ${m.bound}%.3e")
    }
    for (mode <- CordicMode.all) {
      val m = CordicAccuracy.measure(CordicParams(mode, 16, 18))
      assert(m.ok && !m.vacuous, f"$mode n=16 b=18: bound ${m.bound}%.3e")
    }
    assert(CordicBound.constantError(CordicParams(CordicMode.Asin, 8, 12)) == math.Pi / 2)
  }

  "design" should "refuse a target a constant output meets" in {
    val e = Designer.cheapest("asin", 2.0, Rounding.HalfEven)
    assert(e.left.exists(_.contains("pi/2 radians")), e)
    assert(Designer.cheapest("sin", 1.0, Rounding.HalfEven).isLeft)
    assert(Designer.cheapest("atan2", math.Pi, Rounding.HalfEven).isLeft)
  }

  it should "pick a configuration with a meaningful bound just below half the range" in {
    for ((f, target) <- Seq("sin" -> 0.99, "atan2" -> 3.1, "asin" -> 1.5, "acos" -> 1.5)) {
      val d = Designer.cheapest(f, target, Rounding.HalfEven).toOption.get
      assert(d.bound <= target && !CordicBound.vacuous(d.p, d.bound) && d.measured.ok, d.report)
    }
  }
}
