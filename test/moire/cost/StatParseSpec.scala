package moire.cost

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Parsing of recorded yosys 0.23 output (test/resources/moire/cost/sample.v: a memory, a multiply, adders). */
class StatParseSpec extends AnyFlatSpec with Matchers {
  private def res(name: String): String = os.read(os.resource / "moire" / "cost" / name)

  "StatParse.cells" should "count *_lcell_comb plus dffeas as logic cells, and find the RAM and the multiplier" in {
    val (total, modules) = StatParse.cells(res("sample-stat.json"), "top")
    total.luts shouldBe 44
    total.registers shouldBe 25
    total.logicCells shouldBe 69
    total.m9k shouldBe 1
    total.multCells shouldBe 1
    modules.map(_.name) shouldBe Seq("top")
  }

  "StatParse.memoryBits" should "read the inferred memory bits, also with text after the JSON" in {
    StatParse.memoryBits(res("sample-pre.json")) shouldBe 256 * 8
    StatParse.memoryBits(res("sample-pre.json") + "\nWarning: Feature 'synth_intel' is experimental.\n") shouldBe 256 * 8
  }

  it should "read a hierarchical stat, whose JSON yosys 0.23 interleaves with a hierarchy tree" in {
    val text = res("sample-hier-pre.json")
    text should include("       Cordic_atan2_n16_w18f16_a18_g2z5_k1_rne_nogc      1")
    val (design, modules) = StatParse.cells(text, "Subdiv_atan2_in12_M1024_n16_w18g2_p18_pos32_e1_ob")
    modules.size shouldBe 4
    design.cells("$mul") shouldBe 2
    design.cells("$dff") shouldBe 135
  }

  it should "reject text that is not stat JSON with a YosysError" in {
    a[YosysError] should be thrownBy StatParse.cells("ERROR: no design", "top")
  }

  "StatParse.multBlocks" should "count ceil(a / 18) * ceil(b / 18) blocks per $mul" in {
    StatParse.multBlocks(res("sample-mul.txt")) shouldBe 1
    val two = "  cell $mul $m1\n    parameter \\A_WIDTH 20\n    parameter \\B_WIDTH 18\n  end\n" +
      "  cell $mul $m2\n    parameter \\A_WIDTH 37\n    parameter \\B_WIDTH 19\n  end\n"
    StatParse.multBlocks(two) shouldBe 2 + 3 * 2
    // After chtype the cells are black boxes: a hierarchical run dumps them from the flattened netlist.
    StatParse.multBlocks(two.replace("cell $mul", "cell \\moire_mult18")) shouldBe 2 + 3 * 2
    StatParse.multBlocks("") shouldBe 0
  }

  it should "count a signed product by its operands' own widths, not firtool's sign extension" in {
    // firtool writes a 12 x 12 signed square as a 24 x 24 unsigned product of sign-extended operands.
    val ext = (Seq.fill(12)("\\x [11]") :+ "\\x").mkString("{ ", " ", " }")
    val sq = s"  cell $$mul $$m\n    parameter \\A_WIDTH 24\n    parameter \\B_WIDTH 24\n    connect \\A $ext\n    connect \\B $ext\n  end\n"
    StatParse.multipliers(sq) shouldBe Seq((12, 12))
    StatParse.multBlocks(sq) shouldBe 1
    // 18 x 24 signed, widened to 42 x 42: two blocks, not nine.
    val a = (Seq.fill(24)("\\a [17]") :+ "\\a").mkString("{ ", " ", " }")
    val b = (Seq.fill(18)("\\b [23]") :+ "\\b").mkString("{ ", " ", " }")
    StatParse.multBlocks(s"  cell $$mul $$m\n    parameter \\A_WIDTH 42\n    parameter \\B_WIDTH 42\n    connect \\A $a\n    connect \\B $b\n  end\n") shouldBe 2
  }

  it should "keep the sign extension of an operand multiplied by a constant, as synth_ecp5 maps it" in {
    val a = (Seq.fill(18)("\\d [24]") :+ "\\d").mkString("{ ", " ", " }")
    StatParse.multipliers(s"  cell $$mul $$m\n    parameter \\A_WIDTH 43\n    parameter \\B_WIDTH 12\n    connect \\A $a\n    connect \\B 12'110010010001\n  end\n") shouldBe Seq((43, 12))
  }

  "Operand.realWidth" should "drop zero extension and repeated sign bits only" in {
    Operand.realWidth(20, "{ 4'0000 \\y }") shouldBe 16
    Operand.realWidth(20, "{ 4'0010 \\y }") shouldBe 18
    Operand.realWidth(16, "\\y") shouldBe 16
    // Copies of the top bit of a part: the first copy is the sign bit itself.
    Operand.realWidth(11, "{ \\y [7] \\y [7] \\y [7] \\z [7:0] }") shouldBe 9
    Operand.realWidth(10, "{ \\y [7] \\y [7] \\y [7:0] }") shouldBe 8
    Operand.realWidth(8, "{ \\y [7] \\y [6] \\y [5:0] }") shouldBe 8
  }

  "StatParse.longestPath" should "read the length of ltp" in {
    StatParse.longestPath(res("sample-ltp.txt")) shouldBe Some(8)
    StatParse.longestPath("Longest topological path in top (length=-1):") shouldBe None
    StatParse.longestPath("nothing") shouldBe None
  }

  "m9kBlocks" should "pick the best M9K aspect ratio" in {
    StatParse.m9kBlocks(256, 96) shouldBe 3   // 256 x 36 three times
    StatParse.m9kBlocks(8192, 1) shouldBe 1
    StatParse.m9kBlocks(1024, 10) shouldBe 2  // 1024 x 9 twice
    StatParse.m9kBlocks(4, 40) shouldBe 2
  }
}
