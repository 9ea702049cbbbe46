#!/usr/bin/env bash
# Measures the command line on big scenes in fresh processes (fresh memory: every mesh is new
# pages from the kernel), as a user runs it: `sweep info` (parse and evaluate), and `sweep export`
# as OBJ, STL, glb and 3MF (at 80 mm), and `sweep check` (the printability checks alone), of weird.swp and wineglass.swp with every STEPS x10, written into a
# temporary folder. Prints the median wall time, CPU time (user + system), peak memory (maximum
# resident size) and minor page faults of N runs of each.
# Builds nothing.
# Usage: scripts/measure-exports.sh [BUILD_DIR] [N]   (default: $SWEEP_BUILD_DIR or build/, 5 runs)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-${SWEEP_BUILD_DIR:-$root/build}}"
runs="${2:-5}"
sweep="$build/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (apt-get install time; scripts/install-deps.sh)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# Every STEPS x10: the curves' (NAME STEPS ...) and a surface of revolution's copies.
scaled() {  # scaled FILE: writes $out/NAME.swp
  awk '$1 ~ /^(bez2|bez3|bsp2|bsp3|cr2|cr3|kb2|kb3|circ|srev)$/ && $3 ~ /^[0-9]+$/ { $3 = $3 * 10 } { print }' \
    "$1" >"$out/$(basename "$1")"
}
scaled "$root/swp/weird.swp"
scaled "$root/swp/wineglass.swp"

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

measure() {  # measure LABEL COMMAND...: median wall and CPU time over the runs
  local label="$1"
  shift
  : >"$out/cpu"
  : >"$out/wall"
  for _ in $(seq "$runs"); do
    # Wall time from $EPOCHREALTIME (microseconds; GNU time's %e has 10 ms steps), CPU time
    # (user + system) from GNU time. Warnings (an open surface as STL) are not what is measured.
    start=${EPOCHREALTIME/./}
    /usr/bin/time -q -a -o "$out/cpu" -f '%U %S %M %R' "$@" >/dev/null 2>&1 || true  # check exits 1 on a warning
    echo $((${EPOCHREALTIME/./} - start)) >>"$out/wall"
  done
  local wall cpu rss faults
  wall=$(median <"$out/wall")
  cpu=$(awk '{ print $1 + $2 }' "$out/cpu" | median)
  rss=$(awk '{ print $3 }' "$out/cpu" | median)
  faults=$(awk '{ print $4 }' "$out/cpu" | median)
  printf '%-44s wall %7.0f ms   cpu %7.0f ms   peak %5.0f MB   faults %6d\n' "$label" "$((wall / 1000))" \
    "$(awk -v c="$cpu" 'BEGIN { print c * 1000 }')" "$(awk -v k="$rss" 'BEGIN { print k / 1024 }')" "$faults"
}

for file in weird wineglass; do
  measure "$file x10: info (parse, evaluate)" "$sweep" info "$out/$file.swp"
  for format in obj stl glb; do
    measure "$file x10: export --format $format" "$sweep" export "$out/$file.swp" "$out/x" --format "$format"
  done
  measure "$file x10: export --format 3mf --height 80" "$sweep" export "$out/$file.swp" "$out/x" --format 3mf --height 80
  measure "$file x10: check --height 80" "$sweep" check "$out/$file.swp" --height 80
  echo "  ($(du -ch "$out"/x_*.obj | tail -n 1 | cut -f1) of OBJ, $(du -ch "$out"/x_*.stl | tail -n 1 | cut -f1) of STL)"
  rm -f "$out"/x_*
done
