package moire.subdiv

import moire.options.SubdivCmd
import moire.cordic.SimSupport
import moire.signal.AdcFormat
import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The emitted SystemVerilog lints clean, and the emit-subdiv command explains bad options in one line. */
class SubdivEmitSpec extends AnyFlatSpec {
  "Emitted subdivider SystemVerilog" should "pass verilator --lint-only" in {
    SimSupport.requireTool(this, "verilator")
    for ((p, f) <- Seq(SubdivParams() -> AdcFormat.OffsetBinary,
      SubdivParams(14, PhaseMethod.AsinDouble, counts = 65536, minEdgeClocks = 5) -> AdcFormat.TwosComplement)) {
      val dir = os.temp.dir()
      val (sv, latency, name) = SubdivCmd.emit(p, f, dir.toString)
      assert(latency == p.latency + 1 && name.startsWith(p.moduleName) && os.exists(sv))
      val log = new StringBuilder
      val code = Seq("verilator", "--lint-only", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSED", sv.toString)
        .!(ProcessLogger(l => log.append(l).append('\n'), l => log.append(l).append('\n')))
      assert(code == 0, s"$name:\n$log")
    }
  }

  "emit-subdiv" should "reject bad options with one line and exit code 2" in {
    for ((args, expected) <- Seq(
      Seq("--counts", "1000") -> "--counts (M) must be a power of two in 4..65536, got 1000",
      Seq("--method", "tan") -> "--method: 'tan' is not a phase method",
      Seq("--adc-format", "gray") -> "--adc-format: ADC format 'gray' is unknown",
      Seq("--min-edge-clocks", "0") -> "--min-edge-clocks must be in 1..4096")) {
      val (code, _, err) = moire.cli.CliProcess.run("emit-subdiv" +: args: _*)
      val lines = err.toString.linesIterator.filter(_.nonEmpty).toSeq
      assert(code == 2 && lines.size == 1 && lines.head.startsWith(s"moire: $expected"), s"$args: exit $code, $err")
    }
  }
}
