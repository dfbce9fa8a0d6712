package moire.subdiv

import moire.options.SubdivCmd
import moire.signal.AdcFormat
import org.scalatest.flatspec.AnyFlatSpec

/** emit-subdiv writes the design and explains bad options in one line (lint: moire.designs.DesignLintSpec). */
class SubdivEmitSpec extends AnyFlatSpec {
  "emit-subdiv" should "write the design and report the latency and top name of the elaborated module" in {
    for ((p, f) <- Seq(SubdivParams() -> AdcFormat.OffsetBinary,
      SubdivParams(14, PhaseMethod.AsinDouble, counts = 65536, minEdgeClocks = 5) -> AdcFormat.TwosComplement)) {
      val (sv, latency, name) = SubdivCmd.emit(p, f, os.temp.dir().toString)
      assert(latency == SubdivAdc.latency(p) && latency == p.latency + AdcFrontEnd.latency, s"$name: latency $latency")
      assert(name == s"${p.moduleName}_${AdcFrontEnd.tag(f)}" && sv.last == s"$name.sv" && os.read(sv).contains(s"module $name("), name)
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
