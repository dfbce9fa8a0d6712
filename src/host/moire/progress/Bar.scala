package moire.progress

import me.tongfei.progressbar.{ConsoleProgressBarConsumer, ProgressBar, ProgressBarBuilder}

/** Progress of one long stage on stderr: a bar on a terminal; elsewhere (a log, a pipe, CI) no escape
  * codes but one plain line at the start, at every tenth of the way and at the end: what, how far,
  * elapsed seconds. `plainGapS`: the tenths' lines at least that many seconds apart (a 4 s recording wrote one
  * every 0.4 s into a log); the start and the end are always said.
  */
final class Bar(task: String, max: Long, unit: String = "", unitSize: Long = 1, terminal: Boolean = Bar.terminal,
                plainGapS: Double = 0) {
  private val t0 = System.nanoTime()
  private var at = 0L; private var tenth = 0L; private var extra = ""; private var closed = false; private var saidAt = t0
  private val bar: Option[ProgressBar] =
    if (terminal) Some(new ProgressBarBuilder().setTaskName(task).setInitialMax(max).setUnit(unit, unitSize)
      .setConsumer(new ConsoleProgressBarConsumer(System.err)).build())
    else { line(); None }

  def getMax: Long = max
  def position: Long = at
  def stepTo(n: Long): Unit = { at = n; bar.fold(plain())(_.stepTo(n)) }
  def step(): Unit = stepTo(at + 1)
  def setExtraMessage(m: String): Unit = { extra = m; bar.foreach(_.setExtraMessage(m)) }
  def close(): Unit = if (!closed) { closed = true; bar.fold(line())(_.close()) }

  private def plain(): Unit = {
    val t = if (max > 0) at * 10 / max else 0
    if (t > tenth && System.nanoTime() - saidAt >= plainGapS * 1e9) { tenth = t; line() }
  }
  private def line(): Unit = {
    saidAt = System.nanoTime()
    val s = (saidAt - t0) / 1e9
    val how = if (unitSize > 1) f"${at.toDouble / unitSize}%.1f/${max.toDouble / unitSize}%.1f$unit" else s"$at/$max$unit"
    System.err.println(f"$task: $how, $s%.1f s elapsed$extra")
  }
}

object Bar {
  /** A long capture's plain lines (a recording of hours, a burst read out for minutes): at most one in this many seconds. */
  val CaptureGapS = 10.0

  /** A bar draws only when stderr's process has a terminal. */
  def terminal: Boolean = System.console() != null
}
