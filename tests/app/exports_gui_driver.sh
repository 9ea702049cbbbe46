#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool), started from another
# working folder (OUTDIR/elsewhere) on ../FILE: opens the Export and PNGs panel, clicks its Export STL, Export glb,
# glb (quantized) and SVG, then Save PNG of the view, types "window.png" into the PNG name field and clicks Save PNG of
# the window, and quits with Escape. Runs inside xvfb-run.
# Usage: exports_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR   (FILE in OUTDIR)
# Prints the viewer's "panel", "edit" and "status" lines (the view's edges and the messages).
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # fail, wait_for, wait_count, find_window, click, quit_viewer
log=$out/viewer.out
err=$out/viewer.err
mkdir -p "$out/elsewhere"
cd "$out/elsewhere" || exit 1
"$sweep" view "../$(basename "$file")" --size 1200x760 --samples 0 --select "$object" >"$log" 2>"$err" &
pid=$!

wait_for '^item [-0-9.]* [-0-9.]* export-panel$' 30 || fail "the viewer printed no Export and PNGs panel"
find_window
# item X Y NAME: where NAME was last seen (the viewer prints a widget when it appears or moves).
item() {
  awk -v name="$1" '$1 == "item" && $4 == name { x = $2; y = $3 } END { if (x != "") printf "%.0f %.0f\n", x, y }' "$log"
}
press() {
  read -r x y < <(item "$1")
  [ -n "${x:-}" ] && [ "$x" -ge 0 ] || fail "no $1 button"
  click "$x" "$y"
}

# Closed until opened (issue 47, item 4: the long, rarer panels are closed).
sleep 0.3  # the layout settles; the last position printed is where it is
press export-panel
wait_for '^item [-0-9.]* [-0-9.]* png-window$' 20 || fail "opening Export and PNGs showed no buttons"
sleep 0.3

press export-stl
wait_for '^status wrote .*\.stl ' 20 || fail "Export STL wrote nothing"
press export-glb
wait_for '^status wrote .*\.glb ' 20 || fail "Export glb wrote nothing"
press export-glb-quantized
wait_for '^status wrote .*\.glb .*, quantized)' 20 || fail "Export glb (quantized) wrote nothing"
press export-svg
wait_for '^status wrote .*\.svg ' 20 || fail "Export SVG wrote nothing"
press png-view
wait_for '^item [-0-9.]* [-0-9.]* png-save$' 10 || fail "Save PNG of the view asked nothing"
sleep 0.3
press png-save
wait_for '^status saved PNG of the view ' 20 || fail "Save PNG of the view saved nothing"
press png-name
sleep 0.3
# Emptied key by key (a frame apart: a key tapped twice within one frame counts once).
xdotool key --delay 80 End $(printf 'BackSpace %.0s' $(seq 40))
xdotool type --delay 60 window.png
sleep 0.3
press png-window
wait_for '^status saved PNG of the window ' 20 || fail "Save PNG of the window saved nothing"
# Save PNG of the view again: named big.png, 1920 x 1080, without the control points.
press png-view
wait_count '^item [-0-9.]* [-0-9.]* png-save$' 2 10 || fail "Save PNG of the view asked nothing"
sleep 0.3
press png-dialog-name
sleep 0.3
xdotool key --delay 80 End $(printf 'BackSpace %.0s' $(seq 40))
xdotool type --delay 60 big.png
sleep 0.2
press png-size
wait_for '^item [-0-9.]* [-0-9.]* png-size-1$' 10 || fail "the Size list did not open"
sleep 0.3
press png-size-1
sleep 0.3
press png-points
sleep 0.3
press png-save
wait_for '^status saved PNG of the view .*big.png ' 20 || fail "Save PNG of the view saved no big.png"
grep -q '^error ' "$log" && fail "the viewer reported an error"
sleep 0.3
quit_viewer
grep -E '^(panel|edit|status) ' "$log"
