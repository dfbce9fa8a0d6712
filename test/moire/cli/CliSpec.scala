package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import scala.sys.process._

/** The command line as a user meets it: a fresh JVM, exit codes, one-line errors. */
class CliSpec extends AnyFlatSpec {
  def run(args: String*): (Int, String, String) = moire.cli.CliProcess.run(args: _*)

  "A bad argument" should "print one line naming the parameter, exit 2, no stack trace" in {
    val cases = Seq(
      Seq("emit", "--iterations", "100") -> "--iterations must be in 4..40",
      Seq("emit", "--width", "7") -> "--width must be in 8..48",
      Seq("emit", "--mode", "tangent") -> "--mode: 'tangent' is not a mode",
      Seq("emit", "--rounding", "up") -> "--rounding: 'up'",
      Seq("emit", "--width", "wide") -> "--width: 'wide' is not a valid int",
      Seq("emit", "--mode", "sincos", "--peak-table", "16") -> "--peak-table applies to the arcsine",
      Seq("emit", "--frac-bits", "30") -> "--frac-bits must be in 1..17",
      Seq("emit", "--bogus", "1") -> "Unknown argument",
      Seq("design", "--function", "tan", "--max-error", "1e-3") -> "--function: 'tan'",
      Seq("design", "--function", "sin", "--max-error", "-1") -> "--max-error must be a positive finite number",
      Seq("nosuch") -> "Unable to find subcommand")
    for ((args, expected) <- cases) {
      val (code, out, err) = run(args: _*)
      assert(code == 2, s"$args: exit $code")
      val lines = err.linesIterator.filter(_.nonEmpty).toSeq
      assert(lines.size == 1, s"$args: expected one line, got:\n$err")
      assert(lines.head.startsWith("moire: ") && lines.head.contains(expected), s"$args: got ${lines.head}")
      assert(!err.contains("\tat "), s"$args: stack trace")
    }
  }

  "--help" should "describe each subcommand and exit 0" in {
    for (sub <- Seq("emit", "accuracy", "design")) {
      val (code, out, _) = run(sub, "--help")
      assert(code == 0 && out.startsWith("Usage: " + sub), s"$sub --help gave:\n$out")
    }
    val (code, out, _) = run("emit", "--help")
    assert(code == 0 && out.contains("--iterations") && out.contains("--pipeline-every"))
    val (c2, o2, _) = run("--help")
    assert(c2 == 0 && Seq("emit", "accuracy", "design").forall(o2.contains))
  }

  "emit" should "write the SystemVerilog of the chosen configuration into the chosen folder" in {
    val dir = os.temp.dir()
    val (code, out, err) = run("emit", "--mode", "asin-double", "--iterations", "12", "--width", "16", "--out", dir.toString)
    assert(code == 0, err)
    val sv = os.list(dir).filter(_.ext == "sv")
    assert(sv.map(_.last) == Seq("Cordic_asin_double_n12_w16f14_a16_g0z5_k1_rne.sv"), s"files: $sv")
    assert(os.read(sv.head).contains("module Cordic_asin_double_n12_w16f14_a16_g0z5_k1_rne("))
    assert(out.contains("latency 14 clocks"))
  }

  "design --function acos" should "pick and name the arccosine mode, with the launcher's command to emit it" in {
    // it named asin-double (an arcsine) and `./sbt "run emit ..."` (another tool's fuzz sweep, F20)
    val (code, out, err) = run("design", "--function", "acos", "--max-error", "1e-3")
    assert(code == 0, err)
    assert(out.contains("mode acos-double") && out.contains("emit it: moire emit --mode acos-double"), out)
  }

  "No arguments" should "print the overview and write nothing" in {
    val cwd = os.temp.dir(prefix = "moire-noargs-")
    try {
      val (code, out, err) = moire.cli.CliProcess.runIn(Nil, cwd)()
      assert(code == 0 && err.isEmpty, err)
      assert(out.contains("Usage: moire COMMAND") && out.contains("record and explain:") && out.contains("moire help COMMAND"), out)
      assert(out.linesIterator.size < 50, s"the overview is short: ${out.linesIterator.size} lines")
      assert(os.list(cwd).isEmpty, s"wrote ${os.list(cwd)}")
    } finally os.remove.all(cwd)
  }

  "./sbt run with no argument (SbtRun)" should "write the DE2-115 project of the subdivider into generated/ and name the next command" in {
    val cwd = os.temp.dir(prefix = "moire-noargs-")
    try {
      val (code, out, err) = moire.cli.CliProcess.runIn(Nil, cwd, "moire.cli.SbtRun")()
      assert(code == 0, err)
      val dir = cwd / "generated" / "de2-115"
      val top = moire.board.de2115.De2115.topName(moire.board.BoardParams())
      assert(top.startsWith("De2115_subdiv_"), top)
      for (f <- Seq(dir / "moire_de2_115.qsf", dir / "moire_de2_115.qpf", dir / "moire_de2_115.sdc", dir / "flash.sh", dir / "rtl" / s"$top.sv"))
        assert(os.isFile(f) && out.linesIterator.contains(s"wrote $f"), s"$f missing or not reported:\n$out")
      assert(out.linesIterator.exists(_.startsWith(s"next: ${dir / "flash.sh"}")), out)
    } finally os.remove.all(cwd)
  }
}
