#!/usr/bin/env bash
# Measures the viewer's CPU time with riders, paused and playing, in a real window under Xvfb
# (software rendering, no GPU): the viewer opened on a file with riders and left alone while
# paused (it should sleep: nothing moves, nothing is drawn), then Shift+Space and the same time
# playing (a fast frame every 1/60 s at most), then Shift+Space again and, after the one still
# frame, paused again. User + system time from /proc/PID/stat, as a share of one core, and the
# time the timeline shows when paused (it runs at real time).
# Usage: scripts/measure-playback.sh [FILE.swp]   (default: two riders on a trefoil knot;
# SWEEP_BUILD_DIR picks the build, SECONDS_MEASURED the length of each measurement, default 3)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sweep="${SWEEP_BUILD_DIR:-$root/build}/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
if [ -z "${MEASURE_INSIDE_XVFB:-}" ]; then
  exec env MEASURE_INSIDE_XVFB=1 xvfb-run -a -s '-screen 0 1280x800x24' bash "$0" "$@"
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
file="${1:-}"
if [ -z "$file" ]; then
  file="$out/riders.swp"
  cat >"$file" <<'SWP'
knot track 200 2 3 2 0.6
circ body 16 0.15
poly3 spine 2
[0 0 -0.4]
[0 0 0.4]
gcyl plane body spine caps
rider r1 track plane seconds 6
rider r2 track plane seconds 6 start 0.5 up 0 1 0
SWP
fi
seconds="${SECONDS_MEASURED:-3}"
export XDG_STATE_HOME="$out/state" XDG_CONFIG_HOME="$out/config"

# --select prints the status lines (the time paused at) on stdout.
first=$(awk '!/^[ \t]*(#|$)/ { print $2; exit }' "$file")
"$sweep" view "$file" --size 1280x800 --select "$first" >"$out/view.out" 2>&1 &
pid=$!
for _ in $(seq 200); do grep -q '^panel ' "$out/view.out" && break; sleep 0.05; done
window=$(xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
sleep 1  # the still frame and start-up
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
hz=$(getconf CLK_TCK)
share() { awk -v t="$1" -v hz="$hz" -v s="$seconds" 'BEGIN { printf "%.1f %% of one core", 100 * t / (s * hz) }'; }

before=$(ticks); sleep "$seconds"; after=$(ticks)
echo "paused:  $(share $((after - before))) over $seconds s"

xdotool key --window "$window" shift+space
sleep 0.5
before=$(ticks); sleep "$seconds"; after=$(ticks)
echo "playing: $(share $((after - before))) over $seconds s"
xdotool key --window "$window" shift+space
for _ in $(seq 100); do grep -q '^status riders paused at' "$out/view.out" && break; sleep 0.05; done
grep '^status riders paused at' "$out/view.out" | sed 's/^status /  (/; s/$/ on the timeline)/'
sleep 1  # the still frame after the pause

before=$(ticks); sleep "$seconds"; after=$(ticks)
echo "paused again: $(share $((after - before))) over $seconds s"
xdotool key --window "$window" Escape
wait "$pid" 2>/dev/null || true
