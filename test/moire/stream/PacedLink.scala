package moire.stream

/** A [[ByteLink]] that plays back bytes at about `bytesPerSecond` from its first read (as a UART brings them), then
  * stays silent; what the host writes is dropped. For recorder tests whose wall time matters (a clock, Ctrl-C).
  */
final class PacedLink(bytes: Array[Byte], bytesPerSecond: Double, val name: String = "paced") extends ByteLink {
  private var t0 = -1L
  private var at = 0
  def write(a: Array[Byte]): Unit = ()
  def read(buf: Array[Byte]): Int = {
    if (t0 < 0) t0 = System.nanoTime()
    Thread.sleep(5)
    val due = math.min(bytes.length.toLong, ((System.nanoTime() - t0) / 1e9 * bytesPerSecond).toLong).toInt
    val n = math.min(buf.length, due - at)
    if (n <= 0) 0 else { System.arraycopy(bytes, at, buf, 0, n); at += n; n }
  }
  def close(): Unit = ()
}

object PacedLink {
  /** `seconds` of a board's stream of 8-record frames at `recordsPerSecond`, records D apart, paced at that rate. */
  def board(seconds: Double, recordsPerSecond: Double, d: Long = 80000, clock: Double = 40e6): PacedLink = {
    val n = 8
    val recs = BoardStreamFixture.records(((seconds * recordsPerSecond).toInt / n + 2) * n, d, clock)
    val bytes = Encoder.frames(recs.grouped(n).zipWithIndex.map { case (rs, k) => RecordFrame(k, 0, rs) }.toSeq)
    new PacedLink(bytes, moire.protocol.StreamV1.recordFrameBytes(n) * recordsPerSecond / n)
  }
}
