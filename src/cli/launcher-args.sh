# The launcher script's own options. Java options go before the command (moire -J-Xmx8g explain ...); from the command
# on every word is moire's: the script took -v, -d, -mem, -java-home, -jvm-debug, -J... and -D... from anywhere, even
# as an option's value (`emit --out -v` printed the java command line). A `--` put before the command stops it there.
# A -J that carries no Java option is one line and exit 2, not a Java class-not-found trace (`-Jfoo`, a bare `-J`).
_moire_pre=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -J) echo "moire: -J needs a Java option joined to it (like -J-Xmx8g)" >&2; exit 2 ;;
    -J[!-]*) echo "moire: $1: -J passes an option to Java (like -J-Xmx8g), and '${1:2}' is none" >&2; exit 2 ;;
    -J-*|-D*|-XX*) _moire_pre+=("$1"); shift ;;
    *) break ;;
  esac
done
set -- "${_moire_pre[@]}" -- "$@"
