package moire.cli

import circt.stage.ChiselStage
import moire.cordic.{Cordic, CordicParams}

/** Writes SystemVerilog through firtool (fetched by Chisel's own resolver). */
object Emit {
  val firtoolOpts: Array[String] = Array("-disable-all-randomization", "-strip-debug-info")

  def cordic(p: CordicParams, out: String): os.Path = {
    val dir = os.Path(out, os.pwd)
    os.makeDir.all(dir)
    ChiselStage.emitSystemVerilogFile(new Cordic(p), Array("--target-dir", dir.toString), firtoolOpts)
    dir / s"${p.moduleName}.sv"
  }

  private val fileMarker = """(?m)^// ----- 8< ----- FILE "(.*)" ----- 8< -----$""".r

  /** Splits firtool's single-string output into `dir`: the design into `topFile`, and each black-box
    * resource firtool appends after a `// ----- 8< ----- FILE` line into its own file. Returns the
    * Verilog files, the design first; non-Verilog pieces (file lists) are left out.
    */
  def writeSplit(sv: String, topFile: String, dir: os.Path): Seq[os.Path] = {
    os.makeDir.all(dir)
    val cuts = fileMarker.findAllMatchIn(sv).toSeq
    val parts = (topFile, 0) +: cuts.map(m => (os.RelPath(m.group(1)).last, m.end))
    val ends = cuts.map(_.start) :+ sv.length
    parts.zip(ends).collect { case ((name, from), to) if name.endsWith(".sv") || name.endsWith(".v") =>
      val f = dir / name
      os.write.over(f, sv.substring(from, to).dropWhile(_ == '\n'))
      f
    }
  }
}
