package moire.cli

import scala.sys.process._

/** The command line as a user meets it: `moire.cli.Main` in a fresh JVM on the test class path. */
object CliProcess {
  private val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath
  private val cp = System.getProperty("java.class.path")

  /** Runs the CLI; returns (exit code, stdout, stderr). */
  def run(args: String*): (Int, String, String) = runWith(Nil)(args: _*)

  /** As `run`, with extra JVM options (e.g. -Dkey=value). */
  def runWith(jvmOpts: Seq[String])(args: String*): (Int, String, String) = runIn(jvmOpts, os.pwd)(args: _*)

  /** As `runWith`, in the working folder `cwd`. */
  def runIn(jvmOpts: Seq[String], cwd: os.Path, mainClass: String = "moire.cli.Main")(args: String*): (Int, String, String) = {
    val out = new StringBuilder; val err = new StringBuilder
    val code = Process(Seq(javaBin, "-Xmx2g") ++ jvmOpts ++ Seq("-cp", cp, mainClass) ++ args, cwd.toIO)
      .!(ProcessLogger(l => out.append(l).append('\n'), l => err.append(l).append('\n')))
    (code, out.toString, err.toString)
  }
}
