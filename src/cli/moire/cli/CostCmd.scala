package moire.cli

import moire.cost._
import moire.designs.Designs

/** `cost`: yosys logic cells, memory bits, multipliers and longest path of a design. */
object CostCmd {
  private def log(s: String): Unit = System.err.println(s"cost: $s")

  def run(config: CordicConfig, design: String, json: Option[String], timeout: Int, keep: Option[String]): Unit = {
    val p = config.params
    val d = Designs.find(design, p).fold(e => throw new UsageError(e), identity)
    if (timeout < 1) throw new UsageError(s"--timeout must be at least 1 second, got $timeout")
    // outputs before the work: a bad path fails now, not after yosys
    json.foreach(f => moire.files.SafeWrite.checkMade(moire.files.SafeWrite.fileArg(f)))
    keep.foreach(k => moire.files.SafeWrite.checkFolder(os.Path(k, os.pwd)))
    if (!Yosys.available) throw new UsageError("yosys not found on PATH (install yosys 0.23 or newer)")
    val work = keep.map(k => os.Path(k, os.pwd)).getOrElse(Cost.tempDir())
    val r = try Cost.measure(d, if (d.name == "cordic") Some(p) else None, work, timeout, log)
    catch { case e: YosysError => throw new UsageError(e.getMessage) }
    finally if (keep.isEmpty) os.remove.all(work)
    print(r.text)
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      moire.files.SafeWrite.madeText(path, ujson.write(r.json, indent = 2))
      println(s"wrote $path")
    }
  }

  /** A sweep's list, each value within the CORDIC's range for it (one out of range is said, not dropped). */
  private def ints(opt: String, s: String, lo: Int, hi: Int): Seq[Int] = {
    // an empty entry among others (8,,12: a value left out) is refused, as bounds refuses it, not dropped
    val cells = s.split(",", -1).toSeq.map(_.trim)
    val vs = if (cells.forall(_.isEmpty)) Nil else cells.map(v =>
      moire.numbers.Decimal.int(v).getOrElse(throw new UsageError(s"--$opt: '$v' is not an integer list like 8,12,16")))
    if (vs.isEmpty) throw new UsageError(s"--$opt: give at least one integer, like 8,12,16 (got '$s')")
    vs.find(v => v < lo || v > hi).foreach(v => throw new UsageError(s"--$opt: $v is not in $lo..$hi"))
    Lists.once(opt, vs)
  }

  def sweep(variants: String, iterations: String, widths: String, spread: Int, out: String, timeout: Int,
            measure: Boolean, json: Option[String]): Unit = {
    val vs = Variant.parse(variants).fold(e => throw new UsageError(e), identity)
    if (vs.isEmpty) throw new UsageError("--variants: give at least one variant")
    if (spread < 0) throw new UsageError(s"--spread must be 0 or more, got $spread")
    if (timeout < 1) throw new UsageError(s"--timeout must be at least 1 second, got $timeout")
    val grid = SweepGrid(vs, ints("sweep-iterations", iterations, 4, 40), ints("sweep-widths", widths, 8, 48), spread)
    val pts = try grid.points catch {
      case e: IllegalArgumentException => throw new UsageError("--sweep: " + e.getMessage.stripPrefix("requirement failed: "))
    }
    // (each variant's own extra configurations come on top of the grid: an empty grid ran them alone, without a word)
    if (pts.isEmpty || !grid.widths.exists(b => grid.iterations.exists(n => n <= b && n >= b - spread)))
      throw new UsageError(s"--sweep: no (n, b) with b - $spread <= n <= b in these lists")
    moire.files.SafeWrite.checkFolder(os.Path(out, os.pwd))
    json.foreach(f => moire.files.SafeWrite.checkMade(moire.files.SafeWrite.fileArg(f)))
    if (!Yosys.available) throw new UsageError("yosys not found on PATH (install yosys 0.23 or newer)")
    val dir = os.Path(out, os.pwd)
    log(s"${pts.size} configurations; results cached in ${dir / "cache"}")
    val rows = try SweepRun.run(grid, dir, timeout, measure, log)
    catch { case e: YosysError => throw new UsageError(e.getMessage) }
    print(SweepRun.table(rows))
    for (f <- SweepRun.write(rows, dir)) println(s"wrote $f")
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      moire.files.SafeWrite.madeText(path, ujson.write(ujson.Arr(rows.map(_.json): _*), indent = 2))
      println(s"wrote $path")
    }
  }
}
