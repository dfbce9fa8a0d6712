package moire.timing

/** Cells after `synth_ecp5` (yosys 0.70), by type, from `stat -json`. */
final case class Ecp5Cells(byType: Map[String, Long]) {
  private def n(t: String): Long = byType.getOrElse(t, 0L)
  def lut4: Long = n("LUT4")
  def carry: Long = n("CCU2C")
  def registers: Long = n("TRELLIS_FF")
  def brams: Long = n("DP16KD")
  def multipliers: Long = n("MULT18X18D")
}

/** Synthesis for the LFE5U-85F: `synth_ecp5` of the Verilog into the netlist nextpnr reads. */
object Ecp5Synth {
  /** `files` are names in the work folder: YoWASP's tools see the work folder, not /tmp. `upTo` stops
    * `synth_ecp5` before that label (then no netlist is written).
    */
  def script(top: String, files: Seq[String], upTo: Option[String] = None): String =
    Seq(s"read_verilog -sv ${files.map(f => "\"" + f + "\"").mkString(" ")}",
      s"hierarchy -check -top $top",
      upTo.fold(s"synth_ecp5 -top $top -json synth.json")(label => s"synth_ecp5 -top $top -run begin:$label"),
      "tee -q -o stat.json stat -json").mkString("\n") + "\n"

  /** Runs yosys in `work` (writes synth.ys, yosys.log, synth.json, stat.json); returns the seconds taken. */
  def run(tools: Ecp5Tools, top: String, files: Seq[String], work: os.Path, timeoutSeconds: Int, progress: String => Unit): Double = {
    os.makeDir.all(work)
    os.write.over(work / "synth.ys", script(top, files))
    ToolRun.run(s"synth_ecp5 $top", Seq(tools.yosys, "-q", "-s", "synth.ys"), work, work / "yosys.log", timeoutSeconds, progress)
  }

  /** The cells of the top in a `stat -json` file. */
  def cells(statJson: String, top: String): Ecp5Cells = {
    val v = try ujson.read(statJson.substring(statJson.indexOf('{'))) catch {
      case e: Exception => throw new TimingError(s"cannot read the yosys statistics: ${e.getMessage}")
    }
    val d = v.obj.get("design").orElse(v.obj.get("modules").flatMap(_.obj.get("\\" + top)))
      .getOrElse(throw new TimingError(s"yosys statistics name no design $top"))
    Ecp5Cells(d.obj.get("num_cells_by_type").map(_.obj.map { case (t, c) => t.stripPrefix("\\") -> c.num.toLong }.toMap).getOrElse(Map.empty))
  }
}
