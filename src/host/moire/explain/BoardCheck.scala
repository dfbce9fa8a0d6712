package moire.explain

import moire.replay._

import moire.recording.Recording

/** How a recording's board outputs differ from what the RTL computes from the recorded ADC codes. */
final case class Comparison(pattern: String, first: Option[Long], summary: String, params: Map[String, Double])

/** explain's board check: replays the recorded codes and compares the `position` column (and present,
  * over_range, step_fault when recorded) with the RTL, sample by sample; classifies the position difference
  * as none, constant offset, sporadic bit errors, drift, step or irregular. The finding's effect is
  * `board_position_<pattern>` (or `board_flags_mismatch`); it has no BIC (delta_bic null).
  */
object BoardCheck {
  /** Position differences d = recorded - rtl (wrapped to the position width). */
  def classify(recorded: Array[Long], rtl: Array[Long], positionWidth: Int, counts: Int, index: Int => Long): Comparison = {
    val n = recorded.length
    val sh = 64 - positionWidth
    def wrap(v: Long) = (v << sh) >> sh
    val d = Array.tabulate(n)(i => wrap(recorded(i) - rtl(i)))
    val firstAt = d.indexWhere(_ != 0)
    if (firstAt < 0) return Comparison("none", None, s"the board position equals the RTL on all $n samples", Map("samples" -> n))
    val first = index(firstAt)
    val base = Map("samples" -> n.toDouble, "first_mismatch_sample" -> first.toDouble, "mismatching_samples" -> d.count(_ != 0).toDouble)
    val mode = { // the most common difference (longest run of a sorted copy)
      val sorted = d.clone(); java.util.Arrays.sort(sorted)
      var best = sorted(0); var bestLen = 0; var i = 0
      while (i < n) { var j = i; while (j < n && sorted(j) == sorted(i)) j += 1; if (j - i > bestLen) { best = sorted(i); bestLen = j - i }; i = j }
      best
    }
    val dev = (0 until n).filter(i => d(i) != mode)
    val periodsNote = if (mode != 0 && mode % counts == 0) s" = ${mode / counts} whole periods of M = $counts: likely the board's period count before the recording started (the RTL starts from 0), not an error"
      else if (mode != 0) s", not a whole number of periods of M = $counts" else ""
    if (dev.isEmpty)
      return Comparison("constant_offset", Some(first), s"the board position is the RTL's plus $mode counts on every sample$periodsNote",
        base ++ Map("offset_counts" -> mode.toDouble, "offset_periods" -> mode.toDouble / counts))
    val mask = if (positionWidth >= 64) -1L else (1L << positionWidth) - 1
    val isolated = dev.count(i => (i == 0 || d(i - 1) == mode) && (i == n - 1 || d(i + 1) == mode))
    if (dev.size <= math.max(1, n / 20) && isolated >= dev.size * 0.8) {
      val flips = Array.fill(positionWidth)(0)
      dev.foreach { i => val x = (recorded(i) ^ (rtl(i) + mode)) & mask; for (b <- 0 until positionWidth) if (((x >> b) & 1) != 0) flips(b) += 1 }
      val bits = flips.indices.filter(flips(_) > 0)
      val firstDev = index(dev.head)
      val off = if (mode != 0) s" (on top of a constant offset of $mode counts$periodsNote)" else ""
      return Comparison("sporadic_bit_errors", Some(firstDev),
        s"${dev.size} of $n samples differ in isolated samples$off, first at sample $firstDev; flipped bits: " +
          bits.map(b => s"$b (${flips(b)}x)").mkString(", "),
        base ++ Map("first_mismatch_sample" -> firstDev.toDouble, "error_samples" -> dev.size.toDouble, "offset_counts" -> mode.toDouble) ++
          bits.map(b => s"bit_${b}_flips" -> flips(b).toDouble))
    }
    // least-squares line through d
    val mx = (n - 1) / 2.0; val my = d.map(_.toDouble).sum / n
    var sxy = 0.0; var sxx = 0.0; var syy = 0.0; var i = 0
    while (i < n) { val x = i - mx; val y = d(i) - my; sxy += x * y; sxx += x * x; syy += y * y; i += 1 }
    val slope = sxy / sxx; val r2 = if (syy > 0) sxy * sxy / (sxx * syy) else 0.0
    val changes = (1 until n).count(i => d(i) != d(i - 1))
    if (r2 > 0.9 && changes >= 3)
      return Comparison("drift", Some(first), f"the difference board - RTL grows steadily: $slope%.4g counts per sample " +
        f"(${d.last - d(firstAt)} counts from sample $first to the end, R^2 $r2%.3f), first mismatch at sample $first",
        base ++ Map("slope_counts_per_sample" -> slope, "r_squared" -> r2, "final_difference_counts" -> d.last.toDouble))
    if (changes <= 10) {
      val at = (1 until n).filter(i => d(i) != d(i - 1))
      return Comparison("step", Some(first), s"the difference board - RTL changes in $changes steps (${at.take(5).map(j => s"${d(j - 1)} -> ${d(j)} at sample ${index(j)}").mkString(", ")}): counts lost or gained",
        base ++ Map("steps" -> changes.toDouble, "final_difference_counts" -> d.last.toDouble))
    }
    Comparison("irregular", Some(first), s"the board position differs from the RTL on ${d.count(_ != 0)} of $n samples without a simple pattern, first at sample $first",
      base ++ Map("slope_counts_per_sample" -> slope, "r_squared" -> r2))
  }

  /** Mismatch counts of the recorded flag columns against the RTL. */
  def flagMismatches(rec: Recording, o: ReplayOutput): Map[String, Double] =
    Seq("present" -> Replay.Present, "over_range" -> Replay.OverRange, "step_fault" -> Replay.StepFault).collect {
      case (c, bit) if rec.extra.contains(c) =>
        val col = rec.extra(c)
        s"${c}_mismatches" -> (0 until o.length).count(i => (col(i) != 0) != o.flag(i, bit)).toDouble
    }.toMap

  /** The check on one recording with a `position` column: a finding when the board differs, notes either way. */
  def run(file: String, rec: Recording, subdivOpts: Seq[String], log: String => Unit): (Option[Finding], Seq[String]) = {
    // subdivider options given for a recording without the board's outputs compare nothing: said, not dropped
    val pos = rec.extra.getOrElse("position", return (None,
      if (subdivOpts.isEmpty) Nil else Seq("board outputs not compared: --subdiv was given, but the recording has no position column (the board's outputs)")))
    // the board's position counts as its metadata says: an RTL of other counts would differ everywhere
    val given = subdivOpts.indexOf("--counts") match { case i if i >= 0 => subdivOpts.lift(i + 1); case _ => None }
    for (u <- given; v <- rec.meta.get("counts_per_period") if moire.numbers.Decimal.double(u) != moire.numbers.Decimal.double(v))
      return (None, Seq(s"board outputs not compared: --subdiv gives --counts $u, but the recording's counts_per_period is $v " +
        "(the board counted so); leave --counts out and the metadata gives it"))
    try {
      val d = ReplayDesign("subdiv", ReplayCmd.config(subdivOpts, rec.meta))
      ReplayCmd.matchAdc(file, rec, d)
      val pins = ReplayCmd.pins(file, rec)
      val (o, check) = ReplayCmd.replay(d, pins, quiet = true, log)
      if (!check.ok) return (None, Seq(s"board outputs not compared: the RTL replay disagrees with the model (${check.text})"))
      val idx = rec.extra.get("sample_index").map(a => (i: Int) => a(i).toLong).getOrElse((i: Int) => i.toLong)
      val c = classify(pos.map(_.toLong), o.position, d.out.positionWidth, d.out.counts, idx)
      val flags = flagMismatches(rec, o)
      val flagText = flags.filter(_._2 > 0).map { case (k, v) => s"${k.stripSuffix("_mismatches")} differs on ${v.toLong} samples" }
      val note = s"board outputs compared with the RTL (${d.describe}): ${c.summary}" + flagText.map("; " + _).mkString
      if (c.pattern == "none" && flagText.isEmpty) (None, Seq(note))
      else (Some(Finding(if (c.pattern == "none") "board_flags_mismatch" else s"board_position_${c.pattern}", "position",
        c.summary + flagText.map("; " + _).mkString,
        c.params ++ flags, Map.empty, Double.NaN, Double.NaN, Double.NaN, c.first.map(f => s"from sample $f").getOrElse("flags"))), Seq(note))
    } catch {
      case e: moire.MoireError => (None, Seq(s"board outputs not compared: ${e.getMessage}"))
    }
  }
}
