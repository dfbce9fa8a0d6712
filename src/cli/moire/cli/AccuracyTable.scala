package moire.cli

import moire.paper.AccuracyRow

object AccuracyTable {
  private def show(v: ujson.Value): String = v match {
    case ujson.Num(d) => if (d != 0 && (math.abs(d) < 1e-2 || math.abs(d) >= 1e5)) f"$d%.4e" else f"$d%.5f"
    case ujson.Str(s) => s
    case other => other.toString
  }
  def print(rows: Seq[AccuracyRow]): Unit = {
    val header = Seq("source", "item", "paper", "ours", "unit", "holds")
    val cells = rows.map(r => Seq(r.source, r.item, show(r.paper), show(r.ours), r.unit, if (r.holds) "yes" else "NO"))
    val widths = header.indices.map(i => (header +: cells).map(_(i).length).max)
    def line(c: Seq[String]) = c.zip(widths).map { case (s, w) => s.padTo(w, ' ') }.mkString("  ")
    println(line(header))
    println(widths.map("-" * _).mkString("  "))
    cells.foreach(c => println(line(c)))
  }
}
