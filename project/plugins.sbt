// `./sbt stage` writes the `moire` launcher (target/universal/stage/bin/moire): JavaAppPackaging.
addSbtPlugin("com.github.sbt" % "sbt-native-packager" % "1.10.4")
