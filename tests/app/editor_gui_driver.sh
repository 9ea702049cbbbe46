#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): drags one handle of the
# curve given with --select, saves with Ctrl+S and quits with Escape. Runs inside xvfb-run.
# Usage: editor_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "dragged INDEX DX DY" (the handle and the pointer movement in pixels) on success.
# With SWEEP_DRIVER_KILL=1 the viewer is killed with SIGKILL once it has written its recovery
# copy of the drag, started again on the same file, and the copy it offers is recovered (Return)
# and saved (Ctrl+S) before Escape. With SWEEP_DRIVER_CONFLICT=1 another program rewrites the file
# after the drag: the viewer asks, Return keeps the drag, and Ctrl+S asks again before it
# overwrites the changed file (Return). With SWEEP_DRIVER_CLICK=1 the handle is pressed and let go
# without moving, and the window's title is printed ("title NAME") before Ctrl+S.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_for '^panel ' 30 || fail "the viewer printed no handles"
find_window
panel=$(awk '/^panel /{print $2}' "$log")
read -r edit_left edit_bottom < <(awk '/^edit /{print $2, $3}' "$log")
# The handle farthest right of the main panel and not under the edit panel (top right), so the
# pointer is over the 3D view, among those with
# no other handle within 20 pixels (coincident handles would make the pick ambiguous).
read -r index hx hy < <(awk -v panel="$panel" -v edit_left="$edit_left" -v edit_bottom="$edit_bottom" '/^handle /{ n++; id[n] = $2; hx[n] = $3; hy[n] = $4 }
  END {
    best = -1
    for (i = 1; i <= n; i++) {
      if (hx[i] < panel + 20 || (hx[i] > edit_left - 80 && hy[i] < edit_bottom + 50)) continue
      alone = 1
      for (j = 1; j <= n; j++) if (j != i && (hx[i] - hx[j])^2 + (hy[i] - hy[j])^2 < 400) alone = 0
      if (alone && hx[i] > best) { best = hx[i]; line = id[i] " " hx[i] " " hy[i] }
    }
    print line
  }' "$log")
[ -n "${index:-}" ] || fail "no handle right of the panel"
x=$(printf '%.0f' "$hx") y=$(printf '%.0f' "$hy")
dx=60 dy=-30
[ "${SWEEP_DRIVER_CLICK:-}" = 1 ] && dx=0 dy=0

xdotool mousemove --window "$window" "$x" "$y"
sleep 0.2  # a frame or two sees the pointer over the handle (hover)
xdotool mousedown 1
sleep 0.2
if [ "$dx" != 0 ] || [ "$dy" != 0 ]; then
  for k in 1 2 3 4 5 6; do
    xdotool mousemove --window "$window" $(( x + dx * k / 6 )) $(( y + dy * k / 6 ))
    sleep 0.05
  done
fi
sleep 0.3  # the last position is seen before the release
xdotool mouseup 1
sleep 0.2
if [ "${SWEEP_DRIVER_KILL:-}" = 1 ]; then
  wait_for '^recovery written ' 10 || fail "no recovery copy was written after the drag"
  kill -9 "$pid"
  wait "$pid" 2>/dev/null
  start_viewer viewer2
  wait_for '^recovery copy ' 30 || fail "the restarted viewer offered no recovery copy"
  sleep 0.5  # the question is on screen
  xdotool key Return
  wait_for '^recovered ' 10 || fail "Return did not recover the copy"
fi
if [ "${SWEEP_DRIVER_CONFLICT:-}" = 1 ]; then
  sed '1s/ \([0-9][0-9]*\)/ \11/' "$file" >"$file.other" && mv "$file.other" "$file"
  wait_for '^question changed on disk' 5 || fail "no question after the file changed under the edits"
  sleep 0.3
  xdotool key Return
fi
if [ "${SWEEP_DRIVER_CLICK:-}" = 1 ]; then
  sleep 0.3  # a frame sets the title after the release
  echo "title $(xdotool getwindowname "$window")"
fi
xdotool key ctrl+s
if [ "${SWEEP_DRIVER_CONFLICT:-}" = 1 ]; then
  wait_for '^question overwrite' 5 || fail "Save did not ask before overwriting the changed file"
  sleep 0.3
  xdotool key Return
fi
wait_for '^saved ' 10 || fail "Ctrl+S saved nothing"
quit_viewer "unsaved changes left?"
echo "dragged $index $dx $dy"
