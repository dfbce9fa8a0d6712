package moire.designs

import moire.adapt.AdaptParams
import moire.board.{BoardParams, ClockSource}
import moire.cordic.{CordicMode, CordicParams, Rounding, SimSupport, TaperFigures}
import moire.emit.Target
import moire.harmonic.HarmonicParams
import moire.io.QuadratureParams
import moire.quadcomp.QuadCompParams
import moire.signal.AdcFormat
import moire.subdiv.{PhaseMethod, SubdivParams}
import org.scalatest.flatspec.AnyFlatSpec

/** Every registered design (and a spread of other configurations) as `emit` writes it, for both targets:
  * `verilator --lint-only -Wall` without a warning (waivers.vlt exempts vendor declarations only), and
  * Debian yosys `read_verilog -sv; hierarchy -check`.
  */
class DesignLintSpec extends AnyFlatSpec {
  private val waivers = os.Path(getClass.getResource("/moire/designs/waivers.vlt").getPath)
  private val logicClock = BoardParams(clockSource = ClockSource.Logic, adcClockHz = 25000000)

  /** (label, design): the registry at its defaults, then configurations the defaults leave out. */
  private val designs: Seq[(String, Design)] = Designs.all().map(d => d.name -> d) ++ Seq(
    "cordic atan2 n20 b24 every 4" -> Designs.cordic(CordicParams(CordicMode.Atan2, 20, 24, pipelineEvery = 4)),
    "cordic acos-double table 64 truncate" ->
      Designs.cordic(CordicParams(CordicMode.AcosDouble, 16, 18, peakTableSize = 64, rounding = Rounding.Truncate)),
    "cordic asin n12 b16" -> Designs.cordic(CordicParams(CordicMode.Asin, 12, 16)),
    "cordic rotate n8 b12 no gain compensation" -> Designs.cordic(CordicParams(CordicMode.Rotate, 8, 12, gainCompensation = false)),
    "cordic sincos taper (lean)" -> Designs.cordic(TaperFigures.lean),
    "subdiv asin-double 14 bits M 65536 tc" ->
      Designs.subdiv(SubdivParams(14, PhaseMethod.AsinDouble, counts = 65536, minEdgeClocks = 5), AdcFormat.TwosComplement),
    "quadcomp n12 b16 fused peaks" -> Designs.quadcomp(QuadCompParams(iterations = 12, width = 16, averageLog2 = 0, fusePeaks = true)),
    "adapt 14 -> 18 bits, no harmonic table" ->
      Designs.adapt(AdaptParams(inputBits = 14, outputBits = 18, mulFrac = 2, harmonicEntries = 0)),
    "harmonic m2 every 4 out-frac 0" -> Designs.harmonic(HarmonicParams(harmonics = 2, pipelineEvery = 4, outFrac = 0)),
    "counter 16 bits, 3 sync stages" -> Designs.counter(QuadratureParams(16, 3)),
    "board-de2-115 logic clock" -> Designs.boardTop(moire.board.de2115.De2115, "board-de2-115-logic", logicClock),
    "board-ulx3s logic clock" -> Designs.boardTop(moire.board.ulx3s.Ulx3s, "board-ulx3s-logic", logicClock.copy(clockHz = 25000000)))

  for ((label, d) <- designs) {
    s"$label" should "lint clean in verilator -Wall and read in yosys, as SystemVerilog and as Verilog" in {
      SimSupport.requireTool(this, "verilator")
      for (t <- Seq(Target.SystemVerilog, Target.Verilog)) {
        val dir = os.temp.dir(prefix = s"moire-lint-${d.name}-")
        try {
          val files = d.write(dir / "rtl", t)
          assert(files.head.last == s"${d.topName}.sv", files)
          val vendor = Lint.vendor(files, dir)
          val (v, vlog) = Lint.verilator(d.topName, files, vendor, waivers)
          assert(v == 0 && vlog.trim.isEmpty, s"${d.topName} (${t.name}): verilator exit $v\n$vlog")
          if (SimSupport.hasYosys) {
            val (y, ylog) = Lint.yosys(d.topName, files, vendor)
            assert(y == 0, s"${d.topName} (${t.name}): yosys exit $y\n$ylog")
          }
        } finally os.remove.all(dir)
      }
    }
  }

  "The registry" should "name each design once and read top name and latency from the module" in {
    assert(Designs.names.distinct == Designs.names, Designs.names)
    for (name <- Seq("cordic", "subdiv", "quadcomp", "adapt", "corrected", "harmonic", "turntable", "counter", "board-de2-115", "board-ulx3s"))
      assert(Designs.names.contains(name), name)
    val s = Designs.find("subdiv").toOption.get
    assert(s.latency.contains(moire.subdiv.SubdivAdc.latency(SubdivParams())) && s.topName == s"${SubdivParams().moduleName}_ob")
    assert(Designs.find("board-de2-115").toOption.get.latency.isEmpty)
    assert(Designs.find("nope").left.toOption.get == s"--design: 'nope' is not a design; allowed: ${Designs.names.mkString(", ")}")
  }
}
