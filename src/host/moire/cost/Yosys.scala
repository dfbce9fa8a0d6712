package moire.cost

/** Cells of one module (or the whole design) after `synth_intel -family cycloneive`. */
final case class ModuleCells(name: String, cells: Map[String, Long]) {
  /** LUT cells: every cell type ending in `_lcell_comb`. */
  def luts: Long = cells.collect { case (t, n) if t.endsWith("_lcell_comb") => n }.sum
  /** Flip-flops (`dffeas`). */
  def registers: Long = cells.getOrElse("dffeas", 0L)
  /** Logic cells as the issue counts them: LUT cells plus flip-flops. */
  def logicCells: Long = luts + registers
  /** Memories in block RAM: `altsyncram` cells, or memories with a synchronous read that [[Yosys]]
    * keeps as `Yosys.m9kCell` black boxes (each takes one or more M9K blocks).
    */
  def m9k: Long = cells.collect { case (t, n) if t == "altsyncram" || t.endsWith("_ram_block") || t == Yosys.m9kCell => n }.sum
  /** Multiplications left as black boxes (see [[Yosys]]); each takes one or more 18 x 18 blocks. */
  def multCells: Long = cells.getOrElse(Yosys.multCell, 0L)
  /** Generic yosys cells that `synth_intel` left unmapped (`$mux`, `$not`, ...): listed, not in the logic cells. */
  def unmapped: Map[String, Long] = cells.filter { case (t, _) => t.startsWith("$") && t != "$scopeinfo" && t != Yosys.m9kCell }
}

/** What one yosys run measured. `modules` is empty for a flattened run.
  * @param memoryBits bits of the memories yosys inferred before mapping
  * @param multipliers 18 x 18 multiplier blocks the design's multiplications need
  * @param longestPathCells most LUT cells on a path between registers
  * @param blockRamBits bits of the memories kept for block RAM (synchronous read)
  * @param m9kBlocks M9K blocks those memories need (best M9K aspect ratio per memory)
  */
final case class SynthResult(top: String, total: ModuleCells, modules: Seq[ModuleCells], memoryBits: Long,
                             multipliers: Long, longestPathCells: Option[Int], seconds: Double,
                             blockRamBits: Long = 0L, m9kBlocks: Long = 0L)

/** A yosys failure, said in one line. */
final class YosysError(msg: String) extends Exception(msg)

/** Runs yosys 0.23 `synth_intel -family cycloneive` and reads its statistics.
  *
  * yosys 0.23 has no DSP mapping for Cyclone IV: a `$mul` would become thousands of LUTs (and take
  * many minutes). Like Quartus, we put each multiplication into 18 x 18 multiplier blocks instead:
  * the `$mul` cells become black boxes, counted as ceil(a / 18) * ceil(b / 18) blocks, not as LUTs.
  * Nor does it map block RAM for Cyclone IV E: a memory with a synchronous read (which M9K can hold,
  * as Quartus would place it) becomes a black box counted in M9K blocks; asynchronous-read memories
  * go to logic, as they would in Quartus (memories with one read port; more ports go to logic).
  */
object Yosys {
  val multCell = "moire_mult18"
  val m9kCell = "$__moire_m9k"
  private val multStub =
    s"""(* blackbox *) module $multCell #(parameter A_SIGNED = 0, B_SIGNED = 0, A_WIDTH = 1, B_WIDTH = 1, Y_WIDTH = 1)
       |  (input [A_WIDTH-1:0] A, input [B_WIDTH-1:0] B, output [Y_WIDTH-1:0] Y); endmodule
       |""".stripMargin

  def available: Boolean =
    try os.proc("yosys", "-V").call(check = false, stderr = os.Pipe).exitCode == 0
    catch { case _: java.io.IOException => false }

  /** The yosys script. `flatten = false` keeps the hierarchy while mapping (per-module table; totals
    * are the sum over instances), then flattens the mapped netlist for the longest path.
    */
  def script(top: String, files: Seq[os.Path], flatten: Boolean): String = Seq(
    coarse(top, files, flatten) ++ Seq(
      s"chtype -set $multCell t:$$mul",
      s"synth_intel -family cycloneive -top $top" + (if (flatten) "" else " -noflatten"),
      "tee -q -o stat.json stat -json"),
    // A hierarchical run flattens the mapped netlist for the path and the multiplier widths.
    if (flatten) Nil else Seq("flatten", s"tee -q -o mul.txt dump t:$multCell"),
    // Paths through LUT cells only: registers, RAMs and multipliers end a path.
    Seq("tee -q -o ltp.txt ltp -noff w:* t:*_lcell_comb")
  ).flatten.mkString("\n") + "\n"

  /** The script up to the multiplications' dump (`mul.txt`): reading, memories, width reduction. */
  private def coarse(top: String, files: Seq[os.Path], flatten: Boolean): Seq[String] =
    Seq(s"read_verilog -sv ${files.map(f => "\"" + f + "\"").mkString(" ")}",
      "read_verilog -lib mult_stub.v",
      // Vendor PLLs (board tops: altpll on the DE2-115, EHXPLLL on the ULX3S) as black boxes: hard blocks, no logic cells.
      "read_verilog -lib -DNO_CLEARBOX +/intel/common/altpll_bb.v",
      "read_verilog -lib +/ecp5/cells_bb.v",
      s"hierarchy -check -top $top",
      "proc") ++
    // Memories sit in their own firtool modules with separate read and write clock ports; inline
    // those modules into their parents so that yosys sees one clock and can spot a synchronous read.
    (if (flatten) Seq("flatten", "opt_clean")
    else Seq("setattr -mod -set keep_hierarchy 1 *", "setattr -mod -unset keep_hierarchy m:* %m", "flatten",
      "setattr -mod -unset keep_hierarchy *", "opt_clean")) ++
    Seq("tee -q -o pre.json stat -json",
      "memory -nomap",
      s"chtype -set $m9kCell t:$$mem_v2 r:RD_CLK_ENABLE=1'1 %i",
      s"tee -q -o m9k.txt dump t:$m9kCell",
      "opt_expr", "opt_clean", "wreduce", "opt_clean",
      "tee -q -o mul.txt dump t:$mul")

  /** The multiplier blocks alone, as `run` counts them on a flat design, in seconds instead of minutes. */
  def multipliers(top: String, files: Seq[os.Path], work: os.Path, timeoutSeconds: Int): Long = {
    os.makeDir.all(work)
    os.write.over(work / "mult_stub.v", multStub)
    os.write.over(work / "synth.ys", (coarse(top, files, flatten = true) :+ "").mkString("\n"))
    exec(top, work, timeoutSeconds, _ => ())
    StatParse.multBlocks(os.read(work / "mul.txt"))
  }

  /** Synthesizes `files` with `top` in `work`; progress lines every 30 s go to `progress`. */
  def run(top: String, files: Seq[os.Path], work: os.Path, flatten: Boolean, timeoutSeconds: Int,
          progress: String => Unit = _ => ()): SynthResult = {
    if (!available) throw new YosysError("yosys not found on PATH (install yosys 0.23 or newer)")
    os.makeDir.all(work)
    os.write.over(work / "mult_stub.v", multStub)
    os.write.over(work / "synth.ys", script(top, files, flatten))
    val seconds = exec(top, work, timeoutSeconds, progress)
    if (!os.exists(work / "stat.json")) throw new YosysError(s"yosys wrote no statistics for $top (log: ${work / "yosys.log"})")
    val (total, modules) = StatParse.cells(os.read(work / "stat.json"), top)
    val memBits = StatParse.memoryBits(os.read(work / "pre.json"))
    val mults = StatParse.multBlocks(os.read(work / "mul.txt"))
    val ltp = StatParse.longestPath(os.read(work / "ltp.txt"))
    val (ramBits, m9k) = StatParse.blockRam(os.read(work / "m9k.txt"))
    SynthResult(top, total, if (flatten) Nil else modules, memBits, mults, ltp, seconds, ramBits, m9k)
  }

  /** Runs `synth.ys` in `work` within the time limit; returns the seconds taken. */
  private def exec(top: String, work: os.Path, timeoutSeconds: Int, progress: String => Unit): Double = {
    val t0 = System.nanoTime()
    val proc = os.proc("yosys", "-q", "-l", "yosys.log", "-s", "synth.ys").spawn(cwd = work, stdout = os.Pipe, stderr = os.Pipe,
      mergeErrIntoOut = true)
    val drain = new Thread(() => { try proc.stdout.bytes catch { case _: Throwable => () } ; () })
    drain.setDaemon(true); drain.start()
    var waited = 0
    while (proc.isAlive() && waited < timeoutSeconds) {
      proc.waitFor(1000L)
      waited = ((System.nanoTime() - t0) / 1e9).toInt
      if (proc.isAlive() && waited > 0 && waited % 30 == 0) progress(s"yosys on $top: ${waited / 60}m${waited % 60}s")
    }
    if (proc.isAlive()) {
      proc.destroy(); proc.waitFor(2000L); if (proc.isAlive()) proc.destroyForcibly()
      throw new YosysError(s"yosys did not finish $top within $timeoutSeconds s (raise --timeout; big designs can take many minutes)")
    }
    if (proc.exitCode() != 0) {
      val log = if (os.exists(work / "yosys.log")) os.read.lines(work / "yosys.log") else Nil
      val err = log.find(_.contains("ERROR")).getOrElse(s"exit code ${proc.exitCode()}").trim
      throw new YosysError(s"yosys failed on $top: $err (log: ${work / "yosys.log"})")
    }
    (System.nanoTime() - t0) / 1e9
  }
}
