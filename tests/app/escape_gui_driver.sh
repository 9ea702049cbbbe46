#!/bin/bash
# Esc closes what is on top before it quits (issue 47, item 2), in the real window under Xvfb:
# F1 opens the Help window; Esc closes it and the viewer stays; Esc again quits (had the first Esc
# not closed the window, the second would have, and the viewer would still run).
# Usage: escape_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok help", "ok quit", then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, find_window, quit_viewer

start_viewer
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
xdotool windowactivate --sync "$window" 2>/dev/null
xdotool key --window "$window" F1
wait_for '^item [-0-9.]* [-0-9.]* help$' 10 || fail "F1 did not open the Help window"
xdotool key --window "$window" Escape
sleep 1
kill -0 "$pid" 2>/dev/null || fail "Esc quit the viewer while the Help window was open"
echo "ok help"
quit_viewer "with nothing open"
echo "ok quit"
echo done
