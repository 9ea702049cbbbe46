#!/bin/bash
# Drives the real `sweep view` window (xdotool under Xvfb) through curve editing as a user does,
# then saves with Ctrl+S and quits with Escape. Runs inside xvfb-run.
# Usage: curve_editing_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# SWEEP_DRIVER_HANDLE=I: drags handle I of OBJECT 60 pixels right and 30 up (a plain drag).
# SWEEP_DRIVER_BAND="I J K": Shift+drags a rubber band around handles I, J and K from 25 pixels
# outside their box, presses G, moves the pointer 50 right and 40 down and clicks (grab, confirm).
# SWEEP_DRIVER_DOUBLE="I J": double-clicks halfway between handles I and J (on a polyline's segment).
# Prints "moved DX DY" with the pointer movement on success.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_for '^panel ' 30 || fail "the viewer printed no handles"
find_window

# handle_at I: prints the window position of handle I, rounded, or fails.
handle_at() {
  local line
  line=$(awk -v i="$1" '$1 == "handle" && $2 == i { printf "%.0f %.0f\n", $3, $4 }' "$log" | tail -n 1)
  [ -n "$line" ] || fail "no handle $1"
  echo "$line"
}

# move_in_steps X0 Y0 X1 Y1: the pointer travels from (X0, Y0) to (X1, Y1) in six frames.
move_in_steps() {
  for k in 1 2 3 4 5 6; do
    xdotool mousemove --window "$window" $(( $1 + ($3 - $1) * k / 6 )) $(( $2 + ($4 - $2) * k / 6 ))
    sleep 0.05
  done
  sleep 0.3
}

if [ -n "${SWEEP_DRIVER_DOUBLE:-}" ]; then
  read -r i j <<<"$SWEEP_DRIVER_DOUBLE"
  read -r xi yi < <(handle_at "$i")
  read -r xj yj < <(handle_at "$j")
  xdotool mousemove --window "$window" $(( (xi + xj) / 2 )) $(( (yi + yj) / 2 ))
  sleep 0.2
  xdotool click --repeat 2 --delay 80 1
  sleep 0.3
  echo "moved 0 0"
elif [ -n "${SWEEP_DRIVER_HANDLE:-}" ]; then
  read -r x y < <(handle_at "$SWEEP_DRIVER_HANDLE")
  xdotool mousemove --window "$window" "$x" "$y"
  sleep 0.2
  xdotool mousedown 1
  sleep 0.2
  move_in_steps "$x" "$y" $(( x + 60 )) $(( y - 30 ))
  xdotool mouseup 1
  echo "moved 60 -30"
else
  left=100000 top=100000 right=0 bottom=0
  for i in $SWEEP_DRIVER_BAND; do
    read -r x y < <(handle_at "$i")
    (( x < left )) && left=$x
    (( y < top )) && top=$y
    (( x > right )) && right=$x
    (( y > bottom )) && bottom=$y
  done
  x0=$(( left - 25 )) y0=$(( top - 25 )) x1=$(( right + 25 )) y1=$(( bottom + 25 ))
  xdotool mousemove --window "$window" "$x0" "$y0"
  sleep 0.2
  xdotool keydown shift
  xdotool mousedown 1
  sleep 0.2
  move_in_steps "$x0" "$y0" "$x1" "$y1"
  xdotool mouseup 1
  xdotool keyup shift
  sleep 0.3
  xdotool key g
  sleep 0.3
  move_in_steps "$x1" "$y1" $(( x1 + 50 )) $(( y1 + 40 ))
  xdotool click 1
  sleep 0.3
  echo "moved 50 40"
fi
xdotool key ctrl+s
wait_for '^saved ' 10 || fail "Ctrl+S saved nothing"
quit_viewer "unsaved changes left?"
