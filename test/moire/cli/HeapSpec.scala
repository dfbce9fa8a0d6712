package moire.cli

import org.scalatest.flatspec.AnyFlatSpec
import org.scalatest.matchers.should.Matchers

/** The launcher's heap lines (src/cli/heap.sh): java's last -Xmx wins, JAVA_OPTS comes first on the launcher's command
  * line and application.ini's default after it, so JAVA_OPTS=-Xmx8g was ignored (the out-of-memory message advised it).
  * The java options are put together as the launcher does and given to this java, which says the heap it took.
  */
class HeapSpec extends AnyFlatSpec with Matchers {
  private val javaBin = new java.io.File(System.getProperty("java.home"), "bin/java").getPath
  private val script = os.pwd / "src" / "cli" / "heap.sh"

  /** The MB of heap java takes with JAVA_OPTS `opts` and the -J options `dashJ` given after the default. */
  private def heapMb(opts: String, dashJ: String*): Long = {
    val cmd = """java_args=(); addJava () { java_args+=( "$1" ); }; _moire_default_heap=-Xmx4g; . "$1"; shift
                |addJava -Xss8m; addJava -Xmx4g; for a in "$@"; do addJava "$a"; done
                |exec "$JAVA_BIN" ${JAVA_OPTS} "${java_args[@]}" -XX:+PrintFlagsFinal -version""".stripMargin
    val r = os.proc(Seq("bash", "-c", cmd, "bash", script.toString) ++ dashJ).call(check = false, env = Map("JAVA_OPTS" -> opts, "JAVA_BIN" -> javaBin))
    r.exitCode shouldBe 0
    r.out.lines().find(_.contains(" MaxHeapSize ")).get.trim.split("\\s+")(3).toLong / 1048576
  }

  "the launcher" should "take the heap from JAVA_OPTS over its default, and a -J-Xmx over both" in {
    heapMb("") shouldBe 4096
    heapMb("-Xmx1g") shouldBe 1024
    heapMb("-Dx=1 -Xmx1536m -Xss8m") shouldBe 1536
    heapMb("-Xmx1g", "-Xmx768m") shouldBe 768
    heapMb("-Dx=1", "-Xmx768m") shouldBe 768
  }
}

/** The launcher script's own options (src/cli/launcher-args.sh): `-Jfoo` made java look for a main class `foo` and print
  * its ClassNotFoundException (another tool's fuzz sweep, F20); the script took its options from anywhere, even as an
  * option's value (`emit --out -v` printed the java command line, `emit -XX:+Foo` stopped the JVM). The arguments the
  * script's own parser gets are printed one a line: Java's before a `--`, moire's after it.
  */
class LauncherArgsSpec extends AnyFlatSpec with Matchers {
  private val script = os.pwd / "src" / "cli" / "launcher-args.sh"
  private def run(args: String*): (Int, String) = {
    val r = os.proc(Seq("bash", "-c", """. "$0"; printf '%s\n' "$@"""", script.toString) ++ args).call(check = false, stderr = os.Pipe)
    (r.exitCode, (r.out.text() + r.err.text()).trim)
  }

  "the launcher" should "refuse a -J that carries no Java option in one line" in {
    run("-Jfoo", "simulate") shouldBe ((2, "moire: -Jfoo: -J passes an option to Java (like -J-Xmx8g), and 'foo' is none"))
    run("-J", "simulate") shouldBe ((2, "moire: -J needs a Java option joined to it (like -J-Xmx8g)"))
  }

  it should "take Java options before the command and leave every word from the command on to moire" in {
    run("-J-Xmx1g", "-Dx=1", "simulate", "--samples", "100") shouldBe ((0, "-J-Xmx1g\n-Dx=1\n--\nsimulate\n--samples\n100"))
    run("explain", "x.csv") shouldBe ((0, "--\nexplain\nx.csv"))
    for (own <- Seq("-v", "-d", "-help", "-mem", "-jvm-debug", "-java-home", "-main", "-no-version-check", "-J", "-Jfoo", "-J-Xmx1m", "-XX:+Foo", "-Dy=2"))
      withClue(own) { run("emit", "--out", own) shouldBe ((0, s"--\nemit\n--out\n$own")) }
    run("-main", "foo") shouldBe ((0, "--\n-main\nfoo"))
    run() shouldBe ((0, "--"))
  }
}
