package moire.timing

/** Follows a nextpnr log as it is written: the stage for the progress line, and router2 giving up.
  *
  * router2 negotiates congestion: its overuse (wires wanted by more nets than they carry) falls
  * iteration by iteration to 0. On a congested placement it can turn and climb without end (the
  * ULX3S compensated top on b128437: 490 at iteration 43, 1,999 at 71, still rising after 45 min).
  * The watch calls it diverging by [[moire.board.tools.Router2GiveUp]] (the rule the ULX3S build.sh uses too).
  */
final class NextpnrWatch extends ToolRun.Watch {
  private val Iter = """.*iter=(\d+) wires=\d+ overused=\d+ overuse=(\d+).*""".r
  private val Router1 = """Info:\s+(\d+) \|.*\|\s*(\d+)\|.*""".r
  private var best = Long.MaxValue
  private var bestIter = 0
  private var stage = "placing"
  private var gaveUp: Option[String] = None

  def line(l: String): Unit = l match {
    case Iter(i, u) =>
      val (it, over) = (i.toInt, u.toLong)
      if (over < best) { best = over; bestIter = it }
      stage = s"routing (router2), iteration $it, overuse $over"
      if (gaveUp.isEmpty && moire.board.tools.Router2GiveUp(best, over))
        gaveUp = Some(s"router2 did not converge: overuse $best at iteration $bestIter, $over at iteration $it")
    case Router1(_, left) => stage = s"routing (router1), $left arcs left"
    case _ if l.contains("Running router2") || l.contains("Routing..") => stage = "routing"
    case _ if l.contains("Running simulated annealing placer") => stage = "placing (refinement)"
    case _ =>
  }
  def status: Option[String] = Some(stage)
  def abort: Option[String] = gaveUp
}
