package moire.cordic

import chiseltest._
import firrtl2.AnnotationSeq
import org.scalatest.Assertions

/** Simulator choice: Verilator when installed, else treadle. */
object SimSupport {
  def onPath(tool: String): Boolean =
    sys.env.getOrElse("PATH", "").split(java.io.File.pathSeparator).exists(d => new java.io.File(d, tool).canExecute)
  /** MOIRE_SIM=treadle forces the fallback, to check what a machine without Verilator runs. */
  lazy val hasVerilator: Boolean = onPath("verilator") && !sys.env.get("MOIRE_SIM").contains("treadle")
  lazy val hasYosys: Boolean = onPath("yosys")
  def backend: AnnotationSeq = if (hasVerilator) Seq(VerilatorBackendAnnotation) else Seq()
  def backendName: String = if (hasVerilator) "verilator" else "treadle"
  def requireTool(a: Assertions, tool: String): Unit =
    if (!onPath(tool)) a.cancel(s"$tool is not installed (apt-get install $tool); .ci/run installs it")
}
