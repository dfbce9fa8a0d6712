#!/usr/bin/env bash
# OBJCACHE of the tests' Verilator builds (build.sbt sets it and MOIRE_OBJCACHE, the folder): make runs every compile
# as `$OBJCACHE g++ ...`. Verilator's runtime (verilated*.cpp in its include folder) compiles alike for every model,
# but chiseltest forces the model's header into each compile (-include Vtop.h, -DTOP_TYPE), which the runtime does not
# read. Those are compiled once without them and copied (about 11 s of a 37 s build at -O0); every other compile runs
# as it is.
set -euo pipefail
src="${!#}"
case "$src" in
  */verilator/include/verilated*.cpp) ;;
  *) exec "$@" ;;
esac
dir="${MOIRE_OBJCACHE:?MOIRE_OBJCACHE names the cache folder}"
args=(); out=""
while [ $# -gt 0 ]; do
  case "$1" in
    -include) shift 2; continue ;;
    -o) out="$2"; shift 2; continue ;;
    -DTOP_TYPE=*|-MMD|-MP) ;;
    *) args+=("$1") ;;
  esac
  shift
done
[ -n "$out" ] || { echo "objcache.sh: no -o in the compile of $src" >&2; exit 2; }
inc="$(dirname "$src")"
key="$( { printf '%s\0' "${args[@]}"; "${args[0]}" --version; cat "$src" "$inc"/*.h; } | sha256sum | cut -c1-32)"
obj="$dir/$(basename "$src" .cpp)-$key.o"
if [ ! -f "$obj" ]; then
  mkdir -p "$dir"
  tmp="$obj.tmp-$$"
  "${args[@]}" -o "$tmp"
  mv -f "$tmp" "$obj"
fi
cp "$obj" "$out"
