package moire.files

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

import moire.cli.CliInProcess.{classNames, runCli}

/** Files moire makes again at will (Verilog, tables, JSON results, plots) replace only what moire wrote, as it wrote
  * it: a hand-edited .sv, a user's notes under a table's name were written over (another tool's fuzz sweep, F10, F13),
  * and an earlier run's effect plot stayed beside a run that found no effect (F5).
  */
class MadeFilesSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-made-")

  "SafeWrite.made" should "write a file again over its own and refuse a user's or an edited one" in {
    val f = dir / "t" / "table.md"
    SafeWrite.madeText(f, "first\n")
    SafeWrite.madeText(f, "second\n")
    os.read(f) shouldBe "second\n"
    os.write.over(f, "second, edited\n")
    the[FileError] thrownBy SafeWrite.madeText(f, "third\n") should have message
      s"$f: is not as moire wrote it (your own, or edited since); moire does not replace it: move it, or give another output name"
    os.read(f) shouldBe "second, edited\n"
    val mine = dir / "t" / "notes.md"
    os.write(mine, "# my lab notes\n")
    a[FileError] should be thrownBy SafeWrite.checkMade(mine)
    os.read(mine) shouldBe "# my lab notes\n"
  }

  "SafeWrite.removeStale" should "remove only the named files an earlier run wrote, as it wrote them" in {
    val d = dir / "stale"
    for (n <- Seq("a_1.png", "a_2.png", "a_3.png", "b_1.png")) SafeWrite.madeText(d / n, n)
    os.write.over(d / "a_3.png", "edited")
    os.write(d / "a_4.png", "the user's")
    val gone = SafeWrite.removeStale(d, _.startsWith("a_"), Seq(d / "a_1.png"))
    gone shouldBe Seq(d / "a_2.png")
    os.list(d).map(_.last).filterNot(_ == SafeWrite.Manifest).sorted shouldBe Seq("a_1.png", "a_3.png", "a_4.png", "b_1.png")
    os.read(d / SafeWrite.Manifest) should not include "a_2.png"
  }

  "emit" should "refuse to write over a hand-edited .sv of the same name, and write again over its own" in {
    val out = dir / "emit"
    val args = Seq("emit", "--iterations", "8", "--width", "12", "--out", out.toString)
    runCli(args: _*)._1 shouldBe 0
    val sv = os.list(out).filter(_.ext == "sv").head
    runCli(args: _*)._1 shouldBe 0
    os.write.append(sv, "// my hand edit\n")
    val (code, err) = runCli(args: _*)
    withClue(err) {
      code shouldBe 2
      err should include("not as moire wrote it")
      classNames.findFirstIn(err) shouldBe None
    }
    os.read(sv) should endWith("// my hand edit\n")
  }

  "explain --plots" should "remove the effect plot of an earlier run that this run does not make" in {
    val rec = dir / "rec2.csv"; val plots = dir / "plots"
    runCli("simulate", "--samples", "20000", "--effect", "harmonic:order=3,amplitude_rel=0.02", "--out", rec.toString)._1 shouldBe 0
    runCli("explain", "--quiet", "--plots", plots.toString, rec.toString)._1 shouldBe 0
    os.exists(plots / "rec2_effect_1_harmonic.png") shouldBe true
    // a user's plot of another record that starts with this one's name stays
    os.copy(plots / "rec2_residual_time.png", plots / "rec2_b_residual_time.png")
    os.remove(rec)
    runCli("simulate", "--samples", "20000", "--out", rec.toString)._1 shouldBe 0
    runCli("explain", "--quiet", "--plots", plots.toString, rec.toString)._1 shouldBe 0
    os.exists(plots / "rec2_effect_1_harmonic.png") shouldBe false
    os.exists(plots / "rec2_residual_time.png") shouldBe true
    os.exists(plots / "rec2_b_residual_time.png") shouldBe true
  }
}
