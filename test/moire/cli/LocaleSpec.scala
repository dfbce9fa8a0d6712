package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** A file name with non-ASCII characters under LANG=C: the launcher's locale lines (src/cli/utf8-locale.sh, also
  * sourced by ./sbt) give the JVM a UTF-8 character set, so the name is read and found. The name is made and
  * passed by bash, so this JVM's own character set plays no part.
  */
class LocaleSpec extends AnyFlatSpec with Matchers {
  private val dir = os.temp.dir(prefix = "moire-locale-")
  private val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath
  private val script = os.pwd / "src" / "cli" / "utf8-locale.sh"

  "the launcher" should "read a recording named mesure-é.csv under LANG=C" in {
    val rows = (0 until 2000).map { i => val a = 2 * math.Pi * i / 50.0; s"${2048 + (1500 * math.sin(a)).round},${2048 + (1500 * math.cos(a)).round}" }
    os.write(dir / "good.csv", "# moire-recording v1\n# sample_rate_hz: 1000000\n# adc_bits: 12\nsin,cos\n" + rows.mkString("\n") + "\n")
    val cmd = s"""f="$$(printf 'mesure-\\303\\251.csv')"; cp good.csv "$$f"; . "$$1"; exec "$$2" -cp "$$3" moire.cli.Main explain "$$f" --quiet --no-rtl"""
    for (lcAll <- Seq("C", "")) withClue(s"LC_ALL='$lcAll': ") {
      val r = os.proc("bash", "-c", cmd, "bash", script.toString, javaBin, System.getProperty("java.class.path"))
        .call(cwd = dir, check = false, env = Map("LANG" -> "C", "LC_ALL" -> lcAll, "LC_CTYPE" -> ""), mergeErrIntoOut = true)
      withClue(r.out.text()) { r.exitCode shouldBe 0 }
    }
  }
}
