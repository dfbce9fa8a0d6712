package moire.cordic

import org.scalatest.flatspec.AnyFlatSpec

class DesignerSpec extends AnyFlatSpec {
  "design" should "find a configuration that meets the target by bound and by simulation" in {
    for ((f, target) <- Seq("sin" -> 3.85e-5, "atan2" -> 1e-4, "asin" -> 1e-3)) {
      val d = Designer.cheapest(f, target, Rounding.HalfEven).toOption.get
      info(d.report.linesIterator.take(3).mkString(" | "))
      assert(d.bound <= target && d.measured.maxError <= target && d.measured.ok)
      // One width less must break the bound at the same n: the choice is the cheapest at that n.
      val smaller = d.p.copy(width = d.p.width - 1)
      assert(CordicBound.headline(smaller).total > target)
    }
  }

  it should "refuse targets no configuration can guarantee" in {
    assert(Designer.cheapest("sin", 1e-15, Rounding.HalfEven).isLeft)
  }
}
