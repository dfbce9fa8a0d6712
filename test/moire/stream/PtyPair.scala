package moire.stream

import moire.protocol.{AdaptRegisters, Registers}
import java.io.{FileInputStream, FileOutputStream, IOException}
import java.util.concurrent.ConcurrentLinkedQueue
import scala.collection.mutable
import scala.jdk.CollectionConverters._

/** A pseudo-terminal pair made by socat, for testing host tools without a board.
  *
  * API (reusable by other tests):
  * {{{
  * PtyPair { pty =>                      // cancels the test when socat is missing; closes everything after
  *   pty.host                            // path the tool under test opens, e.g. Recorder.run(RecordOptions(pty.host.toString, ...))
  *   pty.feed(bytes, bytesPerSecond)     // the board end writes bytes at a UART-like pace (blocks until sent)
  *   pty.boardIn / pty.boardOut          // raw streams of the board end
  *   val board = new FakeBoard(pty, FakeBoard.registers())  // answers register commands from a Scala map
  *   board.stream(plan, bytesPerSecond)  // streams record frames (seq from the board's counter) in the background
  * }}}
  * To push the bytes of a simulated board into the recorder: run the recorder in a Future (or thread)
  * with `listenOnly = true` and the setup by hand, and `pty.feed(bytes, rate)` on the test thread.
  * The recording starts after the first record frame whose records are D apart (that frame itself is
  * not recorded) and lasts `seconds` of wall time. Without a pty, `Recorder.record(new MemoryLink(bytes), ...)`
  * does the same from memory; to check framing alone, `new Decoder(d).feed(bytes)` and its `stats`.
  */
final class PtyPair private (val dir: os.Path, proc: Process) extends AutoCloseable {
  /** The end the program under test opens (a symlink to /dev/pts/N). */
  val host: os.Path = dir / "host"
  /** The end the test (the fake board) uses. */
  val board: os.Path = dir / "board"
  lazy val boardIn: FileInputStream = new FileInputStream(board.toIO)
  lazy val boardOut: FileOutputStream = new FileOutputStream(board.toIO)
  @volatile private var closed = false
  def isClosed: Boolean = closed

  /** Writes `bytes` from the board end, `chunk` bytes at a time, at about `bytesPerSecond` (baud / 10 for 8N1). */
  def feed(bytes: Array[Byte], bytesPerSecond: Int = 11520, chunk: Int = 64): Unit = {
    val t0 = System.nanoTime(); var at = 0
    while (at < bytes.length && !closed) {
      val n = math.min(chunk, bytes.length - at)
      boardOut.write(bytes, at, n); boardOut.flush(); at += n
      PtyPair.sleepUntil(t0 + (at * 1e9 / bytesPerSecond).toLong)
    }
  }

  def close(): Unit = if (!closed) {
    closed = true
    proc.destroy()
    if (!proc.waitFor(5, java.util.concurrent.TimeUnit.SECONDS)) proc.destroyForcibly()
    try boardIn.close() catch { case _: IOException => }
    try boardOut.close() catch { case _: IOException => }
    os.remove.all(dir)
  }
}

object PtyPair {
  /** socat on the PATH, if any. */
  lazy val socat: Option[String] = sys.env.getOrElse("PATH", "").split(java.io.File.pathSeparator).iterator
    .map(d => new java.io.File(d, "socat")).find(f => f.isFile && f.canExecute).map(_.getPath)

  def sleepUntil(t: Long): Unit = { val d = t - System.nanoTime(); if (d > 0) Thread.sleep(d / 1000000, (d % 1000000).toInt) }

  /** Starts socat and waits (5 s at most) until both links exist. */
  def open(): PtyPair = {
    val exe = socat.getOrElse(throw new IllegalStateException("socat is not installed"))
    val dir = os.temp.dir(prefix = "moire-pty")
    val log = (dir / "socat.log").toIO
    val proc = new ProcessBuilder(exe, "-d", "-d", s"pty,raw,echo=0,link=${dir / "host"}", s"pty,raw,echo=0,link=${dir / "board"}")
      .redirectErrorStream(true).redirectOutput(log).start()
    val until = System.nanoTime() + 5000000000L
    while (!(os.exists(dir / "host") && os.exists(dir / "board")) && System.nanoTime() < until && proc.isAlive) Thread.sleep(10)
    if (!(os.exists(dir / "host") && os.exists(dir / "board"))) {
      proc.destroyForcibly(); val msg = scala.util.Try(os.read(os.Path(log))).getOrElse("")
      os.remove.all(dir)
      throw new IllegalStateException(s"socat made no pty pair in 5 s: $msg")
    }
    new PtyPair(dir, proc)
  }

  /** Runs `body` with a fresh pair and closes it after; cancels the test when socat is missing. */
  def apply[T](body: PtyPair => T): T = {
    if (socat.isEmpty) org.scalatest.Assertions.cancel("socat is not installed (apt-get install socat): pty tests skipped")
    val p = open()
    try body(p) finally p.close()
  }
}

/** One record frame the fake board is to stream.
  * @param skipSeq  seq numbers to skip before this frame (a frame lost on the way)
  * @param flip     byte offsets in the frame to XOR with 0x01 (damage on the wire)
  */
final case class Planned(records: IndexedSeq[Record], dropped: Int = 0, skipSeq: Int = 0, flip: Seq[Int] = Nil)

/** A frame the fake board put on the wire. */
final case class Sent(frame: RecordFrame, wire: Array[Byte], damaged: Boolean)

/** A board imitation on the board end of a [[PtyPair]].
  * Commands are decoded with [[CommandDecoder]] and answered from a register map: writes change writable
  * registers ([[Registers.writable]], the harmonic window only up to `harmonicSlots`), others reply unchanged;
  * bad commands count in cmd_errors. `stream` sends record frames; seq is shared with the replies.
  * Several boards may follow one another on a pair (close one before making the next).
  * `adaptTable`: the adaptive corrector's table (adapt_table_data shows the entry at adapt_table_index; adapt_control
  * and the presets restore it and the learned values as the board does, unless `presets` is false: a bitstream from
  * before them); empty: none.
  * `streamWhen`: the stream starts (if `stream` was called) after the reply to the first command it
  * accepts; None: at once.
  */
final class FakeBoard(pty: PtyPair, initial: Map[Int, Long], harmonicSlots: Int = 0,
                      streamWhen: Option[Command => Boolean] = None, adaptTable: IndexedSeq[Long] = IndexedSeq.empty,
                      presets: Boolean = true) extends AutoCloseable {
  private val regs = mutable.Map(initial.toSeq: _*)
  private val table = mutable.ArrayBuffer.from(adaptTable)
  /** The corrector's table now (changed by preset pair writes). */
  def adaptTableNow: Seq[Long] = synchronized(table.toSeq)
  private var seq = 0
  private val cmdDecoder = new CommandDecoder
  private val cmds = new ConcurrentLinkedQueue[Command]
  private val sentLog = new ConcurrentLinkedQueue[Sent]
  @volatile private var go = streamWhen.isEmpty
  @volatile private var stopped = false
  private var plan: Option[(Iterator[Planned], Int)] = None

  def registers: Map[Int, Long] = synchronized(regs.toMap)
  def commands: Seq[Command] = cmds.asScala.toSeq
  def sent: Seq[Sent] = sentLog.asScala.toSeq

  private def writable(a: Int): Boolean =
    if (a == AdaptRegisters.TableIndex.addr) adaptTable.nonEmpty
    else if (a >= AdaptRegisters.Control.addr && a <= AdaptRegisters.PresetOdd.addr) adaptTable.nonEmpty && presets
    else if (a >= Registers.HarmonicBase) a < Registers.HarmonicBase + 4 * harmonicSlots && (a & 3) != 3 else Registers.writable(a)

  /** adapt_control as the corrected board does it: hold kept, with hold the load and table-pair strobes. */
  private def preset(v: Long): Unit = {
    import AdaptRegisters._
    def on(b: Int) = ((v >> b) & 1) == 1
    regs(Control.addr) = v & 1
    if (on(AdaptBit.Hold) && on(AdaptBit.TableWrite)) {
      val k = (regs.getOrElse(TableIndex.addr, 0L) / 2).toInt
      table(2 * k) = regs.getOrElse(PresetEven.addr, 0L); table(2 * k + 1) = regs.getOrElse(PresetOdd.addr, 0L)
    }
    if (on(AdaptBit.Hold) && on(AdaptBit.Load)) for ((r, pr) <- AdaptRegisters.presets) regs(r.addr) = regs.getOrElse(pr.addr, 0L)
  }

  private def send(bytes: Array[Byte]): Unit = synchronized { pty.boardOut.write(bytes); pty.boardOut.flush() }

  private val reader = new Thread(() => {
    val buf = new Array[Byte](256)
    // polls (available) instead of blocking in read, so that close() ends it and a later board on the same pair gets every byte
    try while (!stopped) {
      val n = if (pty.boardIn.available() > 0) pty.boardIn.read(buf) else { Thread.sleep(1); 0 }
      if (n < 0) stopped = true
      else if (n > 0) cmdDecoder.feed(java.util.Arrays.copyOf(buf, n)).foreach { c =>
        cmds.add(c)
        synchronized {
          regs(Registers.CmdErrors.addr) = cmdDecoder.errors
          if (c.write && writable(c.addr)) regs(c.addr) = if (c.addr == AdaptRegisters.TableIndex.addr) c.value % adaptTable.size else c.value
          if (c.write && c.addr == AdaptRegisters.Control.addr && writable(c.addr)) preset(c.value)
          if (adaptTable.nonEmpty) regs(AdaptRegisters.TableData.addr) = table(regs.getOrElse(AdaptRegisters.TableIndex.addr, 0L).toInt)
          val shown = if (AdaptRegisters.writeOnly.exists(_.addr == c.addr)) 0L else regs.getOrElse(c.addr, 0L)
          send(Encoder.frame(RegisterReply(seq, c.addr, shown)))
          seq = (seq + 1) & 0xFFFF
        }
        if (!go && streamWhen.exists(_(c))) go = true
      }
    } catch { case _: IOException | _: InterruptedException => }
  }, "fake-board-reader")
  reader.setDaemon(true); reader.start()

  private var streamer: Option[Thread] = None

  /** Streams the planned frames at `bytesPerSecond` from when `streamWhen` accepts a command. */
  def stream(frames: Iterator[Planned], bytesPerSecond: Int = 11520): Unit = {
    val t = new Thread(() => {
      try {
        while (!go && !stopped) Thread.sleep(2)
        val t0 = System.nanoTime(); var bytes = 0L
        while (frames.hasNext && !stopped) {
          val p = frames.next()
          val wire = synchronized {
            seq = (seq + p.skipSeq) & 0xFFFF
            val f = RecordFrame(seq, p.dropped, p.records)
            val w = Encoder.frame(f)
            p.flip.foreach(i => w(i) = (w(i) ^ 1).toByte)
            send(w); seq = (seq + 1) & 0xFFFF
            sentLog.add(Sent(f, w, p.flip.nonEmpty))
            w
          }
          bytes += wire.length
          PtyPair.sleepUntil(t0 + (bytes * 1e9 / bytesPerSecond).toLong)
        }
      } catch { case _: IOException | _: InterruptedException => }
    }, "fake-board-stream")
    t.setDaemon(true); t.start(); streamer = Some(t)
  }

  def close(): Unit = {
    stopped = true
    streamer.foreach(_.join(2000))
    reader.join(2000)
  }
}

object FakeBoard {
  /** A register map as a DE2-115 build might have it. */
  def registers(decimation: Long = 80000, adcClockHz: Long = 40000000, countsPerPeriod: Long = 1024, adcFormat: Long = 0,
                frameRecords: Long = 8): Map[Int, Long] = Map(
    Registers.Id.addr -> Registers.IdValue, Registers.Version.addr -> 1L, Registers.Status.addr -> 0x100L,
    Registers.Control.addr -> 1L, Registers.Decimation.addr -> decimation, Registers.AdcClockHz.addr -> adcClockHz,
    Registers.FrameRecords.addr -> frameRecords, Registers.CountsPerPeriod.addr -> countsPerPeriod,
    Registers.AdcFormat.addr -> adcFormat, Registers.Position.addr -> 0xFFFFFFF0L)
}
