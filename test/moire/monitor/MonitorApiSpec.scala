package moire.monitor

import java.net.URI
import java.net.http.{HttpClient, HttpRequest, HttpResponse}
import org.scalatest.flatspec.AnyFlatSpec

/** The monitor's HTTP API without a browser, on the simulated board (docs/monitor.md): the JSON state and its readouts
  * against the simulation's own parameters and an independent fit, a burst that names the simulation's concealed
  * harmonic, save, tolerances, and bad requests (4xx with a message).
  */
class MonitorApiSpec extends AnyFlatSpec {
  private val http = HttpClient.newHttpClient()
  private def get(url: String) = http.send(HttpRequest.newBuilder(URI.create(url)).build(), HttpResponse.BodyHandlers.ofString())
  private def post(url: String, body: String) = http.send(HttpRequest.newBuilder(URI.create(url))
    .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString())
  private def until[T](what: String, seconds: Double)(f: => Option[T]): T = {
    val end = System.nanoTime() + (seconds * 1e9).toLong
    var r = f
    while (r.isEmpty && System.nanoTime() < end) { Thread.sleep(50); r = f }
    r.getOrElse(fail(s"not within $seconds s: $what"))
  }

  "monitor --simulate" should "serve its state, a burst report, save, and refuse bad requests with a 4xx and a message" in {
    val out = os.temp.dir(prefix = "moire-monitor-out")
    val o = MonitorCmd.Options(None, None, simulate = true, Nil, 115200, None, "127.0.0.1", 0, out.toString, Scale.none)
    val (server, all) = MonitorCmd.start(o, w => fail(s"unexpected warning: $w"))
    try {
      val base = server.url
      assert(get(base).statusCode == 200 && get(base).body.contains("<canvas id=\"lissajous\""))
      assert(get(base + "assets/monitor.js").headers.firstValue("Content-Type").get.startsWith("text/javascript"))
      // the state: readouts against the simulated board's parameters (SimBoard: offsets 1.2 and -0.6 % FS, gains 1 and
      // 0.96 of 0.8 FS, phase error 1.5 degree) and against an independent fit of the same records (the window saved)
      val st = until("an ellipse in /api/state", 20) {
        val j = ujson.read(get(base + "api/state").body)
        if (j("connected").bool && !j("ellipse").isNull && j("records_total").num >= Live.Window) Some(j) else None
      }
      val e = st("ellipse")
      assert(math.abs(e("offset_sin").num - 0.012) < 0.001 && math.abs(e("offset_cos").num + 0.006) < 0.001, e)
      assert(math.abs(e("ratio").num - 1 / 0.96) < 0.01 && math.abs(e("phase_error_deg").num - 1.5) < 0.1, e)
      assert(st("position")("um").num == st("position")("counts").num / SimBoard.CountsPerPeriod * SimBoard.PeriodUm)
      assert(math.abs(st("speed")("fringe_hz").num - 5000) < 50, st("speed"))
      val saved = ujson.read(post(base + "api/save", "").body)("files").arr.map(v => os.Path(v.str))
      val rec = moire.recording.Recording.read(saved.find(_.last.endsWith(".csv")).get)
      val state = ujson.read(os.read(saved.find(_.last.endsWith(".state.json")).get))
      val f = OfflineEllipse.fit(rec.values(rec.cos), rec.values(rec.sin))
      val se = state("ellipse")
      info(f"readouts at save: phase ${se("phase_error_deg").num}%.4f degree, independent fit ${f.phaseErrorDeg}%.4f; ratio ${se("ratio").num}%.5f / ${f.ratio}%.5f")
      // stated tolerances: offsets 0.05 % FS, ratio 0.002, phase 0.05 degree (the two fits minimise different distances)
      assert(math.abs(se("offset_sin").num - f.offsetSin) < 5e-4 && math.abs(se("offset_cos").num - f.offsetCos) < 5e-4)
      assert(math.abs(se("ratio").num - f.ratio) < 2e-3 && math.abs(se("phase_error_deg").num - f.phaseErrorDeg) < 0.05)
      // bad requests
      for ((url, body, code, msg) <- Seq(
        ("api/burst", """{"samples": 5}""", 400, "samples must be in"),
        ("api/burst", """{"samples": 1e400}""", 400, "samples must be an integer"),
        ("api/burst", """{"samples": 4096, "pre": 4096}""", 400, "pre must be in"),
        ("api/burst", """{"trigger": "sometimes"}""", 400, "trigger 'sometimes'"),
        ("api/burst", """{"sample": 4096}""", 400, "unknown field 'sample'"),
        ("api/burst", "[1,2", 400, "not JSON"),
        ("api/tolerances", """{"phase_deg": -1}""", 400, "phase_deg must be"),
        ("api/tolerances", """{"amplitude_min_pct": 99}""", 400, "must be below"),
        // a mark no converter shows (another tool's fuzz sweep took 500 %)
        ("api/tolerances", """{"amplitude_max_pct": 500}""", 400, "amplitude_max_pct must be a number above 0 and at most 100"),
        ("api/tolerances", """{"speed": 1}""", 400, "unknown tolerance"))) {
        val r = post(base + url, body)
        assert(r.statusCode == code && r.body.contains(msg), s"$url $body: ${r.statusCode} ${r.body}")
      }
      assert(get(base + "api/report").statusCode == 404 && get(base + "api/report").body.contains("capture a burst first"))
      assert(get(base + "assets/..%2Fsecret").statusCode == 404)
      assert(get(base + "nothing/here").statusCode == 404)
      assert(post(base + "api/state", "").statusCode == 405)
      // tolerances: set one, the readouts use it
      assert(post(base + "api/tolerances", """{"phase_deg": 1}""").statusCode == 200)
      until("the new phase tolerance in the readouts", 5) {
        ujson.read(get(base + "api/state").body)("readouts").arr.find(_("key").str == "phase_error").filter(_("hi").num == 1.0)
      }
      // a burst: the report names the simulated board's concealed effect (a 3rd harmonic on sin)
      val b = post(base + "api/burst", """{"samples": 16384}""")
      assert(b.statusCode == 202, b.body)
      assert(post(base + "api/burst", """{"samples": 16384}""").statusCode == 409)
      val done = until("the burst report", 60) {
        val j = ujson.read(get(base + "api/state").body)("burst")
        if (j("state").str == "running") None else Some(j)
      }
      assert(done("state").str == "done", done)
      assert(done("findings").arr.exists(f => f("effect").str == "harmonic" && f("channel").str == "sin"), done)
      val html = get(base + "api/report")
      assert(html.statusCode == 200 && html.body.contains("harmonic") && html.body.contains("data:image/png;base64,"))
      // a burst from a replay has no trigger hardware: refused at once (it was accepted, then failed)
      val refused = post(base + "api/burst", """{"samples": 4096, "trigger": "z"}""")
      assert(refused.statusCode == 400 && refused.body.contains("no trigger hardware"), refused.body)
      assert(ujson.read(get(base + "api/state").body)("burst")("state").str == "done")
      val files = ujson.read(post(base + "api/save", "").body)("files").arr.map(v => os.Path(v.str).last)
      assert(files.exists(_.endsWith(".html")) && files.count(_.endsWith(".csv")) == 2, files)
    } finally { all.close(); os.remove.all(out) }
  }

  "monitor" should "refuse bad options in one line" in {
    def err(o: MonitorCmd.Options) = intercept[MonitorError](MonitorCmd.validate(o)).getMessage
    val o = MonitorCmd.Options(None, None, simulate = true, Nil, 115200, None, "127.0.0.1", 0, "monitor", Scale.none)
    assert(err(o.copy(simulate = false)).contains("give one of --port"))
    assert(err(o.copy(port = Some("/dev/ttyUSB9"))).contains("give one of"))
    assert(err(o.copy(httpPort = 70000)).contains("--http-port must be in 0..65535"))
    assert(err(o.copy(bind = "192.0.2.1")).contains("--bind '192.0.2.1' is not an address of this computer")) // TEST-NET-1
    assert(err(o.copy(scale = Scale(None, Some(-1), None, None))).contains("--period-um must be a positive finite number"))
    assert(err(o.copy(simulate = false, replay = Some("x.csv"), effects = Seq("jitter:jitter_s=1e-9"))).contains("--effect belongs to --simulate"))
    assert(intercept[MonitorError](MonitorCmd.source(o.copy(simulate = false, replay = Some("/nonexistent.csv")))).getMessage.contains("no such file"))
    val warned = Seq.newBuilder[String]
    val (server, all) = MonitorCmd.start(o.copy(bind = "0.0.0.0"), warned += _)
    try assert(warned.result().exists(_.contains("WARNING: the monitor listens on 0.0.0.0")))
    finally all.close()
  }

  "monitor --port" should "say in the terminal, once, that a port it cannot open is not connected" in {
    val o = MonitorCmd.Options(Some("/nonexistent/ttyNONE"), None, simulate = false, Nil, 115200, None, "127.0.0.1", 0,
      os.temp.dir(prefix = "moire-monitor-out").toString, Scale.none)
    val warned = new java.util.concurrent.ConcurrentLinkedQueue[String]()
    val (server, all) = MonitorCmd.start(o, w => fail(s"unexpected warning: $w"), w => warned.add(w))
    try {
      until("a line on the port", 10)(if (warned.isEmpty) None else Some(()))
      Thread.sleep(2500) // two more tries, which are not said again
      val lines = warned.toArray.toSeq.map(_.toString)
      assert(lines.size == 1 && lines.head.startsWith("monitor: board on /nonexistent/ttyNONE: not connected: ") &&
        lines.head.endsWith("(tried again every second)") && !lines.head.contains("Exception"), lines)
      info(lines.head)
      assert(!ujson.read(get(server.url + "api/state").body)("connected").bool)
    } finally all.close()
  }

  "monitor --replay" should "play a recording at its own rate, its position from the fringe phase when it has no position column" in {
    val dir = os.temp.dir(prefix = "moire-monitor-replay")
    val m = moire.explain.PhysicsModel(moire.signal.SignalParams(amplitude = 0.7, phaseErrorDeg = -1.0, noiseRms = 0.0005, seed = 2),
      moire.signal.Motion.Constant(200), 20000, 40000, moire.signal.Adc(12))
    moire.recording.Recording.write(dir / "r.csv", m.generate()._1)
    val o = MonitorCmd.Options(None, Some((dir / "r.csv").toString), simulate = false, Nil, 115200, None, "127.0.0.1", 0, (dir / "out").toString, Scale.none)
    val t0 = System.nanoTime() // before start: the replay's clock starts there, the server after it
    val (server, all) = MonitorCmd.start(o, w => fail(w))
    try {
      val st = until("an ellipse", 20) {
        val j = ujson.read(get(server.url + "api/state").body)
        if (!j("ellipse").isNull && j("records_total").num >= 2000) Some(j) else None
      }
      val played = st("link")("played").num; val wall = (System.nanoTime() - t0) / 1e9
      assert(played <= (wall + 0.5) * 20000, s"$played samples in $wall s: faster than the recording's 20 kHz")
      assert(st("setup")("scale")("counts_per_period").num == 4 && st("source").str == "replay of r.csv")
      assert(math.abs(st("ellipse")("phase_error_deg").num + 1.0) < 0.1, st("ellipse"))
      // 200 periods/s, 4 counts per period
      assert(math.abs(st("speed")("counts_per_s").num - 800) < 20, st("speed"))
    } finally { all.close(); os.remove.all(dir) }
  }
}
