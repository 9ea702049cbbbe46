#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): clicks the Edit panel's
# Adaptive checkbox on, then off again, and quits with Escape. Runs inside xvfb-run.
# Usage: adaptive_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints the viewer's "counts ..." lines (the stats panel's numbers): before, on, off.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_count '^counts ' 1 30 || fail "the viewer printed no counts"
find_window
read -r ax ay < <(awk '/^adaptive /{printf "%.0f %.0f\n", $2, $3}' "$log")
[ -n "${ax:-}" ] && [ "$ax" -ge 0 ] || fail "no Adaptive checkbox"

click "$ax" "$ay"
wait_count '^counts ' 2 20 || fail "turning Adaptive on changed no count"
click "$ax" "$ay"
wait_count '^counts ' 3 20 || fail "turning Adaptive off changed no count"
quit_viewer
grep '^counts ' "$log"
