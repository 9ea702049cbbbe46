#!/usr/bin/env bash
# Measures `sweep snapshot` against the naive loop a user would write without it: one
# `sweep render` process per picture (320x240, the three modes) over the starter files and the
# artifacts. Prints the wall time of the loop, of `sweep snapshot`'s first run (renders and writes
# the references) and its second run (renders and compares), the speed-up, and the floor: the
# time of the renders alone, as `sweep snapshot` reports it. Builds nothing.
# Usage: scripts/measure-snapshot.sh [BUILD_DIR]   (default: $SWEEP_BUILD_DIR or build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-${SWEEP_BUILD_DIR:-$root/build}}"
sweep="$build/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
mkdir -p "$out/models/artifacts" "$out/loop"
cp "$root"/swp/*.swp "$out/models/"
cp "$root"/swp/artifacts/* "$out/models/artifacts/"
mapfile -t files < <(cd "$out/models" && find . -name '*.swp' | sort)
pictures=$((${#files[@]} * 3))

seconds() { echo $(( ${EPOCHREALTIME/./} )); }
start=$(seconds)
for f in "${files[@]}"; do
  name=${f#./}; name=${name%.swp}; name=${name//\//_}
  "$sweep" render "$out/models/$f" -o "$out/loop/$name-smooth.png" --size 320x240 >/dev/null
  "$sweep" render "$out/models/$f" -o "$out/loop/$name-wire.png" --size 320x240 --surface wire >/dev/null
  "$sweep" render "$out/models/$f" -o "$out/loop/$name-frames.png" --size 320x240 --surface off \
    --curves frames --points on >/dev/null
done
loop=$(( $(seconds) - start ))

start=$(seconds)
"$sweep" snapshot "$out/models" -q >"$out/first.txt" || true
first=$(( $(seconds) - start ))
start=$(seconds)
"$sweep" snapshot "$out/models" -q >"$out/second.txt" || true
second=$(( $(seconds) - start ))

awk -v n="$pictures" -v loop="$loop" -v first="$first" -v second="$second" 'BEGIN {
  printf "%d pictures (%d files x 3 modes) at 320x240\n", n, n / 3
  printf "naive loop (one sweep render per picture): %.2f s (%.0f ms a picture)\n", loop / 1e6, loop / 1e3 / n
  printf "sweep snapshot, first run (writes references): %.2f s, %.1fx faster\n", first / 1e6, loop / first
  printf "sweep snapshot, second run (compares):         %.2f s, %.1fx faster\n", second / 1e6, loop / second
}'
tail -n 1 "$out/second.txt"
