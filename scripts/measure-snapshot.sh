#!/usr/bin/env bash
# Measures `sweep snapshot` against the naive loop a user would write without it: one
# `sweep render` process per picture (320x240, the three modes) over the starter files and the
# artifacts. Prints the wall time of the loop, of `sweep snapshot`'s first run (renders and writes
# the references) and its second run (renders and compares), the speed-up, and the floor: the
# time of the renders alone, as `sweep snapshot` reports it. Builds nothing.
# With --library N [N2 ...]: the scale of CI instead. For each N, a library of N generated models
# (the starter and artifact files, cycled, each with its numbers scaled a little so no two are
# alike) in three modes: the first and second runs' wall time, peak memory (max RSS) and time per
# case, and the ratio of the second run's wall time to the renders alone (the OSMesa time the run
# reports, over its workers). Peak memory must not grow with N; the ratio stays under 1.5.
# Usage: scripts/measure-snapshot.sh [--library N ...] [BUILD_DIR]   (default: $SWEEP_BUILD_DIR or build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
libraries=()
if [ "${1:-}" = "--library" ]; then
  shift
  while [[ "${1:-}" =~ ^[0-9]+$ ]]; do libraries+=("$1"); shift; done
fi
build="${1:-${SWEEP_BUILD_DIR:-$root/build}}"
sweep="$build/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# library N DIR: N models in DIR, the starter and artifact files in turn, model i's numbers with
# more than one digit after the point scaled by 1 + i / 100000 (the artifacts' images beside them).
library() {
  local n=$1 dir=$2 i=0
  mkdir -p "$dir"
  cp "$root"/swp/artifacts/*.png "$root"/swp/artifacts/*.jpg "$dir"/ 2>/dev/null || true
  mapfile -t sources < <(ls "$root"/swp/*.swp "$root"/swp/artifacts/*.swp)
  while [ "$i" -lt "$n" ]; do
    local source=${sources[$((i % ${#sources[@]}))]}
    perl -pe 'BEGIN { $f = 1 + '"$i"' / 100000 } s/(?<![\w.])(-?\d+\.\d\d+)/sprintf("%.6f", $1 * $f)/ge' \
      "$source" >"$dir/$(printf %04d "$i")-$(basename "$source")"
    i=$((i + 1))
  done
}

# run_measured LABEL ARGS...: one `sweep snapshot` with wall time, max RSS and its closing line.
run_measured() {
  local label=$1
  shift
  /usr/bin/time -f "%e %M" -o "$out/time.txt" "$sweep" snapshot "$@" -q >"$out/run.txt" || true
  read -r wall rss < <(tail -n 1 "$out/time.txt")
  local cases renders workers
  cases=$(grep -cE '^(pass|FAIL|new|warning|updated|error) ' "$out/run.txt" || true)
  renders=$(tail -n 1 "$out/run.txt" | sed -E 's/.*renders ([0-9.]+) s on ([0-9]+) workers.*/\1 \2/')
  awk -v label="$label" -v wall="$wall" -v rss="$rss" -v cases="$cases" -v renders="$renders" 'BEGIN {
    split(renders, r, " ")
    printf "%-28s %6d cases  wall %7.2f s  %5.1f ms a case  peak %6.1f MB  renders alone %7.2f s  ratio %.2f\n",
      label, cases, wall, wall * 1000 / cases, rss / 1024, r[1] / r[2], wall / (r[1] / r[2])
  }'
}

if [ ${#libraries[@]} -gt 0 ]; then
  for n in "${libraries[@]}"; do
    library "$n" "$out/lib-$n"
    run_measured "$n models, first run" "$out/lib-$n"
    run_measured "$n models, second run" "$out/lib-$n"
  done
  exit 0
fi
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
