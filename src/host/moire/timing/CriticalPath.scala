package moire.timing

/** The worst path of one clock as nextpnr reports it, in the design's own terms.
  * @param from the launching register (yosys cell name less its ECP5 cell suffix: module path and signal)
  * @param to the capturing cell, named the same way
  * @param logicLevels LUT, multiplier and carry-chain entries on the path (a carry chain counts once)
  * @param carryCells carry cells the path ripples through (FCI to FCO hops)
  * @param signals named nets along the path, module path first (`sd.outPos`), in path order
  * @param verilog the Verilog lines the path's nets come from (`file:line` and the line's text)
  */
final case class CriticalPath(clock: String, delayNs: Double, from: String, to: String, logicLevels: Int, carryCells: Int,
                              signals: Seq[String], verilog: Seq[String]) {
  def json: ujson.Obj = ujson.Obj("clock" -> clock, "delay_ns" -> round3(delayNs), "from" -> from, "to" -> to,
    "logic_levels" -> logicLevels, "carry_cells" -> carryCells, "signals" -> ujson.Arr(signals.map(ujson.Str): _*),
    "verilog" -> ujson.Arr(verilog.map(ujson.Str): _*))

  def text: String = s"$from -> $to: ${f"$delayNs%.2f"} ns, $logicLevels logic levels, $carryCells carry cells; through ${signals.mkString(", ")}"

  private def round3(x: Double) = math.round(x * 1000) / 1000.0
}

object CriticalPath {
  /** yosys and nextpnr append the mapped cell's story to a name (`x_reg_TRELLIS_FF_Q`,
    * `x_LUT4_C_Z_CCU2C_...$CCU2_COMB0`, `$abc$12$...`): the design's name is what comes before.
    */
  private val suffix = """(_(LUT4|CCU2C|TRELLIS_FF|TRELLIS_COMB|PFUMX|L6MUX21|MULT18X18D|ALU54B|DP16KD|TRELLIS_DPR16X4|TRELLIS_RAMW)_|\$).*""".r

  def designName(cell: String): String = suffix.replaceFirstIn(cell.stripPrefix("\\"), "").replaceAll("""\[\d+\]$""", "")

  /** One entry of nextpnr's `critical_paths`; `rtl` reads a Verilog file of the design by its name. */
  def parse(p: ujson.Value, rtl: String => Option[IndexedSeq[String]]): CriticalPath = {
    val segs = p("path").arr.toSeq
    val logic = segs.filter(_("type").str == "logic")
    val carry = logic.count(s => s("from")("port").str == "FCI")
    val names = segs.flatMap(s => s.obj.get("net").map(_.str).toSeq ++ Seq(s("from")("cell").str))
      .map(designName).filter(n => n.nonEmpty && !n.startsWith("$")).distinct
    val sources = segs.flatMap(s => s.obj.get("sources").map(_.arr.map(_.str).toSeq).getOrElse(Nil))
      .filterNot(_.startsWith("/share/")).map(_.split('-').head).distinct
    val verilog = sources.flatMap { src =>
      src.split(':') match {
        case Array(file, pos) => val line = pos.split('.').head.toIntOption
          val text = for (l <- line; lines <- rtl(file) if l >= 1 && l <= lines.size) yield lines(l - 1).trim
          Some(s"$file:${line.getOrElse(0)}" + text.map(t => s": ${if (t.length > 120) t.take(117) + "..." else t}").getOrElse(""))
        case _ => None
      }
    }.distinct
    val from = segs.headOption.map(s => designName(s("from")("cell").str)).getOrElse("")
    val to = segs.lastOption.map(s => designName(s("to")("cell").str)).getOrElse("")
    val clock = p.obj.get("from").map(_.str.stripPrefix("posedge ").stripPrefix("negedge ")).getOrElse("")
    CriticalPath(clock, segs.map(_("delay").num).sum, from, to, logic.size - carry, carry, names, verilog)
  }
}
