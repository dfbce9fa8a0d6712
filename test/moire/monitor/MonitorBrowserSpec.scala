package moire.monitor

import moire.board.{BoardParams, ClockSource}
import moire.emit.{Emit, Target}
import moire.loop.{BenchHead, EndToEndSpec, LoopTop}
import moire.replay.VerilatorBuild
import moire.stream.PtyPair
import org.scalatest.flatspec.AnyFlatSpec

/** `moire monitor` in headless Chromium against the whole DE2-115 board top in Verilator on a pty pair (as
  * EndToEndSpec: an independent bench with a concealed 3rd harmonic of 1 %, a behavioural AD9226): the page shows the
  * Lissajous figure within seconds; its readouts match an independent fit of the records it saved and the bench's
  * own parameters; the burst control yields a report naming the harmonic; the board switched off shows as
  * disconnected, and the page recovers when it is back. Screenshots in target/browser/.
  */
class MonitorBrowserSpec extends AnyFlatSpec {
  // the pty ignores the baud rate: 115200 stands for the 12.5 MBd of the simulated UART
  "moire monitor" should "show the board top in Verilator live in Chromium, explain a burst and survive a disconnect" in {
    val p = BoardParams(adcClockHz = 50000000, baud = 12500000, glitchFilter = 2, decimation = 1 << 16,
      clockSource = ClockSource.Logic, burstSamples = 4096)
    val bench = BenchHead(50e6, speed = 250e3, wobbleHz = 2e3).copy(harmonic = 0.01, seed = 13)
    val e2e = new EndToEndSpec
    val verilog = Emit.elaborate(new LoopTop("de2-115", p), Target.Verilog)._2
    val harness = VerilatorBuild.harness(verilog, "LoopTop", source = new String(classOf[EndToEndSpec].getResourceAsStream("/moire/loop/board_loop.cpp").readAllBytes(), "UTF-8"))
    info(f"loop harness: ${if (harness.cached) "cached" else f"built in ${harness.buildSeconds}%.0f s"}")
    PtyPair { pty =>
      val stim = pty.dir / "stim.bin"
      e2e.stimulus(e2e.harmonic(bench), stim)
      pty.boardOut // the test holds the board end open: socat keeps the pair while the board is switched off
      def board() = os.proc(harness.exe, stim, pty.board, p.baudDivisor.toString, "1000000000000").spawn(stderr = pty.dir / "harness.log")
      var sim = board()
      val out = os.temp.dir(prefix = "moire-monitor-browser")
      val o = MonitorCmd.Options(Some(pty.host.toString), None, simulate = false, Nil, 115200, Some(4096L), "127.0.0.1", 0, out.toString,
        Scale(None, Some(0.16), None, Some(1.0)))
      val (server, all) = MonitorCmd.start(o, w => fail(w))
      try Browser() { b =>
        b.go(server.url)
        def points = b.attr("lissajous", "data-points").toInt
        val shown = b.waitFor("the Lissajous figure with its fitted ellipse", 30)(points >= 50 && b.attr("lissajous", "data-ellipse") == "yes")
        info(f"Lissajous with ellipse on the page $shown%.1f s after it opened")
        // readouts: enough records for a steady fit, then save; the page's values against an independent fit of the
        // records saved (offsets 0.1 % FS, ratio 0.003, phase 0.1 degree: the window moves on by a few records between)
        // and against the bench (offsets 0.2 % FS, ratio 0.005, phase 0.3 degree: the 1 % harmonic bends the figure, and the
        // fit of 2000 records at the phases the decimation happens to hit moves by up to 0.2 degree)
        b.waitFor("2048 records", 120)(b.text("link-records").toDouble >= 2048)
        b.find("save-btn").click()
        b.waitFor("the save", 10)(b.text("save-status").startsWith("saved"))
        def seen(key: String) = b.attr(s"ro-$key", "data-value").toDouble
        val page = Map("offset_sin" -> seen("offset_sin") / 100, "offset_cos" -> seen("offset_cos") / 100, "ratio" -> seen("ratio"), "phase" -> seen("phase_error"))
        b.screenshot("monitor-live")
        val csv = os.list(out).find(_.last.endsWith(".csv")).get
        val rec = moire.recording.Recording.read(csv)
        val f = OfflineEllipse.fit(rec.values(rec.cos), rec.values(rec.sin))
        info(f"page: offsets ${page("offset_sin")}%.5f ${page("offset_cos")}%.5f FS, ratio ${page("ratio")}%.5f, phase ${page("phase")}%.4f degree; " +
          f"independent fit of the ${rec.length} records saved: ${f.offsetSin}%.5f ${f.offsetCos}%.5f, ${f.ratio}%.5f, ${f.phaseErrorDeg}%.4f")
        assert(math.abs(page("offset_sin") - f.offsetSin) < 1e-3 && math.abs(page("offset_cos") - f.offsetCos) < 1e-3, page)
        assert(math.abs(page("ratio") - f.ratio) < 3e-3 && math.abs(page("phase") - f.phaseErrorDeg) < 0.1, page)
        assert(math.abs(page("offset_sin") - bench.offsetSin) < 2e-3 && math.abs(page("offset_cos") - bench.offsetCos) < 2e-3, page)
        assert(math.abs(page("ratio") - 1 / bench.gainCos) < 5e-3 && math.abs(page("phase") - bench.quadratureDeg) < 0.3, page)
        assert(b.text("flag-present").contains("yes"))
        // a burst from the page: the report names the concealed harmonic
        // the page offers the board's burst depth (4096 here) as the length
        b.waitFor("the board's burst depth as the burst length", 5)(b.js("return document.getElementById('burst-samples').value") == "4096")
        b.find("burst-btn").click()
        val took = b.waitFor("the burst report", 180)(Set("done", "failed")(b.attr("burst-status", "data-state")))
        assert(b.attr("burst-status", "data-state") == "done", b.text("burst-status"))
        info(f"burst of 4096 samples captured and explained in $took%.1f s: ${b.text("burst-status")}")
        // the report shown in the page's frame (same origin: its document is readable)
        def inFrame(sel: String) = String.valueOf(b.js(s"const d = document.getElementById('report').contentDocument; " +
          s"const e = d && d.querySelector('$sel'); return e ? e.textContent : null"))
        b.waitFor("the report in the page", 20)(inFrame("h1").startsWith("explain"))
        assert(inFrame(".finding h3").contains("harmonic"), inFrame("body").take(2000))
        b.screenshot("monitor-burst")
        // the board switched off: disconnected; back on: connected, records flow again
        sim.destroy(); sim.waitFor(5000)
        b.waitFor("the page showing the board disconnected", 20)(b.attr("status", "data-connected") == "false")
        b.screenshot("monitor-disconnected")
        sim = board()
        val back = b.waitFor("the page showing the board again", 60)(b.attr("status", "data-connected") == "true" &&
          points >= 50)
        info(f"the page showed the board again $back%.1f s after it was switched back on")
        assert(b.consoleErrors.isEmpty, b.consoleErrors)
      } finally { all.close(); sim.destroy(); sim.waitFor(5000); os.remove.all(out) }
    }
  }
}
