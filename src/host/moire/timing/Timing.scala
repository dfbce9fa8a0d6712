package moire.timing

import chisel3.RawModule
import moire.emit.{Emit, Target}

/** How `timing` runs: speed grades, target, router, cache folder, time limit per tool run. */
final case class TimingOptions(speeds: Seq[Int] = Seq(6, 8), targetMhz: Double = 65.0, router: String = "router2",
                               outOfContext: Boolean = true, cache: os.Path = Timing.defaultCache, timeoutSeconds: Int = 3600) {
  def pnr(speed: Int): PnrOptions = PnrOptions(speed, targetMhz, router, outOfContext)
}

/** The timing engine: elaborate, synthesize (`synth_ecp5`), place and route per speed grade, read the
  * report. Every run is cached under the hash of the Verilog and the flow's options, so a second run
  * of the same design is read back at once.
  */
object Timing {
  def defaultCache: os.Path = os.Path(sys.env.getOrElse("MOIRE_TOOLS", s"${sys.props("user.home")}/.cache/moire-tools"), os.pwd) / "timing"

  /** The Verilog of a design in a fresh folder: (top name, files). */
  def emit(gen: () => RawModule, dir: os.Path): (String, Seq[os.Path]) = {
    val (top, files) = Emit.write(gen(), dir, Target.Verilog)
    (top.desiredName, files)
  }

  /** A fresh work folder `name.tmp-PID` in `parent`, after removing those of runs that are gone (killed). */
  private def tmpDir(parent: os.Path, name: String): os.Path = {
    if (os.isDir(parent)) os.list(parent).filter(_.last.startsWith(s"$name.tmp-")).foreach { d =>
      val alive = d.last.stripPrefix(s"$name.tmp-").toLongOption.exists(p => ProcessHandle.of(p).filter(_.isAlive).isPresent)
      if (!alive) os.remove.all(d)
    }
    val tmp = parent / s"$name.tmp-${ProcessHandle.current().pid()}"
    os.remove.all(tmp); os.makeDir.all(tmp)
    tmp
  }

  private def sha(parts: Seq[Array[Byte]]): String = {
    val md = java.security.MessageDigest.getInstance("SHA-256")
    parts.foreach { p => md.update(p); md.update(0.toByte) }
    md.digest().map(b => f"$b%02x").mkString.take(16)
  }

  /** The synthesis folder of this Verilog, synthesized once: holds the files, synth.json and stat.json.
    * `extra` (name, text) files (a board's .lpf) are written beside them and are part of the hash.
    */
  def synth(tools: Ecp5Tools, top: String, files: Seq[os.Path], o: TimingOptions, progress: String => Unit,
            extra: Seq[(String, String)] = Nil): (os.Path, Boolean) = {
    val script = Ecp5Synth.script(top, files.map(_.last))
    val key = sha(Seq(tools.yosys.getBytes, script.getBytes) ++ files.flatMap(f => Seq(f.last.getBytes, os.read.bytes(f))) ++
      extra.flatMap { case (n, t) => Seq(n.getBytes, t.getBytes) })
    val dir = o.cache / s"$top-$key"
    if (os.exists(dir / "synth.json") && os.exists(dir / "stat.json")) (dir, true)
    else {
      val tmp = tmpDir(o.cache, s"$top-$key")
      files.foreach(f => os.copy.over(f, tmp / f.last))
      extra.foreach { case (n, t) => os.write.over(tmp / n, t) }
      progress(s"synth_ecp5 $top (yosys 0.70)")
      Ecp5Synth.run(tools, top, files.map(_.last), tmp, o.timeoutSeconds, progress)
      os.remove.all(dir); os.move(tmp, dir)
      (dir, false)
    }
  }

  /** Place and route of a synthesized folder at one speed grade (cached in a subfolder). */
  def place(tools: Ecp5Tools, synthDir: os.Path, top: String, p: PnrOptions, timeoutSeconds: Int, progress: String => Unit): SpeedResult = {
    val dir = synthDir / p.tag
    val cached = os.exists(dir / "report.json")
    if (!cached) {
      val tmp = tmpDir(synthDir, p.tag)
      os.copy.over(synthDir / "synth.json", tmp / "synth.json")
      p.lpf.foreach(f => os.copy.over(synthDir / f, tmp / f))
      def pnr(q: PnrOptions): Double = {
        progress(s"nextpnr-ecp5 $top, speed ${q.speed}, target ${q.targetMhz} MHz, ${q.router}${if (q.outOfContext) ", out of context" else ""}")
        Nextpnr.run(tools, q, tmp, timeoutSeconds, progress)
      }
      // router2 that turns and climbs (a congested placement) is given up for router1, and the result says so.
      val (seconds, router) = try (pnr(p), p.router) catch {
        case e: ToolRun.Stopped if p.router == "router2" =>
          progress(s"${e.getMessage}; again with router1")
          os.move.over(tmp / "nextpnr.log", tmp / "nextpnr-router2.log")
          (pnr(p.copy(router = "router1")), s"router1 (${e.why})")
      }
      os.write.over(tmp / "seconds", f"$seconds%.1f")
      os.write.over(tmp / "router", router)
      os.remove.all(dir); os.move(tmp, dir)
    }
    val seconds = os.read(dir / "seconds").trim.toDoubleOption.getOrElse(0.0)
    val router = if (os.isFile(dir / "router")) os.read(dir / "router").trim else p.router
    def rtl(name: String): Option[IndexedSeq[String]] = {
      val f = synthDir / os.RelPath(name).last
      if (os.isFile(f)) Some(os.read.lines(f)) else None
    }
    val (fmax, used, paths) = Nextpnr.report(os.read(dir / "report.json"), rtl)
    val cells = Ecp5Synth.cells(os.read(synthDir / "stat.json"), top)
    // The worst path: the one of the slowest clock (nextpnr lists one per clock pair).
    val worst = if (fmax.isEmpty) paths.sortBy(-_.delayNs).headOption
      else paths.filter(_.clock == fmax.minBy(_._2)._1).sortBy(-_.delayNs).headOption.orElse(paths.sortBy(-_.delayNs).headOption)
    SpeedResult(p.speed, p.targetMhz, fmax, worst, used.getOrElse("TRELLIS_COMB", 0L), used.getOrElse("TRELLIS_FF", 0L),
      used.getOrElse("DP16KD", 0L), used.getOrElse("MULT18X18D", 0L), cells, seconds, cached, router)
  }

  /** The whole flow for one design. */
  def run(tools: Ecp5Tools, design: String, gen: () => RawModule, o: TimingOptions, progress: String => Unit): TimingResult = {
    val work = os.temp.dir(prefix = "moire-timing-")
    try {
      progress(s"$design: elaborating")
      val (top, files) = emit(gen, work / "rtl")
      val (synthDir, cached) = synth(tools, top, files, o, progress)
      if (cached) progress(s"$design: synthesis cached in $synthDir")
      val speeds = o.speeds.map { s =>
        val r = place(tools, synthDir, top, o.pnr(s), o.timeoutSeconds, progress)
        progress(f"$design: speed $s: Fmax ${r.fmax}%.1f MHz${if (r.cached) " (cached)" else ""}")
        r
      }
      TimingResult(design, top, o.outOfContext, speeds)
    } finally os.remove.all(work)
  }

  /** The multiplier blocks `synth_ecp5` maps: its coarse step (`-run begin:map_ram`) already maps every
    * product to MULT18X18D, so this takes seconds where the whole synthesis takes minutes.
    */
  def multipliers(tools: Ecp5Tools, gen: () => RawModule, o: TimingOptions, progress: String => Unit): Long = {
    val work = os.temp.dir(prefix = "moire-timing-")
    try {
      val (top, files) = emit(gen, work)
      os.write.over(work / "synth.ys", Ecp5Synth.script(top, files.map(_.last), upTo = Some("map_ram")))
      ToolRun.run(s"synth_ecp5 $top (coarse)", Seq(tools.yosys, "-q", "-s", "synth.ys"), work, work / "yosys.log", o.timeoutSeconds, progress)
      Ecp5Synth.cells(os.read(work / "stat.json"), top).multipliers
    } finally os.remove.all(work)
  }
}
