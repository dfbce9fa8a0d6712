package moire.explain

import me.tongfei.progressbar.ConsoleProgressBarConsumer

/** Progress of a batch on stderr. On a terminal: one line, redrawn in place, with the files done and each running
  * file's stage and how far it is (`explain: 1 of 4 done; a.csv: effects, round 2 40 %; b.csv: default fit 0 %; 12 s`;
  * `finishing` after the fit: the RTL check, plots, JSON).
  * Elsewhere (a log, a pipe): each file's own plain lines, which name it. Messages and the text reports pass
  * through here, so that none lands inside the redrawn line.
  */
final class BatchProgress(total: Int, terminal: Boolean = moire.progress.Bar.terminal) {
  private final class Running(val name: String) { var stage = "reading"; var steps = 0; var at = 0 }
  private val running = scala.collection.mutable.LinkedHashMap.empty[Int, Running]
  private var done = 0
  private val t0 = System.nanoTime()
  private var drawn = 0L
  private lazy val console = new ConsoleProgressBarConsumer(System.err)

  /** File `i` starts: its progress (on a terminal, a part of the one line; elsewhere its own lines). */
  def start(i: Int, file: os.Path): Progress =
    if (!terminal) Progress.bar(moire.files.Stem.of(file))
    else {
      synchronized { running(i) = new Running(file.last); draw(force = true) }
      new Progress {
        def phase(name: String, steps: Int): Unit = update(i, force = true) { r => r.stage = name; r.steps = steps; r.at = 0 }
        def step(k: Int): Unit = update(i, force = false)(r => r.at += k)
        override def close(): Unit = update(i, force = true) { r => r.stage = "finishing"; r.steps = 0 }
      }
    }

  /** File `i` is done (its report written or its error found). */
  def finish(i: Int): Unit = synchronized {
    running.remove(i); done += 1
    if (terminal) draw(force = true)
  }

  /** A whole line on stderr. */
  def say(line: String): Unit = synchronized { clear(); System.err.println(line); if (terminal) draw(force = true) }

  /** A text report on stdout. */
  def report(text: String): Unit = synchronized { clear(); print(text); Console.out.flush(); if (terminal) draw(force = true) }

  /** The batch is over: the line's last state stays on the terminal. */
  def close(): Unit = synchronized { if (terminal) { draw(force = true); System.err.println() } }

  /** The line: files done, each running file's stage and how far, seconds since the start. */
  def status: String = synchronized {
    val files = running.values.map(r => s"; ${r.name}: ${r.stage}" + (if (r.steps > 0) s" ${100L * math.min(r.at, r.steps) / r.steps} %" else ""))
    f"explain: $done of $total done${files.mkString}; ${(System.nanoTime() - t0) / 1e9}%.0f s"
  }

  private def update(i: Int, force: Boolean)(f: Running => Unit): Unit = synchronized {
    running.get(i).foreach { r => f(r); draw(force) }
  }

  /** Redraws the line (at most five times a second unless forced), cut to the terminal's width. */
  private def draw(force: Boolean): Unit = {
    val now = System.nanoTime()
    if (force || now - drawn > 200000000L) {
      drawn = now
      System.err.print("\r" + status.take(console.getMaxRenderedLength - 1) + "\u001b[K")
      System.err.flush()
    }
  }

  private def clear(): Unit = if (terminal) { System.err.print("\r\u001b[K"); System.err.flush() }
}
