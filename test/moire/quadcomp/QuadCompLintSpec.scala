package moire.quadcomp

import circt.stage.ChiselStage
import moire.emit.{Emit, Target}
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The emitted SystemVerilog carries the parameters in its name and passes Verilator's lint. */
class QuadCompLintSpec extends AnyFlatSpec {
  "Emitted SystemVerilog" should "pass verilator --lint-only" in {
    SimSupport.requireTool(this, "verilator")
    for (p <- Seq(QuadCompParams(), QuadCompParams(iterations = 12, width = 16, averageLog2 = 0, fusePeaks = true))) {
      val dir = os.temp.dir()
      ChiselStage.emitSystemVerilogFile(new QuadComp(p), Array("--target-dir", dir.toString), Target.SystemVerilog.opts)
      val sv = dir / s"${p.moduleName}.sv"
      assert(os.exists(sv), s"no ${sv.last} in ${os.list(dir).map(_.last)}")
      val log = new StringBuilder
      val code = Seq("verilator", "--lint-only", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSED",
        "--top-module", p.moduleName, sv.toString)
        .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
      assert(code == 0, s"${p.moduleName}:\n$log")
    }
  }
}
