package moire.files

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** Ctrl-C (SIGINT) in the middle of a write, in a child JVM: the old output stays whole and no temporary file or
  * folder is left behind (the shutdown hook removes them).
  */
class InterruptSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-interrupt-")
  private val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath

  /** Every file under `d` with its bytes. */
  private def snapshot(d: os.Path): Map[os.Path, Seq[Byte]] = os.walk(d).filter(os.isFile).map(f => f -> os.read.bytes(f).toSeq).toMap
  private def leftovers(d: os.Path): Seq[os.Path] = os.walk(d).filter(p => p.last.contains(".tmp-") || p.last.contains(".moire-new-") || p.last.contains(".old-"))

  /** Starts the CLI in a child JVM, waits until a temporary appears under `watch`, sends SIGINT; the exit code. */
  private def interrupt(watch: os.Path, args: String*): Int = {
    // a job started in the background by a non-interactive shell inherits SIGINT ignored, and so would the child:
    // perl (essential on Debian) puts the default action back and execs the JVM (same pid)
    val restore = Seq("perl", "-e", "$SIG{INT} = 'DEFAULT'; exec @ARGV or die \"exec: $!\"")
    val pb = new ProcessBuilder((restore ++ Seq(javaBin, "-Xmx2g", "-cp", System.getProperty("java.class.path"), "moire.cli.Main") ++ args): _*)
      .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.DISCARD)
    val p = pb.start()
    val deadline = System.nanoTime() + 120e9.toLong
    while (p.isAlive && leftovers(watch).isEmpty && System.nanoTime() < deadline) Thread.sleep(5)
    withClue("no temporary appeared while the command ran: ") { p.isAlive shouldBe true }
    os.proc("kill", "-INT", p.pid().toString).call()
    p.waitFor()
  }

  "simulate" should "leave the old recording and no temporary file when interrupted" in {
    val out = dir / "sim"; val f = out / "rec.csv"
    os.makeDir.all(out); os.write(f, "old\n")
    val code = interrupt(out, "simulate", "--out", f.toString, "--samples", "20000000")
    code should not be 0
    leftovers(out) shouldBe empty
    os.read(f) shouldBe "old\n"
  }

  "board" should "leave the old project whole and nothing else when interrupted" in {
    val out = dir / "board"
    os.makeDir.all(out / "rtl")
    os.write(out / "rtl" / "Old.sv", "module Old; endmodule\n")
    os.write(out / "moire_de2_115.qsf", "old qsf listing rtl/Old.sv\n")
    os.write(out / "notes.txt", "the user's own file\n")
    val before = snapshot(out)
    val code = interrupt(out, "board", "de2-115", "--out", out.toString)
    code should not be 0
    leftovers(out) shouldBe empty
    snapshot(out) shouldBe before
  }
}
