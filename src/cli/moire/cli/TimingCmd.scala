package moire.cli

import moire.designs.Designs
import moire.timing._

/** `timing`: Fmax, utilisation and critical path of designs on the LFE5U-85F (open ECP5 flow). */
object TimingCmd {
  private def log(s: String): Unit = System.err.println(s"timing: $s")

  /** Runs the designs; returns false when one misses its target. */
  def run(config: CordicConfig, design: Option[String], all: Boolean, speeds: String, targetMhz: Double, router: String,
          inContext: Boolean, json: Option[String], markdown: Option[String], cache: Option[String], timeout: Int): Boolean = {
    val p = config.params
    val ds = (design, all) match {
      case (Some(_), true) => throw new UsageError("--design and --all: give one of them")
      case (None, false) => throw new UsageError(s"--design: give a design (${Designs.names.mkString(", ")}) or --all")
      case (Some(n), _) => Seq(Designs.find(n, p).fold(e => throw new UsageError(e), identity))
      case (None, true) => Designs.all(p)
    }
    // an empty entry among others (6,,8) is refused, not dropped
    val cells = speeds.split(",", -1).toSeq.map(_.trim)
    val ss = (if (cells.forall(_.isEmpty)) Nil else cells).map(s => moire.numbers.Decimal.int(s).filter(Seq(6, 7, 8).contains)
      .getOrElse(throw new UsageError(s"--speeds: '$s' is not an ECP5 speed grade; allowed: 6, 7, 8 (comma-separated)")))
    if (ss.isEmpty) throw new UsageError("--speeds: give at least one speed grade (6, 7, 8)")
    Lists.once("speeds", ss)
    if (!(targetMhz > 0 && targetMhz < 1000)) throw new UsageError(s"--target-mhz must be above 0 and below 1000 MHz, got $targetMhz")
    if (!Seq("router1", "router2").contains(router)) throw new UsageError(s"--router: '$router' is not a nextpnr router; allowed: router1, router2")
    if (timeout < 1) throw new UsageError(s"--timeout must be at least 1 second, got $timeout")
    // outputs and the cache before any tool runs
    (json ++ markdown).foreach(f => moire.files.SafeWrite.checkMade(moire.files.SafeWrite.fileArg(f)))
    cache.foreach(c => moire.files.SafeWrite.checkFolder(moire.files.SafeWrite.folderArg(c, "--cache")))
    for (j <- json; m <- markdown if os.Path(j, os.pwd) == os.Path(m, os.pwd))
      throw new UsageError(s"--json and --markdown name one file ($j); give two names")
    val o = TimingOptions(ss.distinct, targetMhz, router, !inContext, cache.map(c => os.Path(c, os.pwd)).getOrElse(Timing.defaultCache), timeout)
    val tools = Ecp5Tools.status.fold(why => throw new UsageError(why), identity)
    val results = ds.map { d =>
      val r = try Timing.run(tools, d.name, d.place, o, log)
      catch { case e: TimingError => throw new UsageError(e.getMessage) }
      print(r.text)
      r
    }
    json.foreach { f =>
      val path = os.Path(f, os.pwd)
      val v = if (results.size == 1) results.head.json else ujson.Arr(results.map(_.json): _*)
      moire.files.SafeWrite.madeText(path, ujson.write(v, indent = 2))
      println(s"wrote $path")
    }
    markdown.foreach { f =>
      val path = os.Path(f, os.pwd)
      val cmd = "moire timing " + (if (all) "--all" else s"--design ${design.get}") + s" --speeds ${ss.mkString(",")}"
      moire.files.SafeWrite.madeText(path, TimingTable.markdown(results, cmd))
      println(s"wrote $path")
    }
    val missed = results.filterNot(_.meets)
    if (missed.nonEmpty) println(s"missed the ${targetMhz} MHz target: ${missed.map(_.design).mkString(", ")}")
    missed.isEmpty
  }
}
