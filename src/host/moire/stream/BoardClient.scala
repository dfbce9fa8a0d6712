package moire.stream

import moire.protocol.{Reg, Registers, StreamV1}


/** The board did not answer a command in time. */
final class NoAnswer(val addr: Int, msg: String) extends Exception(msg)

/** Register reads and writes over a link while the board may be streaming records.
  * Each command is sent, then the stream is decoded until a reply for the same address comes
  * (record frames in between are counted in `recordFramesSeen` and otherwise ignored);
  * after `timeoutMs` the command is sent again, `retries` times, then [[NoAnswer]].
  */
final class BoardClient(val link: ByteLink, timeoutMs: Int = 500, retries: Int = 2) {
  val decoder = new Decoder(1)
  private val buf = new Array[Byte](4096)
  private var seenFrames = 0L
  def recordFramesSeen: Long = seenFrames
  private val burstFrames = scala.collection.mutable.ArrayBuffer.empty[Frame]
  /** Burst frames decoded while waiting for replies (they may follow a reply in the same read); taken once. */
  def takeBurstFrames(): Vector[Frame] = { val v = burstFrames.toVector; burstFrames.clear(); v }

  def read(r: Reg): Long = transact(Command.read(r.addr))
  def read(addr: Int): Long = transact(Command.read(addr))
  /** Writes; returns the value the board reports after the write. */
  def write(addr: Int, value: Long): Long = transact(Command.write(addr, value))

  def transact(c: Command): Long = {
    var attempt = 0
    while (attempt <= retries) {
      link.write(Encoder.command(c))
      val until = System.nanoTime() + timeoutMs * 1000000L
      while (System.nanoTime() < until) {
        val n = link.read(buf)
        if (n > 0) {
          var answer = -1L
          decoder.feed(buf, 0, n).foreach {
            case r: RegisterReply if r.addr == c.addr && answer < 0 => answer = r.value
            case _: RecordFrame => seenFrames += 1
            case b @ (_: BurstInfo | _: BurstSamples) => burstFrames += b
            case _ =>
          }
          if (answer >= 0) return answer
        }
      }
      attempt += 1
    }
    throw new NoAnswer(c.addr, s"${link.name}: the board did not answer ${if (c.write) "a write to" else "a read of"} " +
      s"${Registers.name(c.addr)} within ${timeoutMs} ms (${retries + 1} tries, ${decoder.stats.bytes} bytes, " +
      s"${decoder.stats.frames} frames received)")
  }
}

object BoardClient {
  /** Reads id and version and checks them; one clear line when the board does not answer or is not ours. */
  def check(c: BoardClient, baud: Int, hint: String): (Long, Long) = {
    val id = try c.read(Registers.Id) catch {
      case e: NoAnswer => throw new StreamError(s"${e.getMessage}: check --baud ($baud), the wiring and that the moire design is loaded$hint")
    }
    if (id != Registers.IdValue)
      throw new StreamError(f"${c.link.name}: register id reads 0x$id%08x, not 0x${Registers.IdValue}%08x (MOIR): not a moire board?")
    val v = c.read(Registers.Version)
    if (!StreamV1.ReadableVersions.contains(v.toInt) || v > Int.MaxValue)
      throw new StreamError(s"${c.link.name}: the board speaks stream format version $v; this host tool reads versions ${StreamV1.ReadableVersions.mkString(", ")}")
    (id, v)
  }
}
