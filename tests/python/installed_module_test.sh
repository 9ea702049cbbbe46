#!/usr/bin/env bash
# The Python module as its users get it (issue 57): `cmake --install` into a fresh prefix, then
# Debian's interpreter imports sweep from that prefix's package folder (not the build tree), the
# extension finds the installed libsweep through its RPATH, and a document loads and renders.
# Usage: installed_module_test.sh BUILD_DIR SWP_DIR WORK_DIR
set -euo pipefail
build=$1 swp=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
folder=$(sed -n 's/^-- Python module: //p' "$work/install.log")
[ -n "$folder" ] && [ -f "$folder/__init__.py" ] || { echo "no Python module in the install log"; cat "$work/install.log"; exit 1; }
case "$folder" in "$prefix"/lib/python3.*/site-packages/sweep) ;; *) echo "module installed in $folder"; exit 1 ;; esac
extension=$(ls "$folder"/_sweep*.so)
found=$(ldd "$extension" | awk '/libsweep\.so\.0 =>/ { print $3 }')
[ "$(realpath "$found")" = "$(realpath "$prefix/lib/libsweep.so.0")" ] || { echo "libsweep found at $found"; exit 1; }
cd "$work"
PYTHONPATH="$(dirname "$folder")" /usr/bin/python3 - "$swp" "$prefix" <<'PY'
import sys
import sweep
swp, prefix = sys.argv[1], sys.argv[2]
assert sweep.__file__.startswith(prefix), sweep.__file__
doc = sweep.load(f"{swp}/wineglass.swp")
assert doc.surface("wineglass").positions.shape == (16650, 3)
image = doc.render(64, 48)
assert image.shape == (48, 64, 4) and len({tuple(p) for p in image.reshape(-1, 4)}) > 10
print("sweep", sweep.__version__, "imported from", sweep.__file__)
PY
