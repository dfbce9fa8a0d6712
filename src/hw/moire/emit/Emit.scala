package moire.emit

import chisel3.RawModule
import circt.stage.ChiselStage

/** What the Verilog is for: Verilator and Quartus read SystemVerilog; yosys wants plain Verilog. */
sealed abstract class Target(val name: String, val opts: Array[String])
object Target {
  private val base = Array("-disable-all-randomization", "-strip-debug-info")
  /** SystemVerilog for Verilator and Quartus. Locals are still disallowed: yosys reads these files too. */
  case object SystemVerilog extends Target("sv", base :+ "--lowering-options=disallowLocalVariables")
  /** Plain Verilog-2001 style (no automatic locals, no packed arrays), for yosys and older Quartus releases. */
  case object Verilog extends Target("v", base :+ "--lowering-options=disallowLocalVariables,disallowPackedArrays")
}

/** The one way a design becomes Verilog: elaborate, lower through firtool, split black-box files. */
object Emit {
  /** The elaborated top and its Verilog text (design first, black-box resources appended by firtool). */
  def elaborate[M <: RawModule](gen: => M, target: Target = Target.Verilog): (M, String) = {
    var top: Option[M] = None
    val text = ChiselStage.emitSystemVerilog({ val m = gen; top = Some(m); m }, Array.empty[String], target.opts)
    (top.get, text)
  }

  /** Elaborates `gen` and writes its files into `dir`; returns the top and the Verilog files, the design first. */
  def write[M <: RawModule](gen: => M, dir: os.Path, target: Target = Target.Verilog): (M, Seq[os.Path]) = {
    val (top, text) = elaborate(gen, target)
    (top, writeSplit(text, s"${top.desiredName}.sv", dir))
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
