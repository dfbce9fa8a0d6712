#!/usr/bin/env bash
# sbt launcher: uses `sbt` from PATH when present; otherwise fetches sbt-launch 1.11.7
# from Maven Central once (with mvn) and runs it with Maven Central as the only repository.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# a UTF-8 character set for sbt's JVM too, which reads the command line first (non-ASCII file names under LANG=C)
. "$here/src/cli/utf8-locale.sh"
version=1.11.7

# Use a real sbt on PATH, but not this script itself.
if self_free_sbt="$(PATH="$(echo "$PATH" | tr ':' '\n' | grep -vxF "$here" | paste -sd:)" command -v sbt)"; then
  if [ -t 0 ]; then exec "$self_free_sbt" "$@"; else exec "$self_free_sbt" "$@" < /dev/null; fi
fi

cache="${MOIRE_SBT_CACHE:-$HOME/.cache/moire-sbt}"
jar="$cache/sbt-launch-$version.jar"
repos="$cache/repositories"
mkdir -p "$cache"

if [ ! -s "$jar" ]; then
  command -v mvn >/dev/null || { echo "sbt: neither sbt nor mvn found on PATH; install a JDK and Maven" >&2; exit 1; }
  echo "sbt: fetching org.scala-sbt:sbt-launch:$version from Maven Central (once)" >&2
  mvn -q -B -Dstyle.color=never dependency:copy \
    -Dartifact="org.scala-sbt:sbt-launch:$version" \
    -DoutputDirectory="$cache" -Dmdep.stripVersion=false >&2
  [ -s "$jar" ] || { echo "sbt: download of sbt-launch $version failed" >&2; exit 1; }
fi

cat > "$repos" <<REPOS
[repositories]
  local
  maven-central: https://repo1.maven.org/maven2/
REPOS

java_opts=(-Xss8m -Xmx6g -XX:+UseParallelGC
  "-Dsbt.repository.config=$repos" -Dsbt.override.build.repos=true
  -Dsbt.boot.directory="$cache/boot" -Dsbt.supershell=false)
if [ -t 0 ]; then
  exec java "${java_opts[@]}" -jar "$jar" "$@"
else
  exec java "${java_opts[@]}" -Dsbt.log.noformat=true -jar "$jar" "$@" < /dev/null
fi
