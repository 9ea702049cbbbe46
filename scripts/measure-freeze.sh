#!/usr/bin/env bash
# Measures whether the viewer freezes during long work (issue 29, "never freezing"): a subd on a
# 10 000-face cage (a 100 x 100 quad torus) has its level slider dragged from 0 to 6 in the real
# window under Xvfb, drawing continuously (--frame-time), and the longest gap between two frames is
# printed. Each level's re-mesh runs in the background (EditSession::set_background); before that
# change the frame of each step waited for it. The drag lasts about 1.5 s; then the script waits
# for the last level to arrive and be drawn, and quits.
# Usage: scripts/measure-freeze.sh   (SWEEP_BUILD_DIR picks the build; SWEEP_FREEZE_SECONDS the wait
# after the drag, default 60; SWEEP_FREEZE_SIZE the window, default 1280x800; SWEEP_FREEZE_SAMPLES
# the multisampling, default 4; SWEEP_BACKGROUND_WORK=0 evaluates on the drawing thread, as before)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sweep="${SWEEP_BUILD_DIR:-$root/build}/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
if [ -z "${MEASURE_INSIDE_XVFB:-}" ]; then
  exec env MEASURE_INSIDE_XVFB=1 xvfb-run -a -s '-screen 0 1280x800x24' bash "$0" "$@"
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export XDG_CONFIG_HOME="$out/config" XDG_STATE_HOME="$out/state"

# The cage: a torus of 100 x 100 quads (radii 3 and 1), and its Catmull-Clark subdivision.
awk 'BEGIN {
  n = 100; pi = atan2(0, -1)
  printf "mesh cage %d %d\n", n * n, n * n
  for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
    u = 2 * pi * i / n; v = 2 * pi * j / n
    printf "[%.6f %.6f %.6f]\n", (3 + cos(v)) * cos(u), sin(v), (3 + cos(v)) * sin(u)
  }
  for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
    a = i * n + j; b = ((i + 1) % n) * n + j; c = ((i + 1) % n) * n + (j + 1) % n; d = i * n + (j + 1) % n
    printf "[%d %d %d %d]\n", a, d, c, b
  }
  print "subd smooth 1 cage"
}' >"$out/cage.swp"

"$sweep" view "$out/cage.swp" --size "${SWEEP_FREEZE_SIZE:-1280x800}" --samples "${SWEEP_FREEZE_SAMPLES:-4}" --frame-time --select smooth >"$out/view.out" 2>&1 &
pid=$!
for _ in $(seq 400); do grep -q '^item .* level$' "$out/view.out" && break; sleep 0.05; done
read -r x y < <(awk '$1 == "item" && $4 == "level" {x = $2; y = $3} END {printf "%.0f %.0f\n", x, y}' "$out/view.out")
[ -n "$x" ] || { echo "the level slider was not found" >&2; cat "$out/view.out" >&2; kill "$pid"; exit 1; }
window=$(xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
moves=()
for k in $(seq 50); do moves+=(mousemove --window "$window" $((x + 6 * k)) "$y" sleep 0.03); done
xdotool mousemove --window "$window" "$x" "$y" mousedown 1 "${moves[@]}" mouseup 1
sleep "${SWEEP_FREEZE_SECONDS:-60}"  # level 6: about 41 million vertices to refine, upload and draw
xdotool key --window "$window" ctrl+z  # one undo step for the drag, so quitting does not ask
sleep 2
xdotool key --window "$window" Escape
wait "$pid" || true
echo "meshes shown (the stats line whenever it changed):"
grep -E "^counts" "$out/view.out" | uniq
grep -E "^(frames|moving|still|edits|longest)" "$out/view.out"
