package moire.timing

import moire.cordic.{CordicMode, CordicParams}
import moire.cost.{Cost, Synth, Yosys}
import moire.designs.Designs
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** `cost` (yosys 0.23, Cyclone IV E) counts the multiplier blocks the ECP5 flow maps (MULT18X18D after
  * synth_ecp5's coarse step: multipliers are known there, no place and route needed). The whole cost
  * run of the corrected chain takes minutes, so its count is taken by the same script cut short after
  * the multiplications, which the subdivider shows gives the whole run's count.
  */
class CostEcp5Spec extends AnyFlatSpec with Matchers {
  private val p = CordicParams(CordicMode.SinCos, 16, 18)

  for (name <- Seq("subdiv", "corrected")) {
    s"cost's multiplier count of $name" should "match the ECP5 flow's" in {
      assume(Yosys.available, "yosys not installed")
      val tools = Ecp5Tools.status.fold(cancel(_), identity)
      val d = Designs.find(name, p).toOption.get
      val work = os.temp.dir(prefix = "moire-cost-ecp5-")
      val cost = try {
        val (top, files) = Synth.emit(d.gen, work / "rtl")
        val short = Yosys.multipliers(top, files, work / "mul", 1800)
        if (name == "subdiv") Cost.measure(d, None, work / "full", 1800, _ => ()).synth.multipliers shouldBe short
        short
      } finally os.remove.all(work)
      val ecp5 = Timing.multipliers(tools, d.place, TimingOptions(), _ => ())
      ecp5 should be > 0L
      cost shouldBe ecp5
    }
  }
}
