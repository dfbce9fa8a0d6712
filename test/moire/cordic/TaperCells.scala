package moire.cordic

import moire.emit.{Emit, Target}
import scala.sys.process._

/** Benchmark, not a test: yosys cell counts of the conventional and the tapered sincos CORDIC beside
  * seed 001 Table 1 (2769 LEs, 15 clocks). Logic cells = cycloneive_lcell_comb + dffeas after
  * `synth_intel -family cycloneive`. Run: ./sbt "Test/runMain moire.cordic.TaperCells [out folder]"
  */
object TaperCells {
  def yosysCommand(top: String): String =
    s"read_verilog -sv $top.sv; synth_intel -family cycloneive -top $top; tee -q -o stat.txt stat"

  /** (combinational cells, flip-flops) of one configuration. */
  def cells(p: CordicParams, out: os.Path): (Int, Int) = {
    val dir = out / p.moduleName
    os.makeDir.all(dir)
    Emit.write(new Cordic(p), dir, Target.Verilog)
    val code = Process(Seq("yosys", "-q", "-p", yosysCommand(p.moduleName)), dir.toIO).!(ProcessLogger(_ => ()))
    require(code == 0, s"yosys failed in $dir")
    val stat = os.read.lines(dir / "stat.txt")
    def count(cell: String) = stat.map(_.trim.split("\\s+")).collectFirst { case Array(`cell`, n) => n.toInt }.getOrElse(0)
    (count("cycloneive_lcell_comb"), count("dffeas"))
  }

  def main(args: Array[String]): Unit = {
    val out = os.Path(args.headOption.getOrElse("generated/taper-cells"), os.pwd)
    val base = CordicParams(CordicMode.SinCos, 16, 20)
    val configs = Seq(base, base.copy(taper = true), TaperFigures.lean.copy(taper = false), TaperFigures.lean)
    println(s"yosys -q -p \"${yosysCommand("<module>")}\" in $out/<module>")
    println(f"${"configuration"}%-48s ${"comb"}%6s ${"ff"}%6s ${"cells"}%6s ${"clocks"}%6s ${"bound"}%10s")
    println(f"${"seed 001 Table 1 (Quartus LEs)"}%-48s ${""}%6s ${""}%6s ${2769}%6d ${15}%6d ${3.13e-5}%10.3e")
    for (p <- configs) {
      val (c, f) = cells(p, out)
      println(f"${p.moduleName}%-48s $c%6d $f%6d ${c + f}%6d ${p.latency}%6d ${CordicBound.headline(p).total}%10.3e")
    }
  }
}
