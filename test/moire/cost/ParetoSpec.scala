package moire.cost

import moire.cordic.{CordicMode, CordicParams}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

class ParetoSpec extends AnyFlatSpec with Matchers {
  private def row(f: String, cells: Long, bound: Double, n: Int) =
    SweepRow("v", f, CordicParams(CordicMode.SinCos, n, 16), cells, 0, cells, 0, 0, None, bound, None)

  "Pareto.mark" should "keep exactly the rows no other row of the same function beats on cells and bound" in {
    val rows = Seq(row("sin", 100, 1e-2, 4), row("sin", 200, 1e-3, 5), row("sin", 250, 2e-3, 6),
      row("sin", 300, 1e-3, 7), row("sin", 400, 1e-4, 8), row("asin", 150, 1e-2, 9), row("asin", 120, 1e-3, 10))
    val marked = Pareto.mark(rows)
    marked.filter(_.pareto).map(_.p.iterations).sorted shouldBe Seq(4, 5, 8, 10)
    for (r <- marked; dominated = marked.exists(o => o != r && o.function == r.function &&
      o.logicCells <= r.logicCells && o.errorBound <= r.errorBound && (o.logicCells < r.logicCells || o.errorBound < r.errorBound)))
      r.pareto shouldBe !dominated
  }

  "Pareto.cheapest" should "pick the fewest cells whose bound meets the target" in {
    val rows = Seq(row("sin", 100, 1e-2, 4), row("sin", 200, 1e-3, 5), row("sin", 400, 1e-4, 8))
    Pareto.cheapest(rows, "sin", 5e-3).map(_.logicCells) shouldBe Some(200)
    Pareto.cheapest(rows, "sin", 1e-5) shouldBe None
    Pareto.cheapest(rows, "asin", 1.0) shouldBe None
  }

  "SweepGrid" should "keep the balanced (n, b) pairs of the lists" in {
    val g = SweepGrid(Variant.all.take(1), Seq(6, 8, 10, 12), Seq(10, 12), 2)
    g.points.map { case (_, p) => (p.iterations, p.width) } shouldBe Seq((8, 10), (10, 10), (10, 12), (12, 12))
  }
}
