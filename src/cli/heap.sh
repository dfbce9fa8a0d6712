# The launcher's default heap (application.ini's -J-Xmx, in $_moire_default_heap) gives way to one in JAVA_OPTS:
# JAVA_OPTS comes first on java's command line, so the default would otherwise win. A -J-Xmx on the command line
# still comes last and wins over both.
if [[ " ${JAVA_OPTS:-} " == *" -Xmx"* && -n "${_moire_default_heap:-}" ]]; then
  eval "_moire_$(declare -f addJava)"
  addJava () { [[ "$1" == "$_moire_default_heap" ]] || _moire_addJava "$@"; }
fi
