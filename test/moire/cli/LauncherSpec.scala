package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The launcher's own words, in this JVM: the overview, the four help forms, per-command help with defaults,
  * simulate's effects and the version.
  */
class LauncherSpec extends AnyFlatSpec with Matchers {
  /** (exit code, stdout, stderr). */
  private def cli(args: String*): (Int, String, String) = CliInProcess.synchronized {
    val err = new java.io.ByteArrayOutputStream(); val out = new java.io.ByteArrayOutputStream()
    val (e0, o0) = (System.err, System.out)
    System.setErr(new java.io.PrintStream(err, true)); System.setOut(new java.io.PrintStream(out, true))
    val code = try Console.withOut(out)(Console.withErr(err)(Main.run(args.toArray))) finally { System.setErr(e0); System.setOut(o0) }
    (code, out.toString, err.toString)
  }
  private val commands = Main.commandNames

  "The overview" should "come with -h, --help and help, list every command under a task and say where to read more" in {
    val (_, overview, _) = cli("--help")
    for (form <- Seq(Seq("-h"), Seq("help"), Nil)) cli(form: _*) shouldBe ((0, overview, ""))
    for ((group, names) <- Help.groups) {
      overview should include(group + ":")
      names.foreach(n => commands should contain(n))
    }
    commands.foreach(c => overview should include(s"  $c "))
    overview should include("README.md")
    overview.linesIterator.size should be < 50
  }

  "help CMD and CMD --help" should "print the same usage, with defaults and required options" in {
    for (c <- commands.filter(_ != "replay")) {
      val (code, text, err) = cli("help", c)
      withClue(s"$c: $err") { code shouldBe 0; text should startWith(s"Usage: $c") }
      cli(c, "--help") shouldBe ((0, text, ""))
    }
    val sim = cli("help", "simulate")._2
    sim should include("--samples <int>             number of samples (default 100000)")
    sim should include("--noise <number>            white noise rms, full scale (default 0.0005)")
    sim should include("--out <str>                 output CSV file (required)")
    for ((name, _, _) <- moire.explain.EffectSpec.catalogue) sim should include(s"  $name (")
    cli("help", "replay")._2 should startWith("Usage: replay")
    cli("help", "record")._2 should include("seconds to record (required without --burst)")
  }

  "help board" should "list each board's designs as the board command takes them" in {
    val text = cli("help", "board")._2
    for (b <- moire.board.Boards.all)
      text should include(s"  ${b.name} (${b.title}): ${b.target.toString.toLowerCase} files, designs ${b.designs.map(_.name).mkString(", ")} (in the design registry: ")
    text should include("ulx3s (ULX3S): verilog files, designs subdiv, corrected, compensated (in the design registry: board-ulx3s, board-ulx3s-compensated)")
  }

  it should "refuse an unknown command in one line" in {
    val (code, _, err) = cli("help", "nosuch")
    code shouldBe 2; err.trim shouldBe "moire: 'nosuch' is not a command (moire --help lists them)"
    cli("--bogus")._1 shouldBe 2
  }

  "--version" should "print the version and the git commit of the build" in {
    val (code, out, _) = cli("--version")
    code shouldBe 0
    out.trim should fullyMatch regex """moire \d+\.\d+\.\d+\S* \(commit ([0-9a-f]{7,40}|unknown)\)"""
    val head = scala.util.Try(os.proc("git", "rev-parse", "--short=12", "HEAD").call(check = false).out.trim()).getOrElse("")
    if (head.nonEmpty) Version.commit should not be "unknown"
  }
}
