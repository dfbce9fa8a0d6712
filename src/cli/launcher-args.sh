# The launcher script's own options that would reach Java as no option of it: one line and exit 2, not a Java
# class-not-found trace (`-Jfoo`, a bare `-J`, `-main CLASS`). A -J with a Java option (-J-Xmx8g) passes as before.
for _moire_a in "$@"; do
  case "$_moire_a" in
    -J) echo "moire: -J needs a Java option joined to it (like -J-Xmx8g)" >&2; exit 2 ;;
    -J[!-]*) echo "moire: $_moire_a: -J passes an option to Java (like -J-Xmx8g), and '${_moire_a:2}' is none" >&2; exit 2 ;;
    -main) echo "moire: -main is no option of moire's (its commands: moire --help)" >&2; exit 2 ;;
  esac
done
