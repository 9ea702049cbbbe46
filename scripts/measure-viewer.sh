#!/usr/bin/env bash
# Measures the viewer in a real window under Xvfb (software rendering, no GPU):
#  1. idle CPU: the viewer open on a file, untouched for 10 s (it should sleep: redraw on demand);
#  2. frame times while the camera is dragged and while a control point is dragged (moving frames,
#     drawn without multisampling) and of the still picture (4x MSAA), from `--frame-time`;
#  3. smooth shading against the wireframe (with its normals): the same file drawn continuously at
#     1600x1000 for 6 s in each mode, three times; the median of the runs' median frame times.
# Usage: scripts/measure-viewer.sh [FILE.swp]   (default swp/wineglass.swp; SWEEP_BUILD_DIR picks the build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sweep="${SWEEP_BUILD_DIR:-$root/build}/sweep"
file="${1:-$root/swp/wineglass.swp}"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
if [ -z "${MEASURE_INSIDE_XVFB:-}" ]; then
  exec env MEASURE_INSIDE_XVFB=1 xvfb-run -a -s '-screen 0 1280x800x24' bash "$0" "$@"
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# 1. Idle CPU, in clock ticks of user + system time over 10 s.
"$sweep" view "$file" --size 1280x800 >"$out/idle.out" 2>&1 &
pid=$!
sleep 4  # start-up and the first frames
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
before=$(ticks)
sleep 10
after=$(ticks)
kill "$pid"; wait "$pid" 2>/dev/null || true
hz=$(getconf CLK_TCK)
awk -v t=$((after - before)) -v hz="$hz" 'BEGIN { printf "idle: %.1f %% of one core over 10 s\n", 100 * t / (10 * hz) }'

# 2. Drags, with frame times printed on exit. The profile's handles are printed by --select.
"$sweep" view "$file" --size 1280x800 --frame-time --select profile >"$out/drag.out" 2>&1 &
pid=$!
for _ in $(seq 200); do grep -q '^panel ' "$out/drag.out" && break; sleep 0.05; done
window=$(xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
drag() {  # drag X Y DX DY STEPS: left button from (X, Y), moving by (DX, DY) in STEPS steps
  # One xdotool process for the whole drag, so starting processes does not load the machine.
  local moves=()
  for k in $(seq "$5"); do moves+=(mousemove --window "$window" $(($1 + $3 * k / $5)) $(($2 + $4 * k / $5)) sleep 0.03); done
  xdotool mousemove --window "$window" "$1" "$2" mousedown 1 "${moves[@]}" mouseup 1
  sleep 1  # the still frame after the drag, and a few more
}
read -r hx hy < <(awk '/^handle /{x = $3; y = $4} END {printf "%.0f %.0f\n", x, y}' "$out/drag.out")
drag "$hx" "$hy" 30 20 60  # a control point (the profile's last handle), where --select printed it
xdotool key ctrl+z  # undo the point drag, so quitting does not ask
drag 640 700 200 -60 60  # the camera: empty space below the glass
xdotool key Escape
wait "$pid" || true
grep -E "^(frames|moving|still|edits)" "$out/drag.out"

# 3. Smooth against wire, alternating, three runs each.
for run in 1 2 3; do
  for mode in smooth wire; do
    "$sweep" view "$file" --size 1600x1000 --frame-time --surface "$mode" >"$out/$mode.out" 2>&1 &
    pid=$!
    sleep 6
    xdotool key --window "$(xdotool search --onlyvisible --name 'Sweep' | head -n 1)" Escape
    wait "$pid" || true
    sed -n 's/^frames .*median \([0-9.]*\) ms,.*/\1/p' "$out/$mode.out" >>"$out/$mode.medians"
  done
done
for mode in smooth wire; do
  sort -n "$out/$mode.medians" | awk -v m="$mode" '{ v[NR] = $1 } END { printf "%s: median frame time %.1f ms (runs: %s)\n", m, v[2], v[1] " " v[2] " " v[3] }'
done
