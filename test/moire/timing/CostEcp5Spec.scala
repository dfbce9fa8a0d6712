package moire.timing

import moire.cordic.{CordicMode, CordicParams}
import moire.cost.{Cost, CostDesigns, Yosys}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** `cost` (yosys 0.23, Cyclone IV E) counts the multiplier blocks the ECP5 flow maps (MULT18X18D after
  * synth_ecp5: multipliers are known after synthesis, no place and route needed).
  */
class CostEcp5Spec extends AnyFlatSpec with Matchers {
  private val p = CordicParams(CordicMode.SinCos, 16, 18)

  for (name <- Seq("subdiv", "corrected")) {
    s"cost's multiplier count of $name" should "match the ECP5 flow's" in {
      assume(Yosys.available, "yosys not installed")
      val tools = Ecp5Tools.find.getOrElse(cancel(s"ECP5 tools not installed: ${Ecp5Tools.installHint}"))
      val d = CostDesigns.find(name).toOption.get
      val work = os.temp.dir(prefix = "moire-cost-ecp5-")
      val cost = try Cost.measure(d, p, work, 1800, _ => ()) finally os.remove.all(work)
      val ecp5 = Timing.synthCells(tools, TimingDesigns.gen(d, p), TimingOptions(), _ => ())
      ecp5.multipliers should be > 0L
      cost.synth.multipliers shouldBe ecp5.multipliers
    }
  }
}
