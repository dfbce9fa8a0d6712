package moire.reproduce

import moire.paper.AccuracyRow

import moire.cordic._
import org.scalatest.flatspec.AnyFlatSpec

class ReproduceSpec extends AnyFlatSpec {
  lazy val rows: Seq[AccuracyRow] = Reproduce.rows()

  "The accuracy report" should "hold on every row and carry the JSON fields" in {
    rows.filterNot(_.holds).foreach(r => info(s"does not hold: ${r.item}: paper ${r.paper} ours ${r.ours} ${r.note}"))
    assert(rows.forall(_.holds))
    for (r <- rows; k <- Seq("source", "item", "paper", "ours", "unit", "holds")) assert(r.json.obj.contains(k))
    assert(rows.count(_.source == "seed001") == 28 && rows.count(_.source == "seed002") == 42)
  }

  "Seed 001 Table 1" should "come out of eq. 15 as printed" in {
    assert(math.abs(PaperBounds.seed001Lmax(16, 18) - 3.13e-5) < 0.005 * 3.13e-5)
  }

  "Seed 002 Table 2" should "match the paper cell for cell, from simulation" in {
    for (((m, n, b), (conv, impr)) <- PaperBounds.seed002Table2) {
      assert(Reproduce.seed002Achieved(CordicMode.Asin, n, b, m)._1 == conv, s"conventional M=$m ($n,$b)")
      assert(Reproduce.seed002Achieved(CordicMode.AsinDouble, n, b, m)._1 == impr, s"double M=$m ($n,$b)")
    }
  }
}
