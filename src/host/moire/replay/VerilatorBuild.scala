package moire.replay


/** A built replay harness: the executable, whether it came from the cache, and the build time. */
final case class Harness(exe: os.Path, cached: Boolean, buildSeconds: Double, dir: os.Path)

/** Compiles a design with Verilator and the C++ harness (src/resources/moire/replay/harness.cpp), once per
  * configuration: the cache folder is keyed by a hash of the Verilog, the harness, the flags and the
  * Verilator version. Cache root: system property moire.replay.cache or $MOIRE_REPLAY_CACHE, else $XDG_CACHE_HOME/moire/replay, else ~/.cache/moire/replay.
  */
object VerilatorBuild {
  /** Verilator and C++ options for speed (measured in docs/replay.md): single thread, no tracing or assertions. */
  val verilatorFlags: Seq[String] = Seq("-O3", "--x-assign", "fast", "--x-initial", "fast", "--noassert", "-Wno-fatal",
    "--prefix", "Vtop")
  /** Verilator's makefile compiles the model with OPT_FAST (default -Os, which -CFLAGS cannot override). */
  val makeFlags: Seq[String] = Seq("OPT_FAST=-O2", "OPT_SLOW=-O1", "OPT_GLOBAL=-O2")

  lazy val harnessSource: String = {
    val in = getClass.getResourceAsStream("/moire/replay/harness.cpp")
    if (in == null) throw new IllegalStateException("resource moire/replay/harness.cpp is missing from the class path")
    try new String(in.readAllBytes(), "UTF-8") finally in.close()
  }

  def cacheRoot: os.Path = sys.props.get("moire.replay.cache").orElse(sys.env.get("MOIRE_REPLAY_CACHE")).filter(_.nonEmpty).map(os.Path(_, os.pwd))
    .orElse(sys.env.get("XDG_CACHE_HOME").filter(_.nonEmpty).map(d => os.Path(d, os.pwd) / "moire" / "replay"))
    .getOrElse(os.home / ".cache" / "moire" / "replay")

  lazy val verilatorVersion: String = try os.proc("verilator", "--version").call(stderr = os.Pipe).out.text().trim
  catch { case _: Exception => throw new ReplayError("replay needs Verilator on the PATH (apt-get install verilator)") }

  def key(verilog: String, harness: String = harnessSource): String = {
    val md = java.security.MessageDigest.getInstance("SHA-256")
    for (s <- Seq(verilog, harness, verilatorVersion, verilatorFlags.mkString(" "), makeFlags.mkString(" ")))
      md.update((s + "\u0000").getBytes("UTF-8"))
    md.digest().take(10).map(b => f"${b & 0xff}%02x").mkString
  }

  /** The harness for this Verilog (top module `top`), from the cache or built now; `source` is the C++ harness
    * (default: the replay harness).
    */
  def harness(verilog: String, top: String, root: os.Path = cacheRoot, source: String = harnessSource): Harness = {
    val dir = root / s"$top-${key(verilog, source)}"
    val exe = dir / "harness"
    if (os.isFile(exe)) return Harness(exe, cached = true, 0.0, dir)
    val t0 = System.nanoTime()
    val tmp = root / s".${dir.last}.tmp-${ProcessHandle.current().pid()}-${System.nanoTime()}"
    os.makeDir.all(tmp)
    os.write(tmp / "top.sv", verilog)
    os.write(tmp / "harness.cpp", source)
    val cmd = Seq("verilator", "--cc", "top.sv", "--top-module", top, "--exe", "harness.cpp", "--build", "-j", "1",
      "-Mdir", "obj", "-o", "harness") ++ verilatorFlags ++ makeFlags.flatMap(f => Seq("-MAKEFLAGS", f))
    os.write(tmp / "build.cmd", cmd.mkString(" ") + "\n")
    val r = os.proc(cmd).call(cwd = tmp, check = false, stdout = tmp / "build.log", mergeErrIntoOut = true)
    if (r.exitCode != 0 || !os.isFile(tmp / "obj" / "harness"))
      throw new ReplayError(s"verilator build of $top failed (exit ${r.exitCode}); log: ${tmp / "build.log"}")
    os.copy(tmp / "obj" / "harness", tmp / "harness")
    os.remove.all(tmp / "obj")
    try os.move(tmp, dir, atomicMove = true)
    catch { case _: java.nio.file.FileAlreadyExistsException | _: java.nio.file.DirectoryNotEmptyException => os.remove.all(tmp) }
    Harness(exe, cached = false, (System.nanoTime() - t0) / 1e9, dir)
  }
}
