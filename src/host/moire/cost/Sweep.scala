package moire.cost

import moire.cordic.{CordicMode, CordicParams, Rounding, TaperFigures}

/** One CORDIC variant of the sweep: `function` is what it computes ("sin" or "asin"), which sets the
  * error unit (full scale 1.0 or radians) and the plot it lands in.
  */
final case class Variant(name: String, function: String, make: (Int, Int) => CordicParams, extra: Seq[(Int, Int)] = Nil)

object Variant {
  val all: Seq[Variant] = Seq(
    Variant("sincos", "sin", (n, b) => CordicParams(CordicMode.SinCos, n, b)),
    Variant("sincos-truncate", "sin", (n, b) => CordicParams(CordicMode.SinCos, n, b, rounding = Rounding.Truncate)),
    Variant("sincos-taper", "sin", (n, b) => CordicParams(CordicMode.SinCos, n, b, taper = true)),
    // The lean configuration of TaperFigures (n = 17, b = 20) is always in the sweep.
    Variant("sincos-taper-g2", "sin", (n, b) => CordicParams(CordicMode.SinCos, n, b, guardBits = 2, angleGuardBits = 3, taper = true),
      extra = Seq((TaperFigures.lean.iterations, TaperFigures.lean.width))),
    Variant("asin", "asin", (n, b) => CordicParams(CordicMode.Asin, n, b)),
    Variant("asin-double", "asin", (n, b) => CordicParams(CordicMode.AsinDouble, n, b)),
    Variant("asin-table", "asin", (n, b) => CordicParams(CordicMode.Asin, n, b, peakTableSize = 64))
  )
  def parse(s: String): Either[String, Seq[Variant]] = {
    val names = s.split(",").map(_.trim).filter(_.nonEmpty).toSeq
    // each name checked by the one choice reader; the sweep keeps the catalogue's order
    names.foldLeft[Either[String, Unit]](Right(()))((ok, n) => ok.flatMap(_ => moire.choice.Choice(all, n, s"--variants: '$n' is not a variant")(_.name).map(_ => ())))
      .map(_ => all.filter(v => names.contains(v.name)))
  }
}

/** One synthesized configuration with its error bound. */
final case class SweepRow(variant: String, function: String, p: CordicParams, logicCells: Long, registers: Long, luts: Long,
                          memoryBits: Long, multipliers: Long, longestPathCells: Option[Int], errorBound: Double,
                          measuredError: Option[Double], pareto: Boolean = false) {
  def unit: String = if (function == "sin") "full scale" else "rad"
  def json: ujson.Obj = ujson.Obj(
    "variant" -> variant, "function" -> function, "mode" -> p.mode.name, "iterations" -> p.iterations, "width" -> p.width,
    "peak_table" -> p.peakTableSize, "module" -> p.moduleName, "logic_cells" -> ujson.Num(logicCells.toDouble), "registers" -> ujson.Num(registers.toDouble),
    "luts" -> ujson.Num(luts.toDouble), "memory_bits" -> ujson.Num(memoryBits.toDouble), "multipliers" -> ujson.Num(multipliers.toDouble),
    "longest_path_cells" -> longestPathCells.map(n => ujson.Num(n)).getOrElse(ujson.Null),
    "latency" -> p.latency, "results_per_clock" -> 1, "error_bound" -> errorBound,
    "measured_error" -> measuredError.map(ujson.Num(_)).getOrElse(ujson.Null), "unit" -> unit, "pareto" -> pareto)
}

object SweepRow {
  val csvHeader: String = "variant,function,mode,iterations,width,peak_table,logic_cells,registers,luts,memory_bits," +
    "multipliers,longest_path_cells,latency,error_bound,measured_error,unit,pareto"
  def csv(r: SweepRow): String = Seq(r.variant, r.function, r.p.mode.name, r.p.iterations, r.p.width, r.p.peakTableSize,
    r.logicCells, r.registers, r.luts, r.memoryBits, r.multipliers, r.longestPathCells.getOrElse(""), r.p.latency,
    f"${r.errorBound}%.6e", r.measuredError.map(e => f"$e%.6e").getOrElse(""), r.unit, r.pareto).mkString(",")
}

/** The accuracy-versus-logic Pareto front. */
object Pareto {
  /** Marks, per function, the rows no other row beats on both logic cells and error bound. */
  def mark(rows: Seq[SweepRow]): Seq[SweepRow] = {
    val front = rows.groupBy(_.function).values.flatMap { rs =>
      var best = Double.PositiveInfinity
      rs.sortBy(r => (r.logicCells, r.errorBound)).flatMap { r =>
        if (r.errorBound < best) { best = r.errorBound; Some(r) } else None
      }
    }.toSet
    rows.map(r => r.copy(pareto = front.contains(r)))
  }

  /** The cheapest row whose bound meets `target`, per function. */
  def cheapest(rows: Seq[SweepRow], function: String, target: Double): Option[SweepRow] =
    rows.filter(r => r.function == function && r.errorBound <= target).sortBy(r => (r.logicCells, r.errorBound)).headOption
}
