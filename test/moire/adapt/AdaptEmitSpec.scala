package moire.adapt

import moire.cordic.SimSupport
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The emitted SystemVerilog passes Verilator's lint and carries the parameters in its name. */
class AdaptEmitSpec extends AnyFlatSpec {
  "Emitted SystemVerilog" should "pass verilator --lint-only" in {
    SimSupport.requireTool(this, "verilator")
    for (p <- Seq(AdaptParams(), AdaptParams(inputBits = 14, outputBits = 18, mulFrac = 2, harmonicEntries = 0))) {
      val sv = AdaptEmit.emit(p, os.temp.dir().toString)
      assert(os.exists(sv), s"no ${sv.last}")
      val log = new StringBuilder
      val code = Seq("verilator", "--lint-only", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSED", sv.toString)
        .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
      assert(code == 0, s"${p.moduleName}:\n$log")
    }
  }
}
