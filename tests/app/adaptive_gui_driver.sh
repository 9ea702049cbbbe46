#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): clicks the Edit panel's
# Adaptive checkbox on, then off again, and quits with Escape. Runs inside xvfb-run.
# Usage: adaptive_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints the viewer's "counts ..." lines (the stats panel's numbers): before, on, off.
set -u
sweep=$1 file=$2 object=$3 out=$4
log=$out/viewer.out
"$sweep" view "$file" --size 1000x700 --samples 0 --select "$object" >"$log" 2>"$out/viewer.err" &
pid=$!

source "$(dirname "$0")/gui_driver_support.sh"  # fail, wait_count, wait_for

# click X Y: press and release the left button there, a frame or two apart.
click() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep 0.2
  xdotool mousedown 1
  sleep 0.2
  xdotool mouseup 1
}

wait_count '^counts ' 1 30 || fail "the viewer printed no counts"
window=$(timeout 10 xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
[ -n "$window" ] || fail "no Sweep window found"
read -r ax ay < <(awk '/^adaptive /{printf "%.0f %.0f\n", $2, $3}' "$log")
[ -n "${ax:-}" ] && [ "$ax" -ge 0 ] || fail "no Adaptive checkbox"

click "$ax" "$ay"
wait_count '^counts ' 2 20 || fail "turning Adaptive on changed no count"
click "$ax" "$ay"
wait_count '^counts ' 3 20 || fail "turning Adaptive off changed no count"
xdotool key Escape
for ((i = 0; i < 200; ++i)); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -0 "$pid" 2>/dev/null && fail "Escape did not quit"
wait "$pid" || fail "the viewer exited with an error"
grep '^counts ' "$log"
