package moire.monitor

/** The web server (cask on Undertow) of a [[Monitor]], on `bind`:`port` (0 = a free port; `port` tells which). */
final class MonitorServer(app: Monitor, bind: String, requestedPort: Int) extends AutoCloseable {
  cask.main.Main.silenceJboss() // no XNIO / JBoss banner lines on the terminal
  private val hub = new LiveHub(app.live)
  private val main = new cask.Main {
    lazy val routes = new MonitorRoutes(app, hub)(actorContext, log)
    def allRoutes: Seq[cask.main.Routes] = Seq(routes)
  }
  private val server = io.undertow.Undertow.builder.addHttpListener(requestedPort, bind).setHandler(main.defaultHandler).build
  try server.start() catch {
    case e: RuntimeException => throw new MonitorError(s"cannot listen on $bind:$requestedPort: ${Option(e.getCause).getOrElse(e).getMessage} (another program on that port? try --http-port 0)")
  }
  val port: Int = server.getListenerInfo.get(0).getAddress.asInstanceOf[java.net.InetSocketAddress].getPort
  def url: String = s"http://${if (bind.contains(":")) s"[$bind]" else bind}:$port/"
  def close(): Unit = { hub.close(); server.stop() }
}
