package moire.monitor

/** The monitor's HTTP API (docs/monitor.md): the page and its assets, the JSON state, the live websocket, burst, save,
  * tolerances and the newest burst's report. Bad requests get a 4xx and a JSON {"error": "..."}.
  */
final class MonitorRoutes(app: Monitor, hub: LiveHub)(implicit cc: castor.Context, log: cask.Logger) extends cask.Routes {
  private val Json = Seq("Content-Type" -> "application/json; charset=utf-8", "Cache-Control" -> "no-store")
  private def json(v: ujson.Value, code: Int = 200) = cask.Response(ujson.write(v), code, Json)
  private def error(code: Int, msg: String) = json(ujson.Obj("error" -> msg), code)

  @cask.get("/")
  def index(): cask.Response[String] = MonitorRoutes.asset("index.html").fold(error(500, "index.html missing from the jar"))(identity)

  @cask.get("/assets/:name")
  def assets(name: String): cask.Response[String] = MonitorRoutes.asset(name).getOrElse(error(404, s"no asset '$name'"))

  @cask.get("/api/state")
  def state(): cask.Response[String] = json(app.live.state)

  @cask.websocket("/api/live")
  def liveSocket(): cask.WebsocketResult = cask.WsHandler { channel =>
    hub.add(channel)
    cask.WsActor { case cask.Ws.Close(_, _) => hub.remove(channel) }
  }

  @cask.post("/api/burst")
  def burst(request: cask.Request): cask.Response[String] = app.burstOptions(request.text()) match {
    case Left(msg) => error(400, msg)
    case Right(b) => if (app.startBurst(b)) json(app.live.burst, 202) else error(409, "a burst is already running; wait for its report")
  }

  /** `t`: any value (the page adds the time, so that the frame loads the newest report). */
  @cask.get("/api/report")
  def report(t: String = ""): cask.Response[String] = app.report.fold(error(404, "no burst report yet: capture a burst first"))(h =>
    cask.Response(h, 200, Seq("Content-Type" -> "text/html; charset=utf-8", "Cache-Control" -> "no-store")))

  @cask.post("/api/save")
  def save(): cask.Response[String] = try json(ujson.Obj("files" -> ujson.Arr.from(app.save().map(p => ujson.Str(p.toString)))))
  catch {
    case e: moire.MoireError => error(409, e.getMessage)
    case e: java.io.IOException => error(500, moire.files.SafeWrite.reason(e))
  }

  @cask.get("/api/tolerances")
  def tolerances(): cask.Response[String] = json(app.live.tolerances.json)

  @cask.post("/api/tolerances")
  def setTolerances(request: cask.Request): cask.Response[String] = Tolerances.update(app.live.tolerances, request.text()) match {
    case Left(msg) => error(400, msg)
    case Right(t) => app.live.tolerances = t; json(t.json)
  }

  initialize()
}

object MonitorRoutes {
  private val types = Map("html" -> "text/html", "js" -> "text/javascript", "css" -> "text/css")
  /** A file of the page from the jar (moire/monitor/NAME), only plain names of the known types. */
  def asset(name: String): Option[cask.Response[String]] = {
    val ext = name.split('.').lastOption.getOrElse("")
    if (!name.matches("[a-z]+\\.[a-z]+") || !types.contains(ext)) return None
    Option(getClass.getResourceAsStream(s"/moire/monitor/$name")).map { in =>
      val text = try new String(in.readAllBytes(), "UTF-8") finally in.close()
      cask.Response(text, 200, Seq("Content-Type" -> s"${types(ext)}; charset=utf-8"))
    }
  }
}
