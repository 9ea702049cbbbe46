#!/bin/bash
# New objects where the user can see them (issue 59, item 3), through the real window under Xvfb:
# on the wineglass, the Create panel's trefoil knot is sized to the glass and stands beside it
# (the status says so), the circle is sized to the glass, and the tube of the circle along the
# knot shrinks the circle so that it never passes through itself; each addition frames the view
# on it. Ctrl+S saves; the driver writes OUTDIR/placed.png (the window) to look at.
# Usage: place_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok knot", "ok circle", "ok tube", then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, item, press, quit_viewer

# choose PREFIX NAME: opens the combo marked PREFIX and clicks its entry PREFIX-NAME.
choose() {
  press "$1"
  wait_for "^item [-0-9.]* [-0-9.]* $1-$2\$" 10 || fail "the $1 list showed no $2"
  sleep 0.3
  press "$1-$2"
  sleep 0.3
}

size=1280x800 start_viewer
wait_for '^item [-0-9.]* [-0-9.]* template$' 30 || fail "the viewer marked no template list"
find_window
sleep 0.5

choose template trefoil-knot
press add-curve
wait_for "^status added knot 'knot' (\\(scaled by [0-9.]*, \\)\\?beside the scene): its numbers are in the Edit panel$" 10 ||
  fail "Add curve did not place the knot beside the glass"
echo "ok knot"

choose template circle
press add-curve
wait_for "^status added circ 'circle' (scaled by [0-9.]*): its numbers are in the Edit panel$" 10 ||
  fail "Add curve did not size the circle"
echo "ok circle"

choose surface-kind generalized-cylinder
press add-surface
wait_for "^status added gcyl 'cylinder' from 'circle' along 'knot' ('circle' scaled by [0-9.]* to fit the sweep's bends)$" 10 ||
  fail "Add surface did not fit the circle to the knot's bends"
echo "ok tube"
grep -q '^error ' "$log" && fail "the viewer reported an error"
sleep 1
import -window "$window" "$out/placed.png" 2>/dev/null || fail "could not take a picture of the window"

xdotool key --window "$window" ctrl+s
wait_for '^status saved ' 10 || fail "Ctrl+S did not save"
quit_viewer
echo done
