package moire.cost

/** Reads yosys 0.23 output: `stat -json`, `dump t:$mul` and `ltp`. */
object StatParse {
  private def plain(name: String): String = name.stripPrefix("\\")

  /** The JSON object of a `tee -o` file. yosys 0.23 writes the hierarchy tree of a design with
    * submodules as plain text into `stat -json` (before "design"), and may append warnings: keep only
    * JSON lines, up to the closing brace.
    */
  def jsonPart(text: String): String = {
    val lines = text.linesIterator.toSeq
    val end = lines.indexWhere(_ == "}")
    val json = if (end < 0) lines else lines.take(end + 1)
    json.filter(l => l.trim.isEmpty || "\"{}[]".contains(l.trim.head)).mkString("\n")
  }

  private def cellMap(o: ujson.Value): Map[String, Long] =
    o.obj.get("num_cells_by_type").map(_.obj.map { case (t, n) => plain(t) -> n.num.toLong }.toMap).getOrElse(Map.empty)

  /** The whole design (`design`, with submodule instances expanded) and each module of a `stat -json`. */
  def cells(json: String, top: String): (ModuleCells, Seq[ModuleCells]) = {
    val v = try ujson.read(jsonPart(json)) catch { case e: Exception => throw new YosysError(s"cannot read yosys stat JSON: ${e.getMessage}") }
    val modules = v.obj.get("modules").map(_.obj.toSeq.map { case (n, m) => ModuleCells(plain(n), cellMap(m)) }).getOrElse(Nil)
    val design = v.obj.get("design").map(d => ModuleCells(top, cellMap(d)))
      .orElse(modules.find(_.name == top)).getOrElse(throw new YosysError(s"yosys stat has no design section for $top"))
    (design, modules)
  }

  /** Memory bits yosys inferred (`num_memory_bits` of the design). */
  def memoryBits(json: String): Long = {
    val v = try ujson.read(jsonPart(json)) catch { case e: Exception => throw new YosysError(s"cannot read yosys stat JSON: ${e.getMessage}") }
    v.obj.get("design").orElse(v.obj.get("modules").flatMap(_.obj.values.headOption))
      .flatMap(_.obj.get("num_memory_bits")).map(_.num.toLong).getOrElse(0L)
  }

  private val widthParam = """\s*parameter \\([AB])_WIDTH (\d+)\s*""".r
  private val connectAB = """\s*connect \\([AB]) (.*)""".r
  /** 18 x 18 multiplier blocks for the `$mul` (or black-boxed multiplier) cells of a `dump`:
    * ceil(a / 18) * ceil(b / 18) each, with a and b the operands' real widths ([[Operand.realWidth]]).
    */
  def multBlocks(dump: String): Long = multipliers(dump).map { case (a, b) => ((a + 17) / 18).toLong * ((b + 17) / 18) }.sum

  /** The real operand widths (a, b) of each multiplication in a `dump`. */
  def multipliers(dump: String): Seq[(Int, Int)] = {
    val out = Seq.newBuilder[(Int, Int)]
    var a = 0; var b = 0; var ca = ""; var cb = ""; var inMul = false
    def flush(): Unit = if (inMul) {
      out += ((Operand.realWidth(a, ca, !Operand.constant(cb)), Operand.realWidth(b, cb, !Operand.constant(ca)))); inMul = false
    }
    dump.linesIterator.foreach { l =>
      val t = l.trim
      if (t.startsWith("cell ")) { flush(); inMul = Seq("$mul", Yosys.multCell, "\\" + Yosys.multCell).exists(c => t.startsWith(s"cell $c ")); a = 0; b = 0; ca = ""; cb = "" }
      else if (t == "end") flush()
      else l match {
        case widthParam("A", w) => a = w.toInt
        case widthParam("B", w) => b = w.toInt
        case connectAB("A", c) => ca = c
        case connectAB("B", c) => cb = c
        case _ =>
      }
    }
    flush()
    out.result()
  }

  private val memParam = """\s*parameter \\(SIZE|WIDTH) (\d+)\s*""".r
  /** M9K aspect ratios of Cyclone IV E (depth x width). */
  private val m9kShapes = Seq(8192 -> 1, 4096 -> 2, 2048 -> 4, 1024 -> 9, 512 -> 18, 256 -> 36)
  /** M9K blocks for a depth x width memory: the best aspect ratio, ceil(depth / d) * ceil(width / w). */
  def m9kBlocks(depth: Long, width: Long): Long =
    m9kShapes.map { case (d, w) => ((depth + d - 1) / d) * ((width + w - 1) / w) }.min

  /** (bits, M9K blocks) of the memory black boxes in a `dump` of `Yosys.m9kCell` cells. */
  def blockRam(dump: String): (Long, Long) = {
    var bits = 0L; var blocks = 0L; var size = 0L; var width = 0L; var inMem = false
    def flush(): Unit = if (inMem) { bits += size * width; blocks += m9kBlocks(size, width); inMem = false }
    dump.linesIterator.foreach { l =>
      val t = l.trim
      if (t.startsWith("cell ")) { flush(); inMem = true; size = 0; width = 0 }
      else if (t == "end") flush()
      else l match {
        case memParam("SIZE", v) => size = v.toLong
        case memParam("WIDTH", v) => width = v.toLong
        case _ =>
      }
    }
    flush()
    (bits, blocks)
  }

  private val ltpLine = """Longest topological path in \S+ \(length=(-?\d+)\)""".r.unanchored
  /** LUT cells on the longest path of an `ltp` run (None when yosys found none). */
  def longestPath(text: String): Option[Int] =
    text.linesIterator.collectFirst { case ltpLine(n) => n.toInt }.filter(_ >= 0)
}
