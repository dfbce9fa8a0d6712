package moire.files

/** Ctrl-C (SIGINT) or SIGTERM while work that can end early runs (a recording): the shutdown hook asks that work to
  * stop and waits until the command has written what it has and said so; only then are temporaries removed and the
  * JVM ends. Work that cannot end early (a fit, a build) is not waited for: it ends at once, as before.
  */
object Interrupts {
  /** How long the hook waits for stopped work to write its output (a day's recording takes seconds to write). */
  val WaitMs = 60000L

  /** Asked to stop: the work checks `requested` and ends early, keeping what it has. */
  final class Stop {
    @volatile private[Interrupts] var asked = false
    def requested: Boolean = asked
  }

  private val stops = scala.collection.mutable.LinkedHashSet.empty[Stop]
  /** Commands and stoppable parts running: the hook waits until none is. */
  private var busy = 0
  private var endedEarly = false

  /** Runs `body`, which ends early once its Stop is `requested` (Ctrl-C) and keeps what it has. */
  def stoppable[T](body: Stop => T): T = {
    Temporaries.watch() // the hook that calls `shutdown` is in place
    val s = new Stop
    synchronized { stops += s; busy += 1 }
    try body(s) finally synchronized {
      stops -= s; busy -= 1
      // ended by the JVM's end before the hook asked (a port closed under it): the command's last line is still due
      if (shuttingDown) endedEarly = true
      notifyAll()
    }
  }

  /** A whole command (the CLI): stopped work is waited for until the command has said its last line, too. */
  def command[T](body: => T): T = {
    synchronized(busy += 1)
    try body finally synchronized { busy -= 1; notifyAll() }
  }

  /** The JVM is ending (Ctrl-C, SIGTERM): other hooks may be closing what the work uses (jSerialComm closes its
    * ports), before or after this one asked the work to stop. The JVM tells it only by refusing a new hook.
    */
  def shuttingDown: Boolean = {
    val t = new Thread(() => ())
    try { Runtime.getRuntime.addShutdownHook(t); Runtime.getRuntime.removeShutdownHook(t); false }
    catch { case _: IllegalStateException => true }
  }

  /** What the hook does first: asks every stoppable piece of work to stop. True when there was one. */
  def interrupt(): Boolean = synchronized { stops.foreach(_.asked = true); stops.nonEmpty }

  /** The shutdown hook's part: interrupt, then wait (at most `WaitMs`) until the work and its command are done. */
  private[files] def shutdown(): Unit = if (interrupt() || synchronized(endedEarly)) synchronized {
    val until = System.currentTimeMillis() + WaitMs
    while (busy > 0 && System.currentTimeMillis() < until) wait(math.max(1L, until - System.currentTimeMillis()))
  }
}
