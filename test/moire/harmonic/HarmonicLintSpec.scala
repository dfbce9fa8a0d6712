package moire.harmonic

import circt.stage.ChiselStage
import moire.io.{QuadratureCounter, QuadratureParams}
import moire.emit.{Emit, Target}
import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The emitted SystemVerilog of the compensator and the counter passes Verilator's lint. */
class HarmonicLintSpec extends AnyFlatSpec {
  "Emitted SystemVerilog" should "pass verilator --lint-only" in {
    SimSupport.requireTool(this, "verilator")
    val designs: Seq[(String, () => chisel3.RawModule)] = Seq(
      HarmonicParams().moduleName -> (() => new HarmonicCompensator(HarmonicParams())),
      HarmonicParams(harmonics = 2, pipelineEvery = 4, outFrac = 0).moduleName ->
        (() => new HarmonicCompensator(HarmonicParams(harmonics = 2, pipelineEvery = 4, outFrac = 0))),
      QuadratureParams().moduleName -> (() => new QuadratureCounter(QuadratureParams())))
    for ((name, gen) <- designs) {
      val dir = os.temp.dir()
      ChiselStage.emitSystemVerilogFile(gen(), Array("--target-dir", dir.toString, "--split-verilog"), Target.SystemVerilog.opts)
      val files = os.walk(dir).filter(_.ext == "sv").map(_.toString)
      val log = new StringBuilder
      val code = (Seq("verilator", "--lint-only", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSED", "--top-module", name) ++ files)
        .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
      assert(code == 0, s"$name:\n$log")
    }
  }
}
