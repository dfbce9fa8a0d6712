package moire.monitor

import java.util.concurrent.locks.ReentrantLock
import moire.protocol.{Registers, StreamV1}
import moire.recording.Recording
import moire.stream._

/** A board on a serial port: the setup by registers (as `record` does), then its record stream, decoded as it comes.
  * The board's status register is read every second (its sticky overspeed and FIFO-overflow flags). When the port
  * fails or no bytes come for `staleSeconds`, the page shows the board as disconnected and the source tries again
  * every second (port open, id check, setup) until the board is back. A burst pauses the stream, runs
  * `record --burst`'s capture on the same port, then sets the stream up again.
  */
final class BoardSource(port: String, baud: Int, decimation: Option[Long], user: Scale, timeoutMs: Int = 500,
                        staleSeconds: Double = 2.0) extends Source {
  @volatile private var stop = false
  @volatile private var link: Option[ByteLink] = None
  private val lock = new ReentrantLock()
  private var thread: Thread = _
  private def opts(seconds: Double, out: String) = RecordOptions(port, seconds, out, baud, decimation, quiet = true, timeoutMs = timeoutMs)

  def start(live: Live): Unit = {
    thread = new Thread(() => run(live), "monitor-board")
    thread.setDaemon(true)
    thread.start()
  }

  private def pause(s: Double): Unit = { val until = System.nanoTime() + (s * 1e9).toLong; while (!stop && System.nanoTime() < until) Thread.sleep(20) }

  private def run(live: Live): Unit = while (!stop) {
    val l = try Some(SerialLink.open(port, baud)) catch { case e: StreamError => live.connection(up = false, e.getMessage); None }
    l match {
      case None => pause(1)
      case Some(l) =>
        link = Some(l)
        try {
          while (!stop) {
            lock.lock()
            val s = try {
              val c = new BoardClient(l, timeoutMs)
              val setup = Recorder.setup(c, opts(1, "monitor.csv"), hint = "")
              val depth = if (c.read(Registers.Version) >= 2) Some(c.read(Registers.BurstDepth)) else None
              Some((setup, depth, c.decoder.pending))
            } catch {
              case e: NoAnswer => live.connection(up = false, e.getMessage); None
              case e: StreamError if e.getMessage.contains("did not answer") || e.getMessage.contains("not a moire") =>
                live.connection(up = false, e.getMessage); None
            } finally lock.unlock()
            s match {
              case None => pause(1)
              case Some((setup, depth, pending)) =>
                val meta = Map("source" -> "board (monitor)", "adc" -> "AD9226", "decimation" -> setup.decimation.toString,
                  "adc_clock_hz" -> Recorder.num(setup.adcClockHz), "counts_per_period" -> setup.countsPerPeriod.toString, "port" -> port, "baud" -> baud.toString)
                live.setup(SourceSetup(setup.sampleRateHz, moire.signal.Adc(12, setup.adc),
                  user.copy(countsPerPeriod = user.countsPerPeriod.orElse(Some(setup.countsPerPeriod.toDouble))), meta, s"board on $port", depth))
                live.connection(up = true, "streaming")
                stream(l, live, setup, pending)
            }
          }
        } catch {
          case e: StreamError => live.connection(up = false, e.getMessage)
        } finally { link = None; l.close() }
        pause(1)
    }
  }

  /** Decodes until the stream stops for `staleSeconds` (returns: set up again), a burst took the port (returns), or `stop`. */
  private def stream(l: ByteLink, live: Live, setup: BoardSetup, pending: Array[Byte]): Unit = {
    val dec = new Decoder(setup.decimation)
    val buf = new Array[Byte](4096)
    var lastRaw = -1L; var unwrapped = 0L
    var lastBytes = System.nanoTime(); var lastStatus = 0L
    var rateAt = System.nanoTime(); var rateRecords = 0L; var rate = 0.0
    def take(fs: Seq[Frame]): Unit = {
      val rs = Vector.newBuilder[LiveRecord]
      fs.foreach {
        case f: RecordFrame => f.records.foreach { r =>
          if (lastRaw < 0) unwrapped = r.index
          else { val d = (r.index - lastRaw) & StreamV1.MaxU32; unwrapped += (if (d >= (1L << 31)) d - (1L << 32) else d) }
          lastRaw = r.index
          rs += LiveRecord.of(r, unwrapped)
        }
        case r: RegisterReply if r.addr == Registers.Status.addr => live.status(r.value)
        case _ =>
      }
      live.add(rs.result())
    }
    take(dec.feed(pending))
    while (!stop) {
      lock.lock()
      val n = try l.read(buf) finally lock.unlock()
      val now = System.nanoTime()
      if (n > 0) { take(dec.feed(buf, 0, n)); lastBytes = now }
      else if (now - lastBytes > staleSeconds * 1e9) {
        live.connection(up = false, f"no data from the board for $staleSeconds%.0f s: unplugged, reset or switched off?")
        return
      }
      if (now - lastStatus > 1e9) { lastStatus = now; l.write(Encoder.command(Command.read(Registers.Status.addr))) }
      if (now - rateAt > 1e9) { val st = dec.stats; rate = (st.records - rateRecords) / ((now - rateAt) / 1e9); rateRecords = st.records; rateAt = now }
      val st = dec.stats
      live.link(ujson.Obj("kind" -> "board", "port" -> port, "baud" -> baud, "decimation" -> setup.decimation.toDouble, "frames" -> st.frames.toDouble,
        "records" -> st.records.toDouble, "records_per_s" -> rate, "crc_errors" -> st.crcErrors.toDouble, "bad_headers" -> st.badHeaders.toDouble,
        "frame_gaps" -> st.seqGaps.toDouble, "missing_frames" -> st.seqMissing.toDouble, "index_gaps" -> st.indexGaps.toDouble,
        "missing_records" -> st.indexMissing.toDouble, "dropped_records" -> st.dropped.toDouble))
      if (burstTook) { burstTook = false; return }
    }
  }
  @volatile private var burstTook = false

  def burst(b: BurstOptions, file: os.Path): Recording = {
    val l = link.getOrElse(throw new MonitorError(s"$port: the board is not connected"))
    lock.lock()
    try {
      BurstRecorder.record(l, opts(b.waitSeconds, file.toString), b, _ => (), _ => ())
      burstTook = true
      Recording.read(file)
    } catch {
      case e: StreamError => burstTook = true; throw new MonitorError(e.getMessage)
    } finally lock.unlock()
  }

  def close(): Unit = { stop = true; if (thread != null) thread.join(3000) }
}
