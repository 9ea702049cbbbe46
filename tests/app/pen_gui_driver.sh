#!/bin/bash
# The pen (issue 61, item 1) through the real window under Xvfb, in the profile view: five clicks
# and a click on the first make a closed B-spline; the Pen panel's kind list chooses a Bezier, and
# three presses each dragged before release make an open Bezier with the dragged handles, ended
# with Enter. Ctrl+S saves; the test reads the file back. Prints where it clicked ("bsp X Y" per
# node, "bez X Y DX DY" per pressed node and its drag, in window units) for the test to compare
# with the saved points, and writes OUTDIR/pen.png (the window) to look at.
# Usage: pen_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok pen on", "ok closed bspline", "ok bezier", then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, item, press, quit_viewer

# drag_node X Y DX DY: presses at (X, Y), moves in steps to (X+DX, Y+DY), lets go there.
drag_node() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep 0.2
  xdotool mousedown 1
  sleep 0.2
  for k in 1 2 3 4; do
    xdotool mousemove --window "$window" $(($1 + $3 * k / 4)) $(($2 + $4 * k / 4))
    sleep 0.1
  done
  sleep 0.2
  xdotool mouseup 1
  sleep 0.2
}

size=1280x800 start_viewer
wait_for '^item [-0-9.]* [-0-9.]* pen-panel$' 30 || fail "the viewer marked no Pen panel"
find_window
sleep 0.5
xdotool mousemove --window "$window" 640 400
xdotool key --window "$window" v
sleep 0.3
xdotool key --window "$window" b
wait_for '^status pen: click to put down points' 10 || fail "B did not turn the pen on"
echo "ok pen on"

# A pentagon about (825, 420), 140 units across, clockwise on the window from the top: right of
# the axis (x = 0 is near 707), where nothing is near enough to snap to.
for xy in "825 350" "892 398" "866 477" "784 477" "758 398"; do
  echo "bsp $xy"
  click $xy
  sleep 0.2
done
click 825 350
wait_for "^status drew bsp2 '[a-z0-9]*' (8 points, closed)\$" 10 || fail "clicking the first point did not close the B-spline"
echo "ok closed bspline"

press pen-panel
wait_for '^item [-0-9.]* [-0-9.]* pen-kind$' 10 || fail "the Pen panel did not open"
sleep 0.3
press pen-kind
wait_for '^item [-0-9.]* [-0-9.]* pen-kind-bezier-2d$' 10 || fail "the pen's kind list showed no Bezier (2D)"
sleep 0.3
press pen-kind-bezier-2d
sleep 0.3
for node in "745 600 0 -40" "820 560 40 0" "880 600 0 40"; do
  echo "bez $node"
  drag_node $node
done
xdotool key --window "$window" Return
wait_for "^status drew bez2 '[a-z0-9]*' (7 points)\$" 10 || fail "Enter did not end the Bezier"
echo "ok bezier"
grep -q '^error ' "$log" && fail "the viewer reported an error"
sleep 1
import -window "$window" "$out/pen.png" 2>/dev/null || fail "could not take a picture of the window"

xdotool key --window "$window" ctrl+s
wait_for '^status saved ' 10 || fail "Ctrl+S did not save"
xdotool key --window "$window" b
wait_for '^status pen off$' 10 || fail "B did not put the pen away"
quit_viewer
echo done
