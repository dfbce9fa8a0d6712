package moire.monitor

import moire.explain.{EffectSpec, ExplainCmd, HtmlReport, PhysicsModel}
import moire.recording.Recording
import moire.signal.{Adc, Motion, SignalParams}
import org.scalatest.flatspec.AnyFlatSpec

/** `explain --html` in headless Chromium: one self-contained page that opens offline with no console error and every
  * image drawn; the JSON names the HTML and the plots; sections come from the report data (an unknown list shows too).
  */
class ReportBrowserSpec extends AnyFlatSpec {
  private def recording(file: os.Path): Unit = {
    val m = PhysicsModel(SignalParams(amplitude = 0.85, offsetSin = 0.01, phaseErrorDeg = 1.0, noiseRms = 0.0007, seed = 3),
      Motion.Ramp(20e3, 120e3, 0.01), 10e6, 100000, Adc(12), None, Seq(EffectSpec("harmonic", Map("order" -> 3, "amplitude_rel" -> 0.004), "sin")))
    val (r, _) = m.generate()
    Recording.write(file, r.copy(meta = r.meta ++ Map("counts_per_period" -> "4096", "period_um" -> "20")))
  }

  "explain --html" should "write one self-contained report that Chromium shows with every plot and no console error" in {
    val dir = os.temp.dir(prefix = "moire-html")
    try {
      recording(dir / "sim.csv")
      ExplainCmd.explain(Seq((dir / "sim.csv").toString), Some((dir / "json").toString), Some((dir / "plots").toString), None, quiet = true,
        rtl = None, html = Some((dir / "sim.html").toString))
      val j = ujson.read(os.read(dir / "json" / "sim.json"))
      assert(j("html").str == (dir / "sim.html").toString)
      val plots = j("plots").arr.map(v => os.Path(v.str))
      assert(plots.forall(os.isFile(_)) && Seq("_lissajous_before.png", "_lissajous_after.png", "_interpolation_error.png").forall(s => plots.exists(_.last.endsWith(s))))
      val ie = j("interpolation_error")
      assert(ie("unit").str == "counts" && ie("scaled_unit").str == "um")
      assert(ie("after_correction")("rms").num < ie("before_correction")("rms").num, ie)
      val html = os.read(dir / "sim.html")
      assert(!html.contains("http://") && !html.contains("https://"), "the report must open offline")
      for (s <- Seq("Summary", "Readouts", "Interpolation error", "Lissajous figure", "Findings", "Unexplained structure", "What was not tested"))
        assert(html.contains(s), s)
      Browser(1100, 1400) { b =>
        b.go((dir / "sim.html").toIO.toURI.toString)
        b.waitFor("the page loaded", 20)(b.js("return document.readyState") == "complete")
        val images = b.js("return document.images.length").toString.toInt
        assert(images == plots.size, s"$images images on the page, ${plots.size} plots")
        b.waitFor("every image drawn", 20)(b.js("return Array.from(document.images).every(i => i.complete && i.naturalWidth > 0)") == true)
        assert(b.consoleErrors.isEmpty, b.consoleErrors)
        assert(b.driver.findElement(org.openqa.selenium.By.cssSelector(".finding h3")).getText.contains("harmonic"))
        b.screenshot("explain-report")
      }
      // two files need --html-dir; --html-dir writes one page each
      os.copy(dir / "sim.csv", dir / "sim2.csv")
      assert(intercept[moire.MoireError](ExplainCmd.explain(Seq((dir / "sim.csv").toString, (dir / "sim2.csv").toString), None, None, None,
        quiet = true, rtl = None, html = Some((dir / "x.html").toString))).getMessage.contains("--html-dir"))
      val code = moire.cli.Main.run(Array("explain", (dir / "sim.csv").toString, (dir / "sim2.csv").toString, "--html-dir", (dir / "h").toString,
        "--json-dir", (dir / "j2").toString, "--quiet", "--no-rtl"))
      assert(code == 0 && Seq("sim", "sim2").forall(s => os.isFile(dir / "h" / s"$s.html") && ujson.read(os.read(dir / "j2" / s"$s.json"))("html").str == (dir / "h" / s"$s.html").toString))
    } finally os.remove.all(dir)
  }

  "The HTML renderer" should "show a report list it does not know (new report keys need no change)" in {
    val j = ujson.Obj("file" -> "a.csv", "kind" -> "signals", "findings" -> ujson.Arr(), "negligible" -> ujson.Arr(ujson.Obj("effect" -> "drift", "why" -> "below noise")),
      "default_model_note" -> "the default model does not follow the signal")
    val h = HtmlReport.render(j, Nil)
    assert(h.contains("<h2>Negligible</h2>") && h.contains("below noise") && h.contains("does not follow the signal"))
  }
}
