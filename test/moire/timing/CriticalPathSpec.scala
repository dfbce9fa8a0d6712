package moire.timing

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** nextpnr's report read without the tools: names, levels, carry cells, Verilog lines. */
class CriticalPathSpec extends AnyFlatSpec with Matchers {
  private def seg(t: String, from: String, fp: String, to: String, tp: String, d: Double, net: Option[String] = None, src: Seq[String] = Nil) =
    ujson.Obj.from(Seq("type" -> ujson.Str(t), "delay" -> ujson.Num(d), "from" -> ujson.Obj("cell" -> from, "port" -> fp),
      "to" -> ujson.Obj("cell" -> to, "port" -> tp)) ++ net.map(n => "net" -> ujson.Str(n)) ++
      (if (src.isEmpty) Nil else Seq("sources" -> ujson.Arr(src.map(ujson.Str): _*))))

  private val ff = "sd.outPos_TRELLIS_FF_Q"
  private val c0 = "sd.waitCnt_LUT4_C_Z_CCU2C_COUT$CCU2_COMB0"
  private val c1 = "sd.waitCnt_LUT4_C_Z_CCU2C_COUT$CCU2_COMB1"
  private val lut = "$abc$123$auto_LUT4_Z"
  private val end = "sd.count_TRELLIS_FF_Q"
  private val report = ujson.Obj(
    "fmax" -> ujson.Obj("clock" -> ujson.Obj("achieved" -> 70.5, "constraint" -> 65)),
    "utilization" -> ujson.Obj("TRELLIS_COMB" -> ujson.Obj("used" -> 40, "available" -> 83640), "MULT18X18D" -> ujson.Obj("used" -> 2, "available" -> 156)),
    "critical_paths" -> ujson.Arr(ujson.Obj("from" -> "posedge clock", "to" -> "posedge clock", "path" -> ujson.Arr(
      seg("clk-to-q", ff, "CLK", ff, "Q", 0.5),
      seg("routing", ff, "Q", c0, "B", 1.0, Some("sd.outPos[3]"), Seq("T.sv:2.1-2.9")),
      seg("logic", c0, "B", c0, "FCO", 0.4),
      seg("routing", c0, "FCO", c1, "FCI", 0.0, Some("sd.waitCnt_LUT4_C_Z_CCU2C_COUT$CCU2_FCI_INT")),
      seg("logic", c1, "FCI", c1, "FCO", 0.1),
      seg("routing", c1, "FCO", lut, "A", 0.8, Some("$abc$99$n12"), Seq("/share/lattice/arith_map_ccu2c.v:74.7-80.4")),
      seg("logic", lut, "A", lut, "Z", 0.3),
      seg("routing", lut, "Z", end, "DI", 0.7, Some("sd.count_next[1]"), Seq("T.sv:3.5-3.20")),
      seg("setup", end, "DI", end, "DI", 0.2)))))

  "Nextpnr.report" should "name the critical path in the design's own terms" in {
    val rtl = Map("T.sv" -> IndexedSeq("module T;", "  reg [7:0] outPos;", "  wire [7:0] count_next = outPos + 1;"))
    val (fmax, used, paths) = Nextpnr.report(ujson.write(report), rtl.get)
    fmax shouldBe Map("clock" -> 70.5)
    used("MULT18X18D") shouldBe 2
    val p = paths.head
    p.clock shouldBe "clock"
    p.from shouldBe "sd.outPos"
    p.to shouldBe "sd.count"
    p.logicLevels shouldBe 2 // the carry chain's entry and the LUT
    p.carryCells shouldBe 1
    p.signals shouldBe Seq("sd.outPos", "sd.waitCnt", "sd.count_next", "sd.count")
    p.verilog shouldBe Seq("T.sv:2: reg [7:0] outPos;", "T.sv:3: wire [7:0] count_next = outPos + 1;")
    p.delayNs shouldBe 4.0 +- 1e-9
  }

  "CriticalPath.designName" should "strip the names yosys and nextpnr append" in {
    CriticalPath.designName("sd.x_reg_TRELLIS_FF_Q") shouldBe "sd.x_reg"
    CriticalPath.designName("\\core.acc_MULT18X18D_P") shouldBe "core.acc"
    CriticalPath.designName("sd.outPos[12]") shouldBe "sd.outPos"
    CriticalPath.designName("$abc$1$n2") shouldBe ""
  }

  "a missed target" should "show as negative slack" in {
    val r = SpeedResult(6, 65, Map("clock" -> 50.0), None, 0, 0, 0, 0, Ecp5Cells(Map.empty), 0, cached = false, router = "router2")
    r.meets shouldBe false
    r.slackNs shouldBe (1000 / 65.0 - 20.0) +- 1e-9
    r.json("slack_ns").num should be < 0.0
  }
}
