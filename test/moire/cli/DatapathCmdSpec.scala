package moire.cli

import org.scalatest.flatspec.AnyFlatSpec

class DatapathCmdSpec extends AnyFlatSpec {
  "emit-datapath" should "write every datapath's SystemVerilog under its parameterised name" in {
    val dir = os.temp.dir()
    for (d <- DatapathCmd.designs) DatapathCmd.run(d.name, dir.toString)
    val names = os.list(dir).map(_.last)
    for (prefix <- Seq("QuadComp_", "AdaptiveCorrector_", "Corrected_"))
      assert(names.exists(n => n.startsWith(prefix) && n.endsWith(".sv")), s"no $prefix*.sv in $names")
  }
  it should "name the allowed designs for an unknown one" in {
    val e = intercept[UsageError](DatapathCmd.run("nope", os.temp.dir().toString))
    assert(e.getMessage == "--design: 'nope' is not a datapath; allowed: quadcomp, adapt, corrected")
  }
}
