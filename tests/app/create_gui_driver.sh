#!/bin/bash
# The Create panel and the status bar in the real window under Xvfb (issue 47, items 4 and 5): at
# 1280x800 on a file with a long outliner, the Create panel's first button (Add curve) shows
# without scrolling; a click on it says "added bsp2 'curve' ..." in the status bar; Add surface
# turns that curve (the profile it now offers) and says so; Export STL of the document, whose new
# surface is open, shows the closed-manifold warning in the status bar as a warning. Ctrl+S saves
# and Escape quits.
# Usage: create_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok create visible X Y", "ok curve", "ok surface", "ok warning", then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, item, press, quit_viewer

size=1280x800 start_viewer
wait_for '^item [-0-9.]* [-0-9.]* add-curve$' 30 || fail "the viewer marked no Add curve button"
find_window
sleep 0.5  # the layout settles; the last position printed is where it is
read -r x y < <(item add-curve)
# Within the window and above the status bar (22 units): no scrolling needed.
[ "$y" -gt 0 ] && [ "$y" -lt 778 ] || fail "Add curve is at y = $y, out of a 1280x800 window's sight"
echo "ok create visible $x $y"

press add-curve
wait_for "^status added bsp2 'curve'\\( (scaled by [0-9.]*)\\)\\?: drag its points in the view$" 10 ||
  fail "Add curve said nothing in the status bar"
echo "ok curve"
sleep 0.5
press add-surface
wait_for "^status added srev 'revolution' turning 'curve' in 24 steps$" 10 || fail "Add surface said nothing"
echo "ok surface"

sleep 0.5
press export-panel
wait_for '^item [-0-9.]* [-0-9.]* export-stl$' 10 || fail "opening Export and PNGs showed no Export STL"
sleep 0.5
press export-stl
wait_for "^status .*: warning: surface 'revolution' is open: " 20 || fail "Export STL did not warn"
wait_for '^item [-0-9.]* [-0-9.]* status-bar-warning$' 10 || fail "the status bar did not show the warning as one"
echo "ok warning"
grep -q '^error ' "$log" && fail "the viewer reported an error"

xdotool key --window "$window" ctrl+s
wait_for '^status saved ' 10 || fail "Ctrl+S did not save"
quit_viewer
echo done
