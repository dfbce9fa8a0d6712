package moire.cli

/** The command line run in this JVM (Main.run): exit code and stderr; and the check that a message holds no
  * Java class name or stack trace.
  */
object CliInProcess {
  /** (exit code, stderr) of the command line; stdout is dropped. */
  def runCli(args: String*): (Int, String) = { val (c, _, e) = runCliOut(args: _*); (c, e) }

  /** (exit code, stdout, stderr) of the command line. */
  def runCliOut(args: String*): (Int, String, String) = synchronized {
    val err = new java.io.ByteArrayOutputStream(); val out = new java.io.ByteArrayOutputStream()
    val (e0, o0) = (System.err, System.out)
    System.setErr(new java.io.PrintStream(err, true)); System.setOut(new java.io.PrintStream(out, true))
    val code = try Console.withOut(out)(Console.withErr(err)(Main.run(args.toArray))) finally { System.setErr(e0); System.setOut(o0) }
    (code, out.toString, err.toString)
  }

  /** A Java/Scala class name, an exception's name or a stack frame. */
  val classNames = """(java|scala|ujson|mainargs|chisel3|firrtl)\.[a-z]+\.[A-Z]|Exception|\$[A-Z]|\tat """.r
}
