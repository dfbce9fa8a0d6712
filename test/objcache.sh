#!/usr/bin/env bash
# OBJCACHE of the tests' Verilator builds (build.sbt sets it and MOIRE_OBJCACHE, the folder): make runs every compile
# as `$OBJCACHE g++ ...`. Verilator's runtime (verilated*.cpp in its include folder) compiles alike for every model,
# but chiseltest forces the model's header into each compile (-include Vtop.h, -DTOP_TYPE), which the runtime does not
# read. Those are compiled once without them and copied (about 11 s of a 37 s build at -O0).
set -euo pipefail
src="${!#}"
case "$src" in
  */verilator/include/verilated*.cpp) ;;
  *)
    # a model's own compile, with chiseltest's forced header (-include Vtop.h): that header precompiled once (the
    # copy and its .gch in the cache, keyed by its text and the flags; g++ takes the .gch when the flags match and
    # else reads the header): a CORDIC bank's model compiled in 14 s instead of 25, the header's 5 s included. Other
    # compiles run as they are.
    hdr=""; out=""; flags=(); prev=""
    for a in "${@:1:$#-1}"; do
      case "$prev" in -include) hdr="$a"; prev=""; continue ;; -o) out="$a"; prev=""; continue ;; esac
      case "$a" in -include|-o) ;; -MMD|-MP|-c) ;; *) flags+=("$a") ;; esac
      prev="$a"
    done
    [ -n "$hdr" ] && [ -f "$hdr" ] && [ -n "$out" ] || exec "$@"
    dir="${MOIRE_OBJCACHE:?MOIRE_OBJCACHE names the cache folder}"
    pdir="$dir/pch-$( { printf '%s\0' "${flags[@]}"; "${flags[0]}" --version; cat "$hdr"; } | sha256sum | cut -c1-32)"
    name="$(basename "$hdr")"
    if [ ! -f "$pdir/$name" ]; then
      mkdir -p "$pdir"
      cp "$hdr" "$pdir/$name.tmp-$$" && mv -f "$pdir/$name.tmp-$$" "$pdir/$name"
      # a .gch is 65 MB and needed while its model compiles (under a minute): those older than 3 minutes go
      find "$dir" -name '*.gch' -mmin +3 -delete 2>/dev/null || true
      "${flags[@]}" -x c++-header "$pdir/$name" -o "$pdir/$name.gch.tmp-$$" && mv -f "$pdir/$name.gch.tmp-$$" "$pdir/$name.gch" \
        || rm -f "$pdir/$name.gch.tmp-$$"
    fi
    args=(); prev=""
    for a in "$@"; do if [ "$prev" = "-include" ]; then args+=("$pdir/$name"); else args+=("$a"); fi; prev="$a"; done
    exec "${args[@]}" ;;
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
