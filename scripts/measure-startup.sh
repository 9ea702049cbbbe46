#!/usr/bin/env bash
# Measures the start-up of the command line: `sweep info` on a one-line SWP file, run N times.
# Prints the mean and median wall time in ms and the largest max RSS in MB. Builds nothing.
# Usage: scripts/measure-startup.sh [BUILD_DIR] [N]   (default: $SWEEP_BUILD_DIR or build/, 200 runs)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-${SWEEP_BUILD_DIR:-$root/build}}"
runs="${2:-200}"
sweep="$build/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (apt-get install time; scripts/install-deps.sh)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
printf 'circ c 10 1\n' >"$out/one.swp"
"$sweep" info "$out/one.swp" >/dev/null  # warm the page cache; fails loudly if sweep cannot run

# One line per run: elapsed seconds and max RSS in KiB, from GNU time (which adds only its fork).
for _ in $(seq "$runs"); do
  /usr/bin/time -a -o "$out/times" -f '%e %M' "$sweep" info "$out/one.swp" >/dev/null
done
# %e has 10 ms resolution, so the wall time is taken here around each run, in microseconds
# ($EPOCHREALTIME: no process of its own, so only the fork and exec of sweep are added).
wall_times() {  # wall_times FILE COMMAND...: appends one time per run to FILE
  local file="$1"
  shift
  for _ in $(seq "$runs"); do
    start=${EPOCHREALTIME/./}
    "$@" >/dev/null
    echo $((${EPOCHREALTIME/./} - start)) >>"$file"
  done
}
summary() {  # summary FILE WHAT
  sort -n "$1" | awk -v what="$2" -v runs="$runs" '
    { us[NR] = $1; sum += $1 }
    END {
      median = (NR % 2) ? us[(NR + 1) / 2] : (us[NR / 2] + us[NR / 2 + 1]) / 2
      printf "%s, %d runs: %.2f ms mean, %.2f ms median\n", what, runs, sum / NR / 1e3, median / 1e3
    }'
}
wall_times "$out/wall" "$sweep" info "$out/one.swp"
# The same loop around a program that does nothing: what starting any process costs here.
wall_times "$out/floor" /bin/true

summary "$out/wall" "sweep info, one-line file"
summary "$out/floor" "/bin/true (the machine's floor)"
awk '$2 > max { max = $2 } END { printf "max RSS: %.1f MB\n", max / 1024 }' "$out/times"
