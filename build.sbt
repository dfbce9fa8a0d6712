// moire: Chisel generators for optical-grating signal processing.
ThisBuild / scalaVersion := "2.13.15"
ThisBuild / version := "0.1.0"
ThisBuild / organization := "io.github.moire"

val chiselVersion = "6.7.0"

lazy val root = (project in file("."))
  .settings(
    name := "moire",
    Compile / scalaSource := baseDirectory.value / "src",
    Compile / javaSource := baseDirectory.value / "src",
    Compile / resourceDirectory := baseDirectory.value / "src" / "resources",
    // Board wrappers live apart from the designs: Scala under boards/, vendor Verilog under boards/resources.
    Compile / unmanagedSourceDirectories += baseDirectory.value / "boards",
    Compile / unmanagedResourceDirectories += baseDirectory.value / "boards" / "resources",
    Test / scalaSource := baseDirectory.value / "test",
    Test / javaSource := baseDirectory.value / "test",
    Test / resourceDirectory := baseDirectory.value / "test" / "resources",
    libraryDependencies ++= Seq(
      "org.chipsalliance" %% "chisel" % chiselVersion,
      "com.lihaoyi" %% "mainargs" % "0.7.6",
      "com.lihaoyi" %% "upickle" % "3.1.0",
      "org.hipparchus" % "hipparchus-core" % "4.0.3",
      "org.hipparchus" % "hipparchus-stat" % "4.0.3",
      "org.hipparchus" % "hipparchus-fitting" % "4.0.3",
      "org.hipparchus" % "hipparchus-optim" % "4.0.3",
      "org.hipparchus" % "hipparchus-fft" % "4.0.3",
      "org.knowm.xchart" % "xchart" % "3.8.8",
      "me.tongfei" % "progressbar" % "0.10.2",
      "com.fazecast" % "jSerialComm" % "2.11.4",
      // Compile scope: `bench` measures chiseltest peek/poke from the CLI.
      "edu.berkeley.cs" %% "chiseltest" % "6.0.0",
      "org.scalatest" %% "scalatest" % "3.2.19" % Test,
      "org.scalatestplus" %% "scalacheck-1-18" % "3.2.19.0" % Test,
      "org.scalacheck" %% "scalacheck" % "1.18.1" % Test
    ),
    addCompilerPlugin("org.chipsalliance" % "chisel-plugin" % chiselVersion cross CrossVersion.full),
    scalacOptions ++= Seq("-deprecation", "-feature", "-unchecked", "-language:reflectiveCalls", "-Ymacro-annotations"),
    Compile / mainClass := Some("moire.cli.Main"),
    run / fork := true,
    run / outputStrategy := Some(StdoutOutput),
    run / javaOptions ++= Seq("-Xss8m", "-Xmx4g"),
    Test / fork := true,
    Test / javaOptions ++= Seq("-Xss8m", "-Xmx6g"),
    Test / testOptions += Tests.Argument(TestFrameworks.ScalaTest, "-oD"),
    Test / parallelExecution := false
  )
