// moire: Chisel generators for optical-grating signal processing.
// Layers depend one way: hw <- boards <- host <- cli; the root project holds the tests and runs the cli.
ThisBuild / scalaVersion := "2.13.15"
ThisBuild / version := "0.1.0"
ThisBuild / organization := "io.github.moire"

val chiselVersion = "6.7.0"
/** The staged launcher's and `./sbt run`'s heap; JAVA_OPTS=-Xmx... replaces it for the launcher (src/cli/heap.sh). */
val defaultHeap = "-Xmx4g"
// chiseltest 6.0.0 asks for chisel 6.1.0, which is not on Maven Central: everyone gets 6.7.0.
ThisBuild / dependencyOverrides += "org.chipsalliance" %% "chisel" % chiselVersion

lazy val common = Seq(
  addCompilerPlugin("org.chipsalliance" % "chisel-plugin" % chiselVersion cross CrossVersion.full),
  scalacOptions ++= Seq("-deprecation", "-feature", "-unchecked", "-language:reflectiveCalls", "-Ymacro-annotations"),
  // no Scaladoc jars: `stage` would build them for nothing
  Compile / doc / sources := Nil,
  Compile / packageDoc / publishArtifact := false
)

/** Closures compiled to classes of their own (in the jar, and in the CDS archive) instead of made at their first call by
  * the JDK's lambda factory: a new JVM's 1 M explain spent about 2 s of C2 compiling that factory's bytecode writer, and
  * took 27.5 and 26.9 s instead of 31.1 and 29.4 s (docs/explain.md, the twelfth step). The host and cli layers only:
  * the hardware layers run Chisel, where a new JVM's start is not what counts.
  */
lazy val classLambdas = scalacOptions += "-Ydelambdafy:inline"

/** A layer whose Scala lives in `dir` (no test sources of its own: tests are in the root project). */
def layer(id: String, dir: String) = Project(id, file(dir))
  .settings(common)
  .settings(
    Compile / scalaSource := baseDirectory.value,
    Compile / javaSource := baseDirectory.value,
    Compile / resourceDirectory := baseDirectory.value / "resources",
    Test / unmanagedSourceDirectories := Nil,
    Test / unmanagedResourceDirectories := Nil,
    target := (ThisBuild / baseDirectory).value / "target" / id
  )

/** CORDIC, datapaths, their golden models, io RTL, the stream protocol, fixed point, ADC formats, the emitter. */
lazy val hw = layer("hw", "src/hw").settings(
  libraryDependencies ++= Seq(
    "org.chipsalliance" %% "chisel" % chiselVersion,
    "com.lihaoyi" %% "upickle" % "3.1.0"
  )
)

/** Board harnesses, pin tables, vendor project writers. */
lazy val boards = layer("boards", "boards").dependsOn(hw).settings(
  libraryDependencies += "com.lihaoyi" %% "mainargs" % "0.7.6",
  // ecp5-tools.sh also as a resource: the ULX3S project folder gets a copy for its build.sh
  Compile / unmanagedResourceDirectories += baseDirectory.value / "tools"
)

/** Host tools: recording, stream codec and recorder, replay, explain, cost, the papers' tables, calibration. */
lazy val host = layer("host", "src/host").dependsOn(boards).settings(
  classLambdas,
  libraryDependencies ++= Seq(
    "org.hipparchus" % "hipparchus-core" % "4.0.3",
    "org.hipparchus" % "hipparchus-stat" % "4.0.3",
    "org.hipparchus" % "hipparchus-fitting" % "4.0.3",
    "org.hipparchus" % "hipparchus-optim" % "4.0.3",
    "org.hipparchus" % "hipparchus-fft" % "4.0.3",
    "org.knowm.xchart" % "xchart" % "3.8.8",
    "me.tongfei" % "progressbar" % "0.10.2",
    "com.fazecast" % "jSerialComm" % "2.11.4",
    // `moire monitor`'s web server (cask 0.9.1 asks for upickle 3.0.0; the build's 3.1.0 is the same major)
    "com.lihaoyi" %% "cask" % "0.9.1"
  )
)

/** The command line: parses options, calls the libraries, turns their errors into one line and an exit code. */
lazy val cli = layer("cli", "src/cli").dependsOn(host).settings(
  classLambdas,
  libraryDependencies += "com.lihaoyi" %% "mainargs" % "0.7.6",
  Compile / mainClass := Some("moire.cli.Main"),
  // `moire --version`: the version and the git commit of the build ("unknown" outside a git checkout)
  Compile / resourceGenerators += Def.task {
    val commit = scala.util.Try(scala.sys.process.Process(Seq("git", "rev-parse", "--short=12", "HEAD"), (ThisBuild / baseDirectory).value)
      .!!(scala.sys.process.ProcessLogger(_ => ())).trim).toOption.filter(_.nonEmpty).getOrElse("unknown")
    val f = (Compile / resourceManaged).value / "moire-version.properties"
    val text = s"version=${version.value}\ncommit=$commit\n"
    if (!f.exists || IO.read(f) != text) IO.write(f, text)
    Seq(f)
  }.taskValue
)

lazy val root = (project in file("."))
  .aggregate(hw, boards, host, cli)
  .dependsOn(cli)
  .enablePlugins(JavaAppPackaging)
  .settings(common)
  .settings(
    name := "moire",
    Compile / unmanagedSourceDirectories := Nil,
    Compile / unmanagedResourceDirectories := Nil,
    Test / scalaSource := baseDirectory.value / "test",
    Test / javaSource := baseDirectory.value / "test",
    Test / resourceDirectory := baseDirectory.value / "test" / "resources",
    libraryDependencies ++= Seq(
      "edu.berkeley.cs" %% "chiseltest" % "6.0.0" % Test,
      "org.scalatest" %% "scalatest" % "3.2.19" % Test,
      "org.scalatestplus" %% "scalacheck-1-18" % "3.2.19.0" % Test,
      "org.scalacheck" %% "scalacheck" % "1.18.1" % Test,
      // the browser tests (*Browser*): WebDriver to Debian's chromium through /usr/bin/chromedriver
      "org.seleniumhq.selenium" % "selenium-chrome-driver" % "4.52.0" % Test,
      "org.seleniumhq.selenium" % "selenium-support" % "4.52.0" % Test
    ),
    Compile / mainClass := Some("moire.cli.Main"),
    // `./sbt run` alone writes the flagship DE2-115 project, as it always has; the staged `moire` alone prints the overview
    Compile / run / mainClass := Some("moire.cli.SbtRun"),
    run / fork := true,
    run / outputStrategy := Some(StdoutOutput),
    run / javaOptions ++= Seq("-Xss8m", defaultHeap, "-Dfile.encoding=UTF-8"),
    Test / fork := true,
    Test / javaOptions ++= Seq("-Xss8m", "-Xmx6g"),
    Test / testOptions += Tests.Argument(TestFrameworks.ScalaTest, "-oD"),
    // Two forked JVMs side by side (2 cores), about equal in time: the CORDIC suites, the place-and-route and yosys
    // suites (ULX3S bitstream, timing, cost), the corrected board's restore, the adaptive corrector's RTL sweep and
    // the designs' lint (moved there when the live place and route went to a smaller CORDIC: 268 -> 77 s; 746 and 908 s
    // of suites at bee7b97 before the lint moved), then the rest. A package's suites that share caches (replay's Verilator
    // builds, the timing cache) stay in one JVM. The tests' Verilator models (chiseltest's) are compiled without C++
    // optimisation: about 3 times faster to build a CORDIC bank, and the other RTL suites' CPU time 10 min 58 s -> 8 min
    // 8 s (their simulations run a little slower). The replay harness keeps its own flags (make's command line wins).
    Test / testGrouping := {
      val first = Seq("moire.cordic.", "moire.board.Ulx3sBuildSpec", "moire.board.BoardCorrectedPresetSpec", "moire.timing.", "moire.cost.",
        "moire.adapt.AdaptRtlSpec", "moire.designs.DesignLintSpec")
      val (a, b) = (Test / definedTests).value.partition(t => first.exists(t.name.startsWith))
      val fork = ForkOptions().withRunJVMOptions((Test / javaOptions).value.toVector).withWorkingDirectory(baseDirectory.value)
      // Verilator's runtime objects compiled once for the run and each model's header precompiled (test/objcache.sh):
      // a CORDIC bank's build 37 -> 14 s
      val objcache = Map("OBJCACHE" -> (baseDirectory.value / "test" / "objcache.sh").toString,
        "MOIRE_OBJCACHE" -> (target.value / "verilator-objcache").toString)
      val quickBuild = fork.withEnvVars(objcache + ("MAKEFLAGS" -> "OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0"))
      Seq(Tests.Group("cordic-pnr", a, Tests.SubProcess(quickBuild)), Tests.Group("rest", b, Tests.SubProcess(quickBuild))).filter(_.tests.nonEmpty)
    },
    Test / parallelExecution := true,
    // sbt's default restrictions allow one forked group at a time; replace them.
    Global / concurrentRestrictions := Seq(Tags.limitAll(2), Tags.limit(Tags.ForkedTestGroup, 2), Tags.exclusiveGroup(Tags.Clean)),
    // `./sbt stage`: target/universal/stage/bin/moire runs the cli without sbt (the JVM options of `run`).
    executableScriptName := "moire",
    Universal / javaOptions ++= (run / javaOptions).value.map("-J" + _),
    // A quick start: no second JVM for the launcher's Java version check; the classes a start loads from
    // a CDS archive (lib/moire.jsa, written by `stage`); `--help` stops at the first JIT tier.
    bashScriptExtraDefines ++= Seq(
      IO.read(baseDirectory.value / "src" / "cli" / "utf8-locale.sh"),
      // JAVA_OPTS=-Xmx8g is honoured (the default heap from application.ini would come after it and win)
      s"_moire_default_heap=$defaultHeap", IO.read(baseDirectory.value / "src" / "cli" / "heap.sh"),
      // Java options before the command, every word from it on moire's (-h, -v, -d, -J... too); a -J that carries no
      // Java option: one line, exit 2
      IO.read(baseDirectory.value / "src" / "cli" / "launcher-args.sh"),
      "no_version_check=1",
      // the major version of the java this script runs (JAVA_HOME's, else PATH's), from its release file: no second JVM
      """_moire_jv=$(j="$JAVA_HOME"; [[ -n "$j" && -x "$j/bin/java" ]] || j=$(dirname "$(dirname "$(readlink -f "$(command -v java)" 2>/dev/null)")"); sed -n 's/^JAVA_VERSION="\([0-9]*\).*/\1/p' "$j/release" 2>/dev/null)""",
      // on JDK 25 and later an AOT cache (lib/moire.aot, written by `stage` on such a JDK: classes loaded and linked,
      // the explain's method profiles) starts the JIT on the hot code at once; else the CDS archive of the classes a
      // start loads. Another JDK than the one staged with (or, for the CDS archive, the jars at other paths) starts
      // without them, and says nothing of it
      """if [[ -f "$lib_dir/moire.aot" && "${_moire_jv:-0}" -ge 25 ]]; then addJava "-XX:AOTCache=$lib_dir/moire.aot"; addJava "-Xlog:aot*=off"; addJava "-Xlog:cds*=off"""" +
        """; elif [[ -f "$lib_dir/moire.jsa" && "${_moire_jv:-0}" -lt 25 ]]; then addJava "-XX:SharedArchiveFile=$lib_dir/moire.jsa"; addJava "-Xlog:cds*=off"; fi""",
      """case " $* " in *" --help "*) addJava "-XX:TieredStopAtLevel=1"; addJava "-XX:+UseSerialGC";; esac"""),
    stage := {
      val dir = stage.value
      val jsa = dir / "lib" / "moire.jsa"; val aot = dir / "lib" / "moire.aot"
      IO.delete(Seq(jsa, aot))
      val log = streams.value.log
      // the java the launcher will run, found as it finds it (JAVA_HOME, else PATH), and its major version
      val javaHome = sys.env.get("JAVA_HOME").map(file).filter(h => (h / "bin" / "java").canExecute).orElse(
        sys.env.getOrElse("PATH", "").split(java.io.File.pathSeparator).map(d => file(d) / "java").find(_.canExecute)
          .map(j => j.getCanonicalFile.getParentFile.getParentFile))
      val major = javaHome.flatMap(h => scala.util.Try(IO.readLines(h / "release")).toOption).getOrElse(Nil)
        .collectFirst { case l if l.startsWith("JAVA_VERSION=") => l.drop(14).takeWhile(_.isDigit) }.filter(_.nonEmpty).map(_.toInt).getOrElse(0)
      val quiet = scala.sys.process.ProcessLogger(_ => ())
      val launcher = (dir / "bin" / "moire").getPath
      if (major >= 25) {
        // a training run: a short explain loads what explain loads and records its methods' profiles
        val code = scala.sys.process.Process(Seq(launcher, "explain-bench", "--samples", "250000"), None,
          "JAVA_OPTS" -> s"-XX:AOTCacheOutput=$aot").!(quiet)
        log.info(if (code == 0 && aot.exists) s"wrote $aot (JDK $major: classes and the explain's profiles ahead of time)" else s"no $aot (exit $code); the launcher starts without it")
      } else {
        val code = scala.sys.process.Process(Seq(launcher, "--help"), None, "JAVA_OPTS" -> s"-XX:ArchiveClassesAtExit=$jsa").!(quiet)
        log.info(if (code == 0 && jsa.exists) s"wrote $jsa (class data sharing: a faster start)" else s"no $jsa (exit $code); the launcher starts without it")
      }
      dir
    },
    // the layers' own launchers are not wanted: stage the root only
    stage / aggregate := false
  )
