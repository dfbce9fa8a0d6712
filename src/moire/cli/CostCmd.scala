package moire.cli

import moire.cost._

/** `cost`: yosys logic cells, memory bits, multipliers and longest path of a design. */
object CostCmd {
  private def log(s: String): Unit = System.err.println(s"cost: $s")

  def run(config: CordicConfig, design: String, json: Option[String], timeout: Int, keep: Option[String]): Unit = {
    val d = CostDesigns.find(design).fold(e => throw new UsageError(e), identity)
    val p = config.params
    if (timeout < 1) throw new UsageError(s"--timeout must be at least 1 second, got $timeout")
    if (!Yosys.available) throw new UsageError("yosys not found on PATH (install yosys 0.23 or newer)")
    val work = keep.map(k => os.Path(k, os.pwd)).getOrElse(Cost.tempDir())
    val r = try Cost.measure(d, p, work, timeout, perModule = true, log)
    catch { case e: YosysError => throw new UsageError(e.getMessage) }
    finally if (keep.isEmpty) os.remove.all(work)
    print(r.text)
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      os.write.over(path, ujson.write(r.json, indent = 2), createFolders = true)
      println(s"wrote $path")
    }
  }
}
