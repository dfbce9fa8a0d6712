package moire.explain

import java.util.concurrent.ConcurrentHashMap

/** Time spent in named parts of the fit, summed over calls and threads, when `-Dmoire.timing` is set (else a plain
  * call): explain-bench prints them after its figures.
  */
object Laps {
  val on: Boolean = sys.props.contains("moire.timing")
  private val nanos = new ConcurrentHashMap[String, java.lang.Long]()
  private val calls = new ConcurrentHashMap[String, java.lang.Long]()

  def apply[T](part: String)(body: => T): T =
    if (!on) body
    else {
      val t0 = System.nanoTime()
      try body
      finally {
        nanos.merge(part, System.nanoTime() - t0, (a: java.lang.Long, b: java.lang.Long) => a + b)
        calls.merge(part, 1L, (a: java.lang.Long, b: java.lang.Long) => a + b)
      }
    }

  /** One line per part, the longest first: thread time in ms and calls. */
  def lines: Seq[String] = {
    import scala.jdk.CollectionConverters._
    nanos.asScala.toSeq.sortBy(-_._2.longValue).map { case (k, v) => f"lap $k: ${v / 1e6}%.0f ms in ${calls.get(k)} calls" }
  }
}
