package moire.monitor

import moire.recording.Recording
import moire.stream.BurstOptions

/** Where the monitor's records come from: a board on a serial port, a recording replayed, the simulated board.
  * `start` runs the source on its own thread until `close`; it writes into the [[Live]] it was given.
  */
trait Source extends AutoCloseable {
  def start(live: Live): Unit
  /** Captures a burst (blocking) into `file`; the recording written. Errors are [[MonitorError]]s. */
  def burst(b: BurstOptions, file: os.Path): Recording
  /** Why this source cannot capture the burst `b` at all (a trigger it has no hardware for), said before it starts. */
  def refuses(b: BurstOptions): Option[String] = None
}

/** A bad request or a failed operation of the monitor: one line for the user or the page. */
final class MonitorError(msg: String) extends moire.MoireError(msg)
