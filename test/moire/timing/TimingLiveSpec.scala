package moire.timing

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The open ECP5 flow on a CORDIC with multipliers (rotate mode, n = 8, b = 12: its gain compensation):
  * synth_ecp5, nextpnr-ecp5 out of context at speed grade 6. The subdivider is placed in context by
  * `moire.board.Ulx3sBuildSpec`; the larger designs, the rotate CORDIC at n = 16, b = 18 among them, are benchmarks
  * (`run timing`, README table): its place and route took 4.5-5.6 min of the suite, this one's under a minute.
  * Cancelled where the tools are not installed (boards/tools/ecp5-tools.sh; CI installs them).
  */
class TimingLiveSpec extends AnyFlatSpec with Matchers {
  private def tools: Ecp5Tools = Ecp5Tools.status.fold(cancel(_), identity)
  private lazy val cache = os.temp.dir(prefix = "moire-timing-cache-")
  private lazy val opts = TimingOptions(speeds = Seq(6), cache = cache)
  private val rotate = moire.cordic.CordicParams(mode = moire.cordic.CordicMode.Rotate, iterations = 8, width = 12)
  private val gen = moire.designs.Designs.cordic(rotate).place
  private lazy val first = Timing.run(tools, "cordic", gen, opts, _ => ())

  "timing" should "place a rotate-mode CORDIC at speed grade 6 at or above 65 MHz" in {
    val s = first.speeds.head
    s.speed shouldBe 6
    withClue(first.text) { s.fmax should be >= 65.0 }
    s.meets shouldBe true
    s.registers should be > 100L
    s.luts should be > 100L
    s.multipliers should be >= 1L
    s.cached shouldBe false
    val p = s.criticalPath.get
    p.signals should not be empty
    p.from should not startWith "$"
    p.logicLevels should be >= 1
    first.json("speed_grades")(0)("fmax_mhz").num shouldBe s.fmax +- 0.01
  }

  it should "read a second run of the same Verilog from the cache at once" in {
    val t0 = System.nanoTime()
    val again = Timing.run(tools, "cordic", gen, opts, _ => ())
    val seconds = (System.nanoTime() - t0) / 1e9
    again.speeds.head.cached shouldBe true
    again.speeds.head.fmax shouldBe first.speeds.head.fmax
    seconds should be < 60.0 // elaboration only
  }

  it should "say in one line which tool is missing" in {
    val none = Ecp5Tools(Some(os.temp.dir() / "no-such-bin"))
    val e = the[TimingError] thrownBy Timing.run(none, "cordic", gen, TimingOptions(speeds = Seq(6), cache = os.temp.dir()), _ => ())
    e.getMessage should include("ecp5-tools.sh")
    e.getMessage.linesIterator.size shouldBe 1
  }
}
