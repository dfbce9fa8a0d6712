package moire.cordic

import moire.emit.{Emit, Target}
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The emitted SystemVerilog passes Verilator's lint for a spread of configurations. */
class EmitLintSpec extends AnyFlatSpec {
  "Emitted SystemVerilog" should "pass verilator --lint-only" in {
    SimSupport.requireTool(this, "verilator")
    val configs = Seq(CordicParams(), CordicParams(CordicMode.Atan2, 20, 24, pipelineEvery = 4),
      CordicParams(CordicMode.AcosDouble, 16, 18, peakTableSize = 64, rounding = Rounding.Truncate),
      TaperFigures.lean)
    for (p <- configs) {
      val dir = os.temp.dir()
      val sv = Emit.write(new Cordic(p), os.Path(dir.toString, os.pwd), Target.SystemVerilog)._2.head
      val log = new StringBuilder
      val code = Seq("verilator", "--lint-only", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSED", sv.toString)
        .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
      assert(code == 0, s"${p.moduleName}:\n$log")
    }
  }
}
