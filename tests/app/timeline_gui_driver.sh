#!/bin/bash
# Drives the real `sweep view` window (xdotool under Xvfb) on a file with riders: a screenshot of
# the window paused at time 0 (OUTDIR/paused.png), another a second later still paused
# (paused-later.png), then Shift+Space (play), a second of playing, a screenshot while playing
# (playing.png), Shift+Space again (pause) and Escape. Runs inside xvfb-run.
# Usage: timeline_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints the viewer's "panel", "edit" and "status" lines (the view's edges and the messages).
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, find_window, quit_viewer
start_viewer

wait_for '^item [-0-9.]* [-0-9.]* play$' 30 || fail "the viewer printed no timeline strip"
find_window
sleep 0.5  # the still frame after the layout settled
# shot NAME: the window as it is on the screen, into OUTDIR/NAME.png.
shot() {
  import -window "$window" "$out/$1.png" || fail "import could not take $1.png"
}
shot paused
sleep 1
shot paused-later
xdotool key shift+space
wait_for '^status playing the riders' 10 || fail "Shift+Space did not play"
sleep 1
shot playing
xdotool key shift+space
wait_for '^status riders paused at ' 10 || fail "Shift+Space did not pause"
grep -q '^error ' "$log" && fail "the viewer reported an error"
quit_viewer
grep -E '^(panel|edit|status) ' "$log"
