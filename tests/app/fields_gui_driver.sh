#!/bin/bash
# Drives the real `sweep view` window with synthetic X input (xdotool): types into number fields
# as a user does (Ctrl+click, one key at a time, Return), saves with Ctrl+S and quits with
# Escape. Runs inside xvfb-run. Usage: fields_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# SWEEP_DRIVER_TYPING lists what to do, separated by ';': "NAME=TEXT" types TEXT into the field
# the panels mark NAME (mark_item) and presses Return; "NAME" alone clicks it (a panel's header);
# "scroll=N" turns the mouse wheel N notches down over the main panel.
# Prints "typing NAME TEXT title TITLE" with the window's title just before each Return (a '*'
# there means something applied while typing), and copies the viewer's "error ..." lines.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_for '^panel ' 30 || fail "the viewer printed no handles"
find_window

# item_at NAME: sets x and y to where the field NAME was last marked (fails if never).
item_at() {
  local line
  wait_for "^item [-0-9.]* [-0-9.]* $1\$" 5 || fail "no field '$1' marked"
  sleep 0.3  # the layout settles; the last position printed is where it is
  line=$(grep "^item [-0-9.]* [-0-9.]* $1\$" "$log" | tail -n 1)
  x=$(printf '%.0f' "$(echo "$line" | awk '{print $2}')")
  y=$(printf '%.0f' "$(echo "$line" | awk '{print $3}')")
}

IFS=';' read -r -a steps <<<"${SWEEP_DRIVER_TYPING:-}"
for step in "${steps[@]}"; do
  name=${step%%=*}
  if [ "$name" = scroll ]; then  # scroll=N: the mouse wheel N notches down over the main panel
    xdotool mousemove --window "$window" 150 400
    xdotool click --repeat "${step#*=}" --delay 50 5
    sleep 0.5
    continue
  fi
  item_at "$name"
  if [ "$name" = "$step" ]; then
    click "$x" "$y"
    sleep 0.5
    continue
  fi
  text=${step#*=}
  xdotool mousemove --window "$window" $(( x + 25 )) "$y"
  sleep 0.2
  xdotool keydown ctrl
  sleep 0.1
  xdotool mousedown 1
  sleep 0.2
  xdotool mouseup 1
  sleep 0.1
  xdotool keyup ctrl
  sleep 0.3  # the text field takes the keyboard
  xdotool type --delay 120 "$text"
  sleep 0.3
  echo "typing $name $text title $(xdotool getwindowname "$window")"
  xdotool key Return
  sleep 0.5
done
# SWEEP_DRIVER_SHOT=FILE.png: a picture of the screen before the save, to look at.
[ -n "${SWEEP_DRIVER_SHOT:-}" ] && import -window root "$SWEEP_DRIVER_SHOT" 2>/dev/null
xdotool key ctrl+s
wait_for '^saved ' 10 || fail "Ctrl+S saved nothing"
quit_viewer "unsaved changes left?"
grep '^error ' "$log"
echo "done"
