package moire.stream

/** A [[ByteLink]] that plays back bytes, `chunk` at a time, then stays silent; what the host writes is kept.
  * For recorder tests that need no pty: `Recorder.record(new MemoryLink(bytes), options with listenOnly, ...)`.
  */
final class MemoryLink(bytes: Array[Byte], chunk: Int = 64, val name: String = "memory") extends ByteLink {
  private var at = 0
  val written = scala.collection.mutable.ArrayBuffer.empty[Byte]
  def write(a: Array[Byte]): Unit = written ++= a
  def read(buf: Array[Byte]): Int = {
    val n = math.min(math.min(chunk, buf.length), bytes.length - at)
    if (n <= 0) { Thread.sleep(5); 0 }
    else { System.arraycopy(bytes, at, buf, 0, n); at += n; n }
  }
  def close(): Unit = ()
}
