package moire.cost

import moire.cordic.{CordicAccuracy, CordicBound, CordicParams}

/** The grid of a sweep: every (n, b) of the lists with `b - spread <= n <= b` (balanced: neither term dominates). */
final case class SweepGrid(variants: Seq[Variant], iterations: Seq[Int], widths: Seq[Int], spread: Int) {
  def points: Seq[(Variant, CordicParams)] = variants.flatMap { v =>
    val grid = for (b <- widths; n <- iterations if n <= b && n >= b - spread) yield (n, b)
    (grid ++ v.extra.filterNot(grid.contains)).map { case (n, b) => (v, v.make(n, b)) }
  }
}

/** Runs a sweep with a cache keyed by the emitted Verilog, writes CSV, JSON and the plots. */
object SweepRun {
  /** A configuration's synthesis, read from the cache when the same Verilog was synthesized before. */
  def synth(p: CordicParams, cache: os.Path, timeoutSeconds: Int, progress: String => Unit): (SynthResult, Boolean) = {
    val work = os.temp.dir(prefix = "moire-sweep-", deleteOnExit = false)
    try {
      val d = moire.designs.Designs.cordic(p)
      val files = d.write(work / "rtl", moire.emit.Target.Verilog); val top = d.topName
      val key = sha1(files.map(os.read(_)).mkString + Yosys.script("T", Nil, flatten = true))
      val entry = cache / s"${p.moduleName}-$key.json"
      if (os.exists(entry)) (fromJson(ujson.read(os.read(entry)), top), true)
      else {
        val r = Yosys.run(top, files, work / "flat", flatten = true, timeoutSeconds, progress)
        os.write.over(entry, ujson.write(toJson(r)), createFolders = true)
        (r, false)
      }
    } finally os.remove.all(work)
  }

  private def sha1(s: String): String =
    java.security.MessageDigest.getInstance("SHA-1").digest(s.getBytes("UTF-8")).take(8).map("%02x".format(_)).mkString

  private def toJson(r: SynthResult): ujson.Obj = ujson.Obj("cells" -> ujson.Obj.from(r.total.cells.map { case (k, v) => k -> ujson.Num(v.toDouble) }),
    "memory_bits" -> ujson.Num(r.memoryBits.toDouble), "multipliers" -> ujson.Num(r.multipliers.toDouble),
    "longest_path_cells" -> r.longestPathCells.map(n => ujson.Num(n)).getOrElse(ujson.Null), "seconds" -> r.seconds)
  private def num(v: ujson.Value): Double = v match { case ujson.Str(s) => s.toDouble; case o => o.num }
  private def fromJson(v: ujson.Value, top: String): SynthResult = SynthResult(top,
    ModuleCells(top, v("cells").obj.map { case (k, n) => k -> num(n).toLong }.toMap), Nil, num(v("memory_bits")).toLong,
    num(v("multipliers")).toLong, v("longest_path_cells").numOpt.map(_.toInt), num(v("seconds")))

  def run(grid: SweepGrid, out: os.Path, timeoutSeconds: Int, measure: Boolean, log: String => Unit): Seq[SweepRow] = {
    val pts = grid.points
    val pb = new moire.progress.Bar("cost sweep", pts.size.toLong)
    val rows = try pts.map { case (v, p) =>
      pb.setExtraMessage(s" ${v.name} n=${p.iterations} b=${p.width}")
      val (s, _) = synth(p, out / "cache", timeoutSeconds, m => log(m))
      val measured = if (measure) Some(CordicAccuracy.measure(p).maxError) else None
      pb.step()
      SweepRow(v.name, v.function, p, s.total.logicCells, s.total.registers, s.total.luts, s.memoryBits, s.multipliers,
        s.longestPathCells, CordicBound.headline(p).total, measured)
    } finally pb.close()
    Pareto.mark(rows)
  }

  /** Writes sweep.csv, sweep.json and one PNG per function; returns the files. */
  def write(rows: Seq[SweepRow], out: os.Path): Seq[os.Path] = {
    os.makeDir.all(out)
    val csv = out / "sweep.csv"
    moire.files.SafeWrite.text(csv, (SweepRow.csvHeader +: rows.map(SweepRow.csv)).mkString("", "\n", "\n"))
    val json = out / "sweep.json"
    moire.files.SafeWrite.text(json, ujson.write(ujson.Arr(rows.map(_.json): _*), indent = 2))
    val pngs = rows.map(_.function).distinct.map { f =>
      val png = out / s"pareto-$f.png"
      ParetoPlot.write(png, f, rows.filter(_.function == f))
      png
    }
    Seq(csv, json) ++ pngs
  }

  /** Accuracy levels for the "cheapest per accuracy" table: decades plus the paper's 3.13e-5 for sines. */
  def levels(function: String): Seq[Double] =
    ((1 to 7).flatMap(k => Seq(3 * math.pow(10, -k - 1), math.pow(10, -k))) ++
      (if (function == "sin") Seq(PaperAnchor.accuracy) else Nil)).sorted.reverse

  def table(rows: Seq[SweepRow]): String = {
    val b = new StringBuilder
    for (f <- rows.map(_.function).distinct) {
      val unit = if (f == "sin") "full scale 1.0" else "rad"
      b ++= s"$f ($unit): cheapest configuration for each accuracy\n"
      b ++= f"  ${"max error"}%10s  ${"variant"}%-16s ${"n"}%3s ${"b"}%3s ${"logic cells"}%11s ${"path"}%5s ${"clocks"}%6s ${"bound"}%10s ${"measured"}%10s\n"
      val worst = rows.filter(_.function == f).map(_.errorBound).max
      for (t <- levels(f) if t < 3 * worst) Pareto.cheapest(rows, f, t) match {
        case Some(r) => b ++= f"  $t%10.2e  ${r.variant}%-16s ${r.p.iterations}%3d ${r.p.width}%3d ${r.logicCells}%11d ${r.longestPathCells.map(_.toString).getOrElse("-")}%5s ${r.p.latency}%6d ${r.errorBound}%10.3e ${r.measuredError.map(e => f"$e%10.3e").getOrElse("-")}%10s\n"
        case None =>
      }
      b ++= s"  Pareto front: ${rows.filter(r => r.function == f && r.pareto).sortBy(_.logicCells).map(r => s"${r.variant} n=${r.p.iterations} b=${r.p.width} (${r.logicCells})").mkString(", ")}\n"
    }
    rows.find(r => PaperAnchor.applies(r.p) && r.variant == "sincos" && r.p.width == 20).orElse(
      rows.find(r => PaperAnchor.applies(r.p) && r.variant == "sincos")).foreach { r =>
      b ++= f"paper (seed 001 Table 1, Quartus): ${PaperAnchor.logicElements} LEs, ${PaperAnchor.clocks} clocks, ${PaperAnchor.accuracy}%.2e" +
        f" | ours n=16 b=${r.p.width} (yosys): ${r.logicCells} logic cells, ${r.p.latency} clocks, bound ${r.errorBound}%.2e\n"
    }
    val best = Pareto.cheapest(rows, "sin", PaperAnchor.accuracy)
    best.foreach(r => b ++= f"cheapest sine in this sweep at the paper's accuracy ${PaperAnchor.accuracy}%.2e: ${r.variant} n=${r.p.iterations} b=${r.p.width}, ${r.logicCells} logic cells (goal <= ${PaperAnchor.goalCells})\n")
    b.toString
  }
}
