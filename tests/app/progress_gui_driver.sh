#!/bin/bash
# Long work in the real window (xdotool under Xvfb): the level slider of a subd on a large cage is
# typed to 5, whose re-mesh runs in the background; the progress bar's Cancel appears after its
# delay and is clicked; the document goes back to level 1. Runs inside xvfb-run.
# Usage: progress_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints the viewer's "status", "counts" and "item" lines.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, find_window, click, quit_viewer
start_viewer

wait_for '^item [-0-9.]* [-0-9.]* level$' 30 || fail "the viewer printed no level slider"
find_window
read -r x y < <(awk '$1 == "item" && $4 == "level" {x = $2; y = $3} END {printf "%.0f %.0f\n", x, y}' "$log")
# Ctrl+click turns the slider into a typed field (its text selected): level 5.
xdotool mousemove --window "$window" $((x + 25)) "$y"
sleep 0.2
xdotool keydown ctrl
sleep 0.1
xdotool mousedown 1
sleep 0.2
xdotool mouseup 1
sleep 0.1
xdotool keyup ctrl
sleep 0.3  # the text field takes the keyboard
xdotool type --delay 120 5
sleep 0.3
xdotool key Return
wait_for '^item [-0-9.]* [-0-9.]* cancel progress$' 20 || fail "no progress bar with Cancel"
sleep 0.1  # the button is marked once the bar's window has its height (its second frame)
read -r cx cy < <(awk '$1 == "item" && $4 == "cancel" {x = $2; y = $3} END {printf "%.0f %.0f\n", x, y}' "$log")
click "$cx" "$cy"
wait_for '^status cancelled: back to what the view showed' 10 || fail "Cancel did not cancel"
sleep 0.5
grep -q '^error ' "$log" && fail "the viewer reported an error"
grep -E '^(status|counts|item [-0-9.]* [-0-9.]* (level|cancel progress)$)' "$log"
quit_viewer
echo done
