#!/bin/bash
# The Help window and an empty view in the real window under Xvfb (issue 47, item 9), at 1280x800:
# F1 opens Help; its lower edge is above the status bar and its last row (the mouse table's) is out
# of sight until the wheel scrolls it into the window. Esc closes it. Ctrl+N makes an empty
# document: Export and PNGs' "the view" saves the view as a PNG. Then the viewer is started
# without a file and --screenshot saves its window. The test looks at both pictures' grids.
# Usage: view_aids_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "ok help fits", "ok help scrolls", "new view PATH", "empty start PATH", then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, item, press, quit_viewer

size=1280x800 start_viewer
wait_for '^selected ' 30 || fail "the viewer did not start"
find_window
xdotool windowactivate --sync "$window" 2>/dev/null
xdotool key --window "$window" F1
wait_for '^item [-0-9.]* [-0-9.]* help-last-row$' 10 || fail "F1 did not open the Help window"
sleep 0.5  # it settles: the last positions printed are where it is
read -r hx bottom < <(item help)  # its lower-left corner
read -r _ last < <(item help-last-row)
[ "$bottom" -le 778 ] || fail "the Help window reaches y = $bottom, under the status bar of an 800-high window"
[ "$last" -gt "$bottom" ] || fail "the Help window's last row (y = $last) shows unscrolled: nothing to scroll"
echo "ok help fits"
xdotool mousemove --window "$window" $((hx + 300)) $((bottom - 200))
sleep 0.2
xdotool click --repeat 60 --delay 30 5  # the wheel, down
for ((i = 0; i < 40; ++i)); do
  read -r _ last < <(item help-last-row)
  [ "$last" -lt "$bottom" ] && break
  sleep 0.1
done
[ "$last" -lt "$bottom" ] || fail "the wheel did not scroll the Help window's last row (y = $last) into it"
echo "ok help scrolls"
xdotool key --window "$window" Escape
sleep 0.5
kill -0 "$pid" 2>/dev/null || fail "Esc quit the viewer while the Help window was open"

xdotool key --window "$window" ctrl+n
wait_for '^status new untitled document$' 10 || fail "Ctrl+N made no new document"
wait_for '^item [-0-9.]* [-0-9.]* export-panel$' 10 || fail "no Export and PNGs panel"
sleep 0.5
press export-panel
wait_for '^item [-0-9.]* [-0-9.]* png-view$' 10 || fail "opening Export and PNGs showed no PNG buttons"
sleep 0.5
press png-view
wait_for '^item [-0-9.]* [-0-9.]* png-save$' 10 || fail "Save PNG of the view asked nothing"
sleep 0.3
press png-save
wait_for '^status saved PNG of the view ' 20 || fail "Save PNG of the view saved nothing"
grep '^status saved PNG of the view ' "$log" | tail -n 1 | sed -e 's/^status saved PNG of the view /new view /' \
  -e 's/ ([0-9]* x [0-9]* pixels)$//'
quit_viewer

# Started without a file (an empty, untitled document from the start).
"$sweep" view --size 1280x800 --samples 0 --frame-count 8 \
  --screenshot "$out/empty-start.png" >"$out/empty.out" 2>"$out/empty.err" || fail "the empty start failed: $(cat "$out/empty.err")"
echo "empty start $out/empty-start.png"
echo done
