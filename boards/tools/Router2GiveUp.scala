package moire.board.tools

/** When nextpnr's router2 is given up for router1: its overuse (wires wanted by more nets than they
  * carry) at least `factor` times its best so far and `margin` wires above it. Converging routes here
  * wobble by a few wires near the end (at most 2 -> 15); a congested placement climbs into the
  * thousands. One rule for `timing` (moire.timing.NextpnrWatch) and the ULX3S build.sh (its awk).
  */
object Router2GiveUp {
  val factor = 2
  val margin = 100
  def apply(best: Long, now: Long): Boolean = now >= factor * best && now >= best + margin
}
