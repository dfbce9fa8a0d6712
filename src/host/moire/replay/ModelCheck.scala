package moire.replay

import moire.signal.Adc
import moire.subdiv.{SubdivCycle, SubdivModel, SubdivSample}

/** How many rows were compared with the bit-accurate model, and the first that differs. */
final case class CheckResult(rows: Long, windows: Int, firstMismatch: Option[(Int, String)]) {
  def ok: Boolean = firstMismatch.isEmpty
  def text: String = firstMismatch match {
    case None => s"model check: all $rows checked rows equal the bit-accurate model (first rows clock by clock${if (windows > 0) s", plus $windows windows" else ""})"
    case Some((r, what)) => s"model check: row $r differs from the bit-accurate model: $what"
  }
}

/** Compares replay outputs with the Scala model: the first `head` rows clock by clock (position, phase, flags,
  * A/B/Z, overspeed), then `windows` windows of `window` rows spread over the rest, the subdivider's period
  * counter seeded from the row before each window (position, phase and flags only; A/B/Z need the whole history).
  */
object ModelCheck {
  def run(d: ReplayDesign, pins: PinStream, out: ReplayOutput, head: Int = 100000, windows: Int = 20, window: Int = 5000): CheckResult = {
    val n = pins.length
    val k = math.min(n, head)
    var checked = 0L
    val m = d.model()
    val l = d.latency
    var t = 0
    // Cycle t: the pins of sample t go in; the outputs show row t - latency.
    while (t < k + l) {
      val c = if (t < n) m.clock(true, pins.sin(t), pins.cos(t), pins.otrS(t), pins.otrC(t)) else m.clock(false, 0, 0, false, false)
      if (t >= l) {
        val r = t - l
        diff(c, out, r, d, clockLevel = true).foreach(w => return CheckResult(checked, 0, Some(r -> w)))
        checked += 1
      }
      t += 1
    }
    var done = 0
    d.subdivModel.filter(_ => n > k + window).foreach { p =>
      val adc = Adc(p.inputBits, d.format)
      val starts = (0 until windows).map(w => k + ((n - k - window).toLong * w / math.max(1, windows - 1)).toInt).distinct
      for (s <- starts) {
        val sm = new SubdivModel(p)
        var j = s - 1
        while (j >= 0 && !out.flag(j, Replay.Present)) j -= 1
        if (s > 0) sm.seedCounter(j >= 0, if (j >= 0) out.phase(j) else 0L, out.position(s - 1) >> p.countBits)
        var r = s
        while (r < s + window) {
          val e = sm.process(SubdivSample(adc.fromPins(pins.sin(r)), adc.fromPins(pins.cos(r)), pins.otrS(r), pins.otrC(r)))
          val c = SubdivCycle(true, e, false, false, false, 0, false, false, false, false)
          diff(c, out, r, d, clockLevel = false).foreach(w => return CheckResult(checked, done, Some(r -> w)))
          checked += 1; r += 1
        }
        done += 1
      }
    }
    CheckResult(checked, done, None)
  }

  private def diff(c: SubdivCycle, out: ReplayOutput, r: Int, d: ReplayDesign, clockLevel: Boolean): Option[String] = {
    def b(bit: Int) = out.flag(r, bit)
    val got = Seq("valid" -> b(Replay.Valid), "position" -> out.position(r), "phase" -> out.phase(r), "present" -> b(Replay.Present),
      "over_range" -> b(Replay.OverRange), "step_fault" -> b(Replay.StepFault))
    val exp = Seq("valid" -> c.valid, "position" -> c.out.position, "phase" -> c.out.phase, "present" -> c.out.present,
      "over_range" -> c.out.overRange, "step_fault" -> c.out.stepFault)
    val g2 = if (clockLevel) got ++ Seq("a" -> b(Replay.A), "b" -> b(Replay.B), "z" -> b(Replay.Z), "overspeed" -> b(Replay.Overspeed)) else got
    val e2 = if (clockLevel) exp ++ Seq("a" -> c.a, "b" -> c.b, "z" -> c.z, "overspeed" -> c.overspeed) else exp
    g2.zip(e2).collectFirst { case ((name, gv), (_, ev)) if gv != ev => s"$name: RTL $gv, model $ev" }
  }
}
