package moire.emit

import chisel3.RawModule
import circt.stage.ChiselStage

/** What the Verilog is for: Verilator and Quartus read SystemVerilog; yosys wants plain Verilog. */
sealed abstract class Target(val name: String, val opts: Array[String])
object Target {
  /** No automatic locals, no packed arrays: Debian's yosys 0.23 rejects both (DesignLintSpec reads every design). */
  private val base = Array("-disable-all-randomization", "-strip-debug-info",
    "--lowering-options=disallowLocalVariables,disallowPackedArrays")
  /** SystemVerilog for Verilator and Quartus (`emit`, `board de2-115`, replay). */
  case object SystemVerilog extends Target("sv", base)
  /** Plain Verilog-2001 style for yosys (`cost`, `timing`, `board ulx3s`). Today the same lowering as
    * [[SystemVerilog]], since the SystemVerilog must read in yosys 0.23 too; kept apart so a caller says
    * which tool reads its files.
    */
  case object Verilog extends Target("v", base)
}

/** The one way a design becomes Verilog: elaborate, lower through firtool (one text, or one file per module). */
object Emit {
  /** The elaborated top and its Verilog text (design first, black-box resources appended by firtool). */
  def elaborate[M <: RawModule](gen: => M, target: Target = Target.Verilog): (M, String) = {
    var top: Option[M] = None
    val text = firtool(ChiselStage.emitSystemVerilog({ val m = gen; top = Some(m); m }, Array.empty[String], target.opts))
    (top.get, text)
  }

  /** `body`, again after a pause where firtool could not be resolved: on a new machine's first use another process (the
    * suite's other JVM, a launcher) may be unpacking it into the same cache (`Error resolving firtool` in a CI run).
    */
  private def firtool[T](body: => T): T = {
    var tries = 0
    while (true) {
      try return body
      catch { case x: Exception if tries < 3 && Option(x.getMessage).exists(_.contains("resolving firtool")) => tries += 1; Thread.sleep(3000L * tries) }
    }
    throw new IllegalStateException("unreachable")
  }

  /** Elaborates `gen` without lowering it (fast): the top, to read its name and latency. */
  def module[M <: RawModule](gen: => M): M = {
    var top: Option[M] = None
    chisel3.stage.ChiselGeneratorAnnotation(() => { val m = gen; top = Some(m); m }).elaborate
    top.get
  }

  /** Elaborates `gen` and writes one file per module (`Name.sv`, the file named after its module as
    * Verilator's DECLFILENAME asks) and the black-box files into `dir`; returns the top and the
    * Verilog files, the top's first.
    */
  def write[M <: RawModule](gen: => M, dir: os.Path, target: Target = Target.Verilog): (M, Seq[os.Path]) = {
    moire.files.SafeWrite.checkFolder(dir)   // before the elaboration, not after it
    var top: Option[M] = None
    val tmp = os.temp.dir(prefix = "moire-emit-")
    try {
      firtool(ChiselStage.emitSystemVerilogFile({ val m = gen; top = Some(m); m },
        Array("--target-dir", tmp.toString, "--split-verilog"), target.opts))
      val first = s"${top.get.desiredName}.sv"
      // Verilog files that hold a module (not firtool's extern_modules.sv, macro definitions only)
      val files = os.walk(tmp).filter(f => os.isFile(f) && Seq("sv", "v").contains(f.ext) && """(?m)^\s*module\s""".r.findFirstIn(os.read(f)).nonEmpty)
      // a namesake a user wrote or edited is refused, not replaced (all or none are written)
      val sorted = files.sortBy(f => (f.last != first, f.last))
      moire.files.SafeWrite.made(sorted.map(f => (dir / f.last) -> ((t: os.Path) => os.copy(f, t))))
      (top.get, sorted.map(f => dir / f.last))
    } finally os.remove.all(tmp)
  }
}
