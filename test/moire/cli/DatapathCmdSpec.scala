package moire.cli

import moire.designs.Designs
import org.scalatest.flatspec.AnyFlatSpec

class DatapathCmdSpec extends AnyFlatSpec {
  "emit-datapath" should "write a registered design's SystemVerilog under its parameterised name, with its latency" in {
    val dir = os.temp.dir()
    for (name <- Seq("quadcomp", "adapt", "corrected", "turntable")) {
      val line = DatapathCmd.run(name, dir.toString)
      val d = Designs.find(name).toOption.get
      assert(line == s"wrote ${dir / s"${d.topName}.sv"} (${d.describe})", line)
      assert(line.matches(s"wrote .*\\.sv \\($name .*latency \\d+ clocks\\)"), line)
    }
    val names = os.list(dir).map(_.last)
    for (prefix <- Seq("QuadComp_", "AdaptiveCorrector_", "Corrected_", "Turntable_"))
      assert(names.exists(n => n.startsWith(prefix) && n.endsWith(".sv")), s"no $prefix*.sv in $names")
  }
  it should "name the allowed designs for an unknown one" in {
    val e = intercept[UsageError](DatapathCmd.run("nope", os.temp.dir().toString))
    assert(e.getMessage == s"--design: 'nope' is not a design; allowed: ${Designs.names.mkString(", ")}")
    assert(e.getMessage.contains("cordic, subdiv, quadcomp, adapt, corrected, harmonic"))
  }
  "designs" should "list every registered design once, with a description" in {
    val lines = DatapathCmd.list
    assert(lines.map(_.split(" +").head) == Designs.names, lines.mkString("\n"))
    assert(lines.forall(_.split("  +").length == 2), lines.mkString("\n"))
  }
}
