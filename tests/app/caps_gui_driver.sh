#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): clicks the selected
# surface's caps checkbox in the Edit panel, saves with Ctrl+S and quits with Escape. Runs
# inside xvfb-run. Usage: caps_gui_driver.sh SWEEP FILE.swp SURFACE OUTDIR
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_for '^caps ' 30 || fail "the viewer printed no caps checkbox"
find_window
read -r cx cy < <(awk '/^caps /{printf "%.0f %.0f\n", $2, $3}' "$log")
[ -n "${cx:-}" ] && [ "$cx" -ge 0 ] || fail "no caps checkbox"
click "$cx" "$cy"
sleep 0.5
xdotool key ctrl+s
sleep 0.5
quit_viewer
echo "clicked caps at $cx $cy"
