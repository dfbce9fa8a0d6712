package moire.cli

import moire.designs.Designs
import moire.emit.Target

/** `emit-datapath` and `designs`: any design of the registry ([[moire.designs.Designs]]) at its defaults. */
object DatapathCmd {
  /** Writes the design's SystemVerilog into `out`; returns the line to print. */
  def run(design: String, out: String): String = {
    val d = Designs.find(design).fold(e => throw new UsageError(e), identity)
    val file = d.write(os.Path(out, os.pwd), Target.SystemVerilog).head
    s"wrote $file (${d.describe})"
  }

  /** One line per registered design: name and description (nothing is elaborated). */
  def list: Seq[String] = {
    val all = Designs.all()
    val w = all.map(_.name.length).max
    all.map(d => s"${d.name.padTo(w, ' ')}  ${d.what}")
  }
}
