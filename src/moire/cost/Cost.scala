package moire.cost

import moire.cordic.CordicParams

/** Elaborates a design, synthesizes it with yosys and builds its [[CostReport]]. */
object Cost {
  /** Flattened totals and path; for designs with submodules a second, hierarchical run gives the per-module table. */
  def measure(d: CostDesign, p: CordicParams, work: os.Path, timeoutSeconds: Int, perModule: Boolean,
              progress: String => Unit): CostReport = {
    progress(s"elaborating ${d.name}")
    val (top, files) = Synth.emit(() => d.gen(p), work / "rtl")
    val modules = files.map(f => """(?m)^module\s""".r.findAllIn(os.read(f)).size).sum
    progress(s"yosys on $top (flattened)")
    val flat = Yosys.run(top, files, work / "flat", flatten = true, timeoutSeconds, progress)
    val synth = if (perModule && modules > 1) {
      progress(s"yosys on $top (per module)")
      val hier = Yosys.run(top, files, work / "hier", flatten = false, timeoutSeconds, progress)
      flat.copy(modules = hier.modules, seconds = flat.seconds + hier.seconds)
    } else flat
    CostReport(d.name, d.what, synth, d.latency(p), if (d.name == "cordic") Some(p) else None)
  }

  def tempDir(): os.Path = os.temp.dir(prefix = "moire-cost-", deleteOnExit = false)
}
