package moire.files

import java.nio.file.{Files, LinkOption}

/** The temporary files and folders moire is writing: a JVM shutdown hook (Ctrl-C, SIGTERM) removes them (after
  * stoppable work, [[Interrupts]], has written what it has), and
  * renames that put finished outputs in place run under [[lock]], so an interrupt falls before or after them,
  * never between them.
  */
object Temporaries {
  private val live = scala.collection.mutable.LinkedHashSet.empty[os.Path]
  private var closing = false
  /** Held while finished outputs are renamed into place (and by the shutdown hook). */
  val lock = new Object

  Runtime.getRuntime.addShutdownHook(new Thread(() => {
    // a recording stopped by Ctrl-C writes what arrived first (its renames need the lock, and `closing` unset)
    Interrupts.shutdown()
    lock.synchronized {
      closing = true
      live.foreach(remove)
      live.clear()
    }
  }, "moire-temporaries"))

  /** Nothing but this object's start: its shutdown hook is in place. */
  def watch(): Unit = ()

  def add(p: os.Path): Unit = lock.synchronized(live += p)
  def done(p: os.Path): Unit = lock.synchronized(live -= p)

  /** Runs `body` (renames) under the lock, unless the JVM is shutting down: then nothing is renamed. */
  def commit[T](body: => T): T = lock.synchronized {
    if (closing) throw new FileError("interrupted; nothing was changed")
    body
  }

  private def remove(p: os.Path): Unit =
    try {
      if (Files.isDirectory(p.toNIO, LinkOption.NOFOLLOW_LINKS)) os.remove.all(p) else Files.deleteIfExists(p.toNIO)
    } catch { case _: java.io.IOException => () }
}
