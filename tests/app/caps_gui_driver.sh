#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): clicks the selected
# surface's caps checkbox in the Edit panel, saves with Ctrl+S and quits with Escape. Runs
# inside xvfb-run. Usage: caps_gui_driver.sh SWEEP FILE.swp SURFACE OUTDIR
set -u
sweep=$1 file=$2 object=$3 out=$4
log=$out/viewer.out
"$sweep" view "$file" --size 1000x700 --samples 0 --select "$object" >"$log" 2>"$out/viewer.err" &
pid=$!

source "$(dirname "$0")/gui_driver_support.sh"  # fail, wait_count, wait_for

wait_for '^caps ' 30 || fail "the viewer printed no caps checkbox"
window=$(timeout 10 xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
[ -n "$window" ] || fail "no Sweep window found"
read -r cx cy < <(awk '/^caps /{printf "%.0f %.0f\n", $2, $3}' "$log")
[ -n "${cx:-}" ] && [ "$cx" -ge 0 ] || fail "no caps checkbox"
xdotool mousemove --window "$window" "$cx" "$cy"
sleep 0.2
xdotool mousedown 1
sleep 0.2
xdotool mouseup 1
sleep 0.5
xdotool key ctrl+s
sleep 0.5
xdotool key Escape
for ((i = 0; i < 200; ++i)); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -0 "$pid" 2>/dev/null && fail "Escape did not quit"
wait "$pid" || fail "the viewer exited with an error"
echo "clicked caps at $cx $cy"
