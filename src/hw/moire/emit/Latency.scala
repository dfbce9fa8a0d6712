package moire.emit

/** A module with a fixed pipeline depth: results `latency` clocks after their input. The design
  * registry (moire.designs) reads it from the elaborated module.
  */
trait Latency {
  def latency: Int
}
