package moire.cost

import moire.cli.CliProcess
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers
import scala.sys.process._

class CostCliSpec extends AnyFlatSpec with Matchers {
  private def oneLine(args: String*)(expect: String): Unit = {
    val (code, _, err) = CliProcess.run(args: _*)
    code shouldBe 2
    err.trim.linesIterator.toSeq shouldBe Seq(err.trim)
    err should startWith("moire: ")
    err should include(expect)
  }

  "cost" should "reject bad options with one line and exit code 2" in {
    oneLine("cost", "--design", "nope")("--design: 'nope' is not a design")
    oneLine("cost", "--width", "5")("--width must be in 8..48")
    oneLine("cost", "--sweep", "--variants", "sincos,bogus")("--variants: 'bogus'")
    oneLine("cost", "--sweep", "--sweep-widths", "12,x")("--sweep-widths: 'x'")
    oneLine("cost", "--timeout", "0")("--timeout")
  }

  it should "say in one line when yosys is missing" in {
    val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath
    val err = new StringBuilder
    val code = Process(Seq(javaBin, "-Xmx1g", "-cp", System.getProperty("java.class.path"), "moire.cli.Main",
      "cost", "--iterations", "6", "--width", "10"), None, "PATH" -> "/nonexistent")
      .!(ProcessLogger(_ => (), l => err.append(l).append('\n')))
    code shouldBe 2
    err.toString.trim shouldBe "moire: yosys not found on PATH (install yosys 0.23 or newer)"
  }

  it should "print the table and write the JSON of a small CORDIC" in {
    assume(Yosys.available, "yosys not installed")
    val f = os.temp(prefix = "moire-cost-", suffix = ".json")
    val (code, out, err) = CliProcess.run("cost", "--iterations", "6", "--width", "10", "--json", f.toString)
    withClue(err) { code shouldBe 0 }
    out should include("logic cells")
    out should include("of the EP4CE115's 114480 LEs")
    val j = ujson.read(os.read(f))
    for (k <- Seq("logic_cells", "registers", "memory_bits", "longest_path_cells")) j(k) shouldBe a[ujson.Num]
    j("logic_cells").num should be > j("registers").num
    os.remove(f)
  }
}
