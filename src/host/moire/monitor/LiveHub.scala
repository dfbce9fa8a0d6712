package moire.monitor

import java.util.concurrent.ConcurrentHashMap
import scala.jdk.CollectionConverters._

/** The pages connected by websocket: each gets the state (GET /api/state's JSON) every `periodMs`. */
final class LiveHub(live: Live, periodMs: Int = 200) extends AutoCloseable {
  private val channels = ConcurrentHashMap.newKeySet[cask.WsChannelActor]()
  @volatile private var stop = false
  def add(c: cask.WsChannelActor): Unit = channels.add(c)
  def remove(c: cask.WsChannelActor): Unit = channels.remove(c)
  def size: Int = channels.size

  private val thread = new Thread(() => while (!stop) {
    if (!channels.isEmpty) {
      val text = ujson.write(live.state)
      channels.asScala.foreach(c => try c.send(cask.Ws.Text(text)) catch { case _: Exception => channels.remove(c) })
    }
    Thread.sleep(periodMs)
  }, "monitor-hub")
  thread.setDaemon(true)
  thread.start()

  def close(): Unit = { stop = true; thread.join(2000) }
}
