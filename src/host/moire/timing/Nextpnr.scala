package moire.timing

/** Place and route on the LFE5U-85F (CABGA381) with nextpnr-ecp5, timing-driven at the target.
  * @param lpf a Lattice constraint file in the work folder (pins, clock), for a board; none out of context
  */
final case class PnrOptions(speed: Int, targetMhz: Double, router: String, outOfContext: Boolean, lpf: Option[String] = None) {
  require(Seq(6, 7, 8).contains(speed), s"--speed: $speed is not an ECP5 speed grade; allowed: 6, 7, 8")
  require(targetMhz > 0 && targetMhz < 1000, s"--target-mhz must be above 0 and below 1000 MHz, got $targetMhz")
  require(Seq("router1", "router2").contains(router), s"--router: '$router' is not a nextpnr router; allowed: router1, router2")
  def tag: String = f"s$speed-${targetMhz}%.1fMHz-$router${if (outOfContext) "-ooc" else ""}"
  def args: Seq[String] = Seq("--85k", "--package", "CABGA381", "--speed", speed.toString, "--json", "synth.json",
    "--report", "report.json", "--router", router, "--freq", targetMhz.toString, "--timing-allow-fail", "--seed", "1") ++
    (if (outOfContext) Seq("--out-of-context") else Nil) ++ lpf.toSeq.flatMap(f => Seq("--lpf", f, "--textcfg", "design.config"))
}

object Nextpnr {
  /** Runs nextpnr in `work` (which holds synth.json and the .lpf); returns the seconds taken.
    * Throws [[ToolRun.Stopped]] when router2 does not converge ([[NextpnrWatch]]).
    */
  def run(tools: Ecp5Tools, o: PnrOptions, work: os.Path, timeoutSeconds: Int, progress: String => Unit): Double =
    ToolRun.run(s"nextpnr-ecp5 speed ${o.speed}", tools.nextpnr +: o.args, work, work / "nextpnr.log", timeoutSeconds, progress,
      new NextpnrWatch)

  /** (Fmax per clock, used cells per bel type, worst path per clock) of a `--report` file. */
  def report(text: String, rtl: String => Option[IndexedSeq[String]]): (Map[String, Double], Map[String, Long], Seq[CriticalPath]) = {
    val v = try ujson.read(text) catch { case e: Exception => throw new TimingError(s"cannot read the nextpnr report: ${e.getMessage}") }
    val fmax = v.obj.get("fmax").map(_.obj.map { case (c, f) => c -> f("achieved").num }.toMap).getOrElse(Map.empty)
    val used = v.obj.get("utilization").map(_.obj.map { case (t, u) => t -> u("used").num.toLong }.toMap).getOrElse(Map.empty)
    val paths = v.obj.get("critical_paths").map(_.arr.toSeq.map(p => CriticalPath.parse(p, rtl))).getOrElse(Nil)
    (fmax, used, paths)
  }
}
