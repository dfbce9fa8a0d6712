package moire.cost

import moire.cordic.CordicParams
import moire.designs.Design
import moire.emit.Target

/** Elaborates a design, synthesizes it with yosys and builds its [[CostReport]]. */
object Cost {
  /** One yosys run: flattened for a single module, hierarchical (per-module table) otherwise.
    * `cordic` is the CORDIC's configuration when the design is one (its error bound goes into the report).
    */
  def measure(d: Design, cordic: Option[CordicParams], work: os.Path, timeoutSeconds: Int, progress: String => Unit): CostReport = {
    progress(s"elaborating ${d.name}")
    val files = d.write(work / "rtl", Target.Verilog)
    val modules = files.map(f => """(?m)^module\s""".r.findAllIn(os.read(f)).size).sum
    progress(s"yosys on ${d.topName} (${if (modules > 1) s"$modules modules" else "one module"})")
    val synth = Yosys.run(d.topName, files, work / "synth", flatten = modules <= 1, timeoutSeconds, progress)
    CostReport(d.name, d.what, synth, d.latency, cordic)
  }

  def tempDir(): os.Path = os.temp.dir(prefix = "moire-cost-", deleteOnExit = false)
}
