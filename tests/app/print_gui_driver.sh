#!/bin/bash
# Printing through the real window under Xvfb (issue 58): in the Export and PNGs panel, types a
# print height of 30 mm, clicks 3MF, and clicks the first printability finding listed, which
# must select the surface it names. Saves a PNG of the window showing the list, and quits.
# Usage: print_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok exported", "ok listed", "ok selected", then the viewer's status and selection lines.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, item, press, quit_viewer

size=1280x800 start_viewer
wait_for '^item [-0-9.]* [-0-9.]* export-panel$' 30 || fail "the viewer printed no Export and PNGs panel"
find_window
sleep 0.5
press export-panel
wait_for '^item [-0-9.]* [-0-9.]* print-height$' 20 || fail "opening Export and PNGs showed no print height"
sleep 0.3
press print-height
sleep 0.3
xdotool key --delay 80 ctrl+a BackSpace
xdotool type --delay 120 30
xdotool key Return
sleep 0.3
press export-3mf
wait_for '^status wrote .*\.3mf ' 20 || fail "Export 3MF wrote nothing"
wait_for '^status model size .* x 30.0 mm ' 5 || fail "the 3MF is not 30 mm tall"
echo "ok exported"
wait_for '^item [-0-9.]* [-0-9.]* print-finding-0$' 10 || fail "no finding listed"
echo "ok listed"
sleep 0.5
press print-finding-0
wait_for '^selection tube$' 10 || fail "clicking the finding did not select 'tube'"
echo "ok selected"
press png-window
wait_for '^status saved PNG of the window ' 20 || fail "Save PNG of the window saved nothing"
grep -q '^error ' "$log" && fail "the viewer reported an error"
quit_viewer
grep -E '^(status|selection) ' "$log"
