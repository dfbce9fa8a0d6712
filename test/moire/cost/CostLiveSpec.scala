package moire.cost

import moire.cordic.{CordicMode, CordicParams}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** yosys on small CORDICs (seconds each); cancelled where yosys is not installed. */
class CostLiveSpec extends AnyFlatSpec with Matchers {
  private def cordic(n: Int, b: Int, mode: CordicMode = CordicMode.SinCos) = CordicParams(mode, n, b)
  private def measure(p: CordicParams): CostReport = {
    assume(Yosys.available, "yosys not installed")
    val work = os.temp.dir(prefix = "moire-cost-test-")
    try Cost.measure(moire.designs.Designs.cordic(p), Some(p), work, 300, _ => ())
    finally os.remove.all(work)
  }

  private lazy val small = measure(cordic(6, 10))
  private lazy val wider = measure(cordic(6, 14))

  /** With a register after every iteration the longest path is one iteration's add/subtract: its carry
    * runs through the adder's cells (at least half the internal width: yosys trims constant low bits; 11
    * of 13, 13 of 17 and 9 of 11 measured), and never through two adders (at most the width plus 2).
    */
  private def onePipelineStage(cells: Option[Int], p: CordicParams) = withClue(s"longest path of ${p.moduleName}: ") {
    p.pipelineEvery shouldBe 1
    cells.get should (be >= p.innerWidth / 2 and be <= p.innerWidth + 2)
  }

  "cost" should "count LUT cells and registers of a CORDIC, with a longest path" in {
    small.logicCells shouldBe small.synth.total.luts + small.registers
    // Every pipeline stage holds at least x, y and z: 3 * 10 bits over 6 iterations, plus valid bits.
    small.registers should be >= (6L * 3 * 10)
    onePipelineStage(small.synth.longestPathCells, cordic(6, 10))
    small.synth.memoryBits shouldBe 0
    small.synth.multipliers shouldBe 0
  }

  it should "grow with the data width" in {
    wider.logicCells should be > small.logicCells
    wider.registers should be > small.registers
    wider.synth.longestPathCells.get should be > small.synth.longestPathCells.get // a longer carry chain
  }

  it should "write the JSON keys of the issue" in {
    val j = small.json
    for (k <- Seq("logic_cells", "registers", "memory_bits", "longest_path_cells", "error_bound", "latency", "results_per_clock"))
      j.obj.keySet should contain(k)
    j("logic_cells").num shouldBe small.logicCells.toDouble
    j("latency").num shouldBe cordic(6, 10).latency.toDouble
  }

  it should "stop a yosys run that exceeds its time limit with one line" in {
    assume(Yosys.available, "yosys not installed")
    val work = os.temp.dir(prefix = "moire-cost-test-")
    try {
      val (top, files) = Synth.emit(() => new moire.cordic.Cordic(cordic(12, 16)), work / "rtl")
      val e = the[YosysError] thrownBy Yosys.run(top, files, work / "flat", flatten = true, timeoutSeconds = 1)
      e.getMessage should include("did not finish")
      e.getMessage.linesIterator.size shouldBe 1
    } finally os.remove.all(work)
  }

  it should "list the modules of a hierarchical design and add their instances up" in {
    assume(Yosys.available, "yosys not installed")
    val work = os.temp.dir(prefix = "moire-cost-test-")
    val inner = cordic(4, 8)
    val pair = new moire.designs.Design("pair", "two CORDICs", () => new TwoCordics(inner))
    val r = try Cost.measure(pair, None, work, 300, _ => ()) finally os.remove.all(work)
    val cm = r.synth.modules.find(_.name == inner.moduleName).get
    r.synth.modules.map(_.name) should contain allOf ("TwoCordics", inner.moduleName)
    r.registers should be >= 2 * cm.registers
    r.logicCells should be >= 2 * cm.logicCells
    onePipelineStage(r.synth.longestPathCells, inner) // the two CORDICs side by side, not in series
    r.json("modules").arr.size shouldBe 2
    r.text should include(inner.moduleName)
  }

  "cost --sweep" should "write CSV, JSON and PNG with the Pareto front marked, and reuse its cache" in {
    assume(Yosys.available, "yosys not installed")
    val out = os.temp.dir(prefix = "moire-sweep-test-")
    try {
      val grid = SweepGrid(Variant.all.filter(v => v.name == "sincos" || v.name == "asin-double"), Seq(6, 8), Seq(10), 4)
      val rows = SweepRun.run(grid, out, 300, measure = true, _ => ())
      rows.size shouldBe 4
      val files = SweepRun.write(rows, out)
      files.map(_.last) shouldBe Seq("sweep.csv", "sweep.json", "pareto-sin.png", "pareto-asin.png")
      os.read.lines(out / "sweep.csv").size shouldBe 5
      os.read.bytes(out / "pareto-sin.png").take(4).toSeq shouldBe Seq(0x89.toByte, 'P'.toByte, 'N'.toByte, 'G'.toByte)
      val json = ujson.read(os.read(out / "sweep.json")).arr
      json.size shouldBe 4
      for (r <- json) Seq("logic_cells", "registers", "memory_bits", "longest_path_cells", "error_bound", "pareto")
        .foreach(k => r.obj.keySet should contain(k))
      for (r <- rows) {
        val dominated = rows.exists(o => o.function == r.function && o.logicCells <= r.logicCells && o.errorBound <= r.errorBound &&
          (o.logicCells < r.logicCells || o.errorBound < r.errorBound))
        r.pareto shouldBe !dominated
        r.measuredError.get should be <= r.errorBound
      }
      // More iterations at the same width cost more cells.
      val sin = rows.filter(_.variant == "sincos").sortBy(_.p.iterations)
      sin(1).logicCells should be > sin(0).logicCells
      SweepRun.synth(cordic(6, 10), out / "cache", 300, _ => ())._2 shouldBe true
    } finally os.remove.all(out)
  }

  it should "put a synchronous-read memory in M9K blocks and an asynchronous one in logic" in {
    assume(Yosys.available, "yosys not installed")
    def run(sync: Boolean) = {
      val work = os.temp.dir(prefix = "moire-cost-test-")
      try { val (top, files) = RamProbe.emit(sync, work / "rtl"); Yosys.run(top, files, work / "synth", flatten = true, 300) }
      finally os.remove.all(work)
    }
    val s = run(sync = true); val a = run(sync = false)
    s.blockRamBits shouldBe RamProbe.depth.toLong * 40
    s.m9kBlocks shouldBe 2
    a.blockRamBits shouldBe 0
    a.memoryBits shouldBe RamProbe.depth.toLong * 40
    a.total.logicCells should be > (10 * s.total.logicCells)
  }
}

/** Two CORDICs side by side: a design with a hierarchy. */
class TwoCordics(p: CordicParams) extends chisel3.Module {
  import chisel3._
  val io = IO(new Bundle { val z = Input(SInt(p.angleBits.W)); val y = Output(SInt(p.width.W)) })
  private val a = Module(new moire.cordic.Cordic(p))
  private val b = Module(new moire.cordic.Cordic(p))
  Seq(a, b).foreach { c => c.io.in.valid := true.B; c.io.in.bits.x := 0.S; c.io.in.bits.y := 0.S }
  a.io.in.bits.z := io.z
  b.io.in.bits.z := -io.z
  io.y := RegNext(a.io.out.bits.y ^ b.io.out.bits.x)

}

/** A `depth` x 40 memory with a synchronous or an asynchronous read port. */
object RamProbe {
  import chisel3._
  /** Words: 64 of 40 bits take two M9K blocks (36 bits wide at most) as 256 did, and the test takes 14 s instead of 50. */
  val depth = 64
  class Ram(sync: Boolean) extends Module {
    override def desiredName = if (sync) "RamProbeSync" else "RamProbeAsync"
    val io = IO(new Bundle {
      val wen = Input(Bool()); val waddr = Input(UInt(chisel3.util.log2Ceil(depth).W)); val wdata = Input(UInt(40.W))
      val raddr = Input(UInt(chisel3.util.log2Ceil(depth).W)); val rdata = Output(UInt(40.W))
    })
    if (sync) {
      val m = SyncReadMem(depth, UInt(40.W))
      when(io.wen) { m.write(io.waddr, io.wdata) }
      io.rdata := m.read(io.raddr)
    } else {
      val m = Mem(depth, UInt(40.W))
      when(io.wen) { m.write(io.waddr, io.wdata) }
      io.rdata := m(io.raddr)
    }
  }
  def emit(sync: Boolean, dir: os.Path): (String, Seq[os.Path]) = Synth.emit(() => new Ram(sync), dir)
}
