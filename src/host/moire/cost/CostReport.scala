package moire.cost

import moire.cordic.{CordicBound, CordicMode, CordicParams}

/** The resources of the Cyclone IV E EP4CE115 on the DE2-115 board. */
object Ep4ce115 {
  val logicElements: Long = 114480L
  val memoryBits: Long = 3981312L
  val multipliers18: Long = 266L
  def pct(used: Long, of: Long): String = f"${100.0 * used / of}%.2f%%"
}

/** Seed 001 Table 1: the pipelined sine CORDIC in Quartus, n = 16, b = 18. */
object PaperAnchor {
  val logicElements = 2769
  val clocks = 15
  val accuracy = 3.13e-5
  val goalCells = 2000
  /** Is this the paper's configuration? Its b = 18 counts fractional bits (width 20 here); width 18 is our default. */
  def applies(p: CordicParams): Boolean = p.mode == CordicMode.SinCos && p.iterations == 16 && (p.width == 18 || p.width == 20)
  /** Sine CORDICs are printed next to the paper's. */
  def compares(p: CordicParams): Boolean = p.mode == CordicMode.SinCos
}

/** What `cost` reports for one design. */
final case class CostReport(design: String, what: String, synth: SynthResult, latency: Option[Int],
                            cordic: Option[CordicParams]) {
  def logicCells: Long = synth.total.logicCells
  def registers: Long = synth.total.registers
  def errorBound: Option[Double] = cordic.map(p => CordicBound.headline(p).total)

  def json: ujson.Obj = {
    val o = ujson.Obj(
      "design" -> design, "top" -> synth.top,
      "logic_cells" -> ujson.Num(logicCells.toDouble), "registers" -> ujson.Num(registers.toDouble), "luts" -> ujson.Num(synth.total.luts.toDouble),
      "memory_bits" -> ujson.Num(synth.memoryBits.toDouble), "m9k_blocks" -> ujson.Num(synth.m9kBlocks.toDouble), "block_ram_bits" -> ujson.Num(synth.blockRamBits.toDouble), "multipliers" -> ujson.Num(synth.multipliers.toDouble),
      "cells_by_type" -> ujson.Obj.from(synth.total.cells.toSeq.sortBy(_._1).map { case (t, n) => t -> ujson.Num(n.toDouble) }),
      "unmapped_cells" -> ujson.Obj.from(synth.total.unmapped.toSeq.sortBy(_._1).map { case (t, n) => t -> ujson.Num(n.toDouble) }),
      "longest_path_cells" -> synth.longestPathCells.map(n => ujson.Num(n)).getOrElse(ujson.Null),
      "latency" -> latency.map(n => ujson.Num(n)).getOrElse(ujson.Null),
      "yosys_seconds" -> math.round(synth.seconds * 10) / 10.0,
      "capacity" -> ujson.Obj("device" -> "EP4CE115", "logic_elements" -> ujson.Num(Ep4ce115.logicElements.toDouble),
        "memory_bits" -> ujson.Num(Ep4ce115.memoryBits.toDouble), "multipliers_18x18" -> ujson.Num(Ep4ce115.multipliers18.toDouble)))
    cordic.foreach { p =>
      o("results_per_clock") = 1
      o("error_bound") = CordicBound.headline(p).total
      o("mode") = p.mode.name; o("iterations") = p.iterations; o("width") = p.width
    }
    if (synth.modules.nonEmpty) o("modules") = ujson.Arr(synth.modules.map(m => ujson.Obj("module" -> m.name,
      "logic_cells" -> ujson.Num(m.logicCells.toDouble), "registers" -> ujson.Num(m.registers.toDouble), "luts" -> ujson.Num(m.luts.toDouble), "m9k_blocks" -> ujson.Num(m.m9k.toDouble),
      "multiplier_cells" -> ujson.Num(m.multCells.toDouble))): _*)
    o
  }

  def text: String = {
    val b = new StringBuilder
    val t = synth.total
    b ++= s"$design: $what\n  top ${synth.top}, yosys 0.23 synth_intel -family cycloneive (${f"${synth.seconds}%.0f"} s)\n"
    if (synth.modules.nonEmpty) {
      val w = synth.modules.map(_.name.length).max
      b ++= s"  ${"module".padTo(w, ' ')} " + f"${"logic cells"}%11s ${"LUTs"}%7s ${"FFs"}%7s ${"RAMs"}%5s ${"mults"}%5s  (one instance each)\n"
      for (m <- synth.modules.sortBy(-_.logicCells))
        b ++= s"  ${m.name.padTo(w, ' ')} " + f"${m.logicCells}%11d ${m.luts}%7d ${m.registers}%7d ${m.m9k}%5d ${m.multCells}%5d\n"
    }
    b ++= f"  total: ${t.logicCells} logic cells (${t.luts} LUTs + ${t.registers} registers) = ${Ep4ce115.pct(t.logicCells, Ep4ce115.logicElements)} of the EP4CE115's ${Ep4ce115.logicElements} LEs\n"
    b ++= f"  memory: ${synth.memoryBits} bits inferred, ${synth.blockRamBits} of them in block RAM (${synth.m9kBlocks} of 432 M9K blocks; the rest in logic) = ${Ep4ce115.pct(synth.blockRamBits, Ep4ce115.memoryBits)} of ${Ep4ce115.memoryBits} bits; " +
      f"multipliers: ${synth.multipliers} of ${Ep4ce115.multipliers18} 18x18 (${Ep4ce115.pct(synth.multipliers, Ep4ce115.multipliers18)})\n"
    if (t.unmapped.nonEmpty)
      b ++= s"  left unmapped by synth_intel (generic yosys cells, not in the logic cells): ${t.unmapped.toSeq.sortBy(_._1).map { case (c, n) => s"$c $n" }.mkString(", ")}\n"
    b ++= s"  longest path between registers: ${synth.longestPathCells.map(n => s"$n LUT cells").getOrElse("not measured")}\n"
    latency.foreach(l => b ++= s"  latency $l clocks${if (cordic.isDefined) ", one result per clock" else ""}\n")
    cordic.foreach { p =>
      b ++= f"  error bound ${CordicBound.headline(p).total}%.3e ${if (p.mode == CordicMode.SinCos || p.mode == CordicMode.Rotate) "(full scale 1.0)" else "rad"}\n"
      if (PaperAnchor.compares(p)) b ++= anchorLine(p) + "\n"
    }
    b.toString
  }

  def anchorLine(p: CordicParams): String =
    f"  paper (seed 001 Table 1, Quartus): ${PaperAnchor.logicElements} LEs, ${PaperAnchor.clocks} clocks, ${PaperAnchor.accuracy}%.2e" +
      f" | ours (yosys, ${if (p.taper) "tapered" else "conventional"}): $logicCells logic cells, ${p.latency} clocks, bound ${CordicBound.headline(p).total}%.2e" +
      f" | goal (bound <= ${PaperAnchor.accuracy}%.2e in <= ${PaperAnchor.goalCells} cells): " + goal(p)

  private def goal(p: CordicParams): String = {
    val why = Seq((CordicBound.headline(p).total > PaperAnchor.accuracy) -> "bound above", (logicCells > PaperAnchor.goalCells) -> "cells above")
      .collect { case (true, w) => w }
    if (why.isEmpty) "met" else s"not met (${why.mkString(", ")})"
  }
}
