package moire.cost

import moire.cordic.CordicParams

/** Elaborates a design, synthesizes it with yosys and builds its [[CostReport]]. */
object Cost {
  /** One yosys run: flattened for a single module, hierarchical (per-module table) otherwise. */
  def measure(d: CostDesign, p: CordicParams, work: os.Path, timeoutSeconds: Int, progress: String => Unit): CostReport = {
    progress(s"elaborating ${d.name}")
    val (top, files) = Synth.emit(() => d.gen(p), work / "rtl")
    val modules = files.map(f => """(?m)^module\s""".r.findAllIn(os.read(f)).size).sum
    progress(s"yosys on $top (${if (modules > 1) s"$modules modules" else "one module"})")
    val synth = Yosys.run(top, files, work / "synth", flatten = modules <= 1, timeoutSeconds, progress)
    CostReport(d.name, d.what, synth, d.latency(p), if (d.name == "cordic") Some(p) else None)
  }

  def tempDir(): os.Path = os.temp.dir(prefix = "moire-cost-", deleteOnExit = false)
}
