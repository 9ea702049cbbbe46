# Sourced by the *_gui_driver.sh scripts once they have set `sweep` (the binary), `file` (the
# SWP file), `object` (what to select) and `out` (the folder for the viewer's output).

# start_viewer [NAME]: runs `sweep view FILE` with OBJECT selected in the background, its stdout
# in OUT/NAME.out (`log`) and stderr in OUT/NAME.err (`err`), NAME "viewer" unless given; sets `pid`.
# The window is `size` (WxH) screen units if set, else 1000x700.
start_viewer() {
  local name=${1:-viewer}
  log=$out/$name.out
  err=$out/$name.err
  # Sweep's own browser unless a driver asks for the desktop's dialog (a developer's desktop would
  # otherwise pop up its file chooser).
  SWEEP_FILE_CHOOSER=${SWEEP_FILE_CHOOSER-in-app} \
    "$sweep" view "$file" --size "${size:-1000x700}" --samples 0 --select "$object" >"$log" 2>"$err" &
  pid=$!
}

# fail MESSAGE: say why, show what the viewer printed, stop it, exit 1.
fail() {
  echo "driver: $*" >&2
  echo "--- viewer stdout:" >&2; cat "$log" >&2
  echo "--- viewer stderr:" >&2; cat "$err" >&2
  kill "$pid" 2>/dev/null
  exit 1
}

# wait_count PATTERN N SECONDS: until the viewer has printed N lines matching PATTERN (fails if
# it exits first).
wait_count() {
  local tries=$(( $3 * 20 ))
  for ((i = 0; i < tries; ++i)); do
    [ "$(grep -c "$1" "$log" 2>/dev/null)" -ge "$2" ] && return 0
    kill -0 "$pid" 2>/dev/null || return 1
    sleep 0.05
  done
  return 1
}

# wait_for PATTERN SECONDS: until the viewer prints a line matching PATTERN.
wait_for() {
  wait_count "$1" 1 "$2"
}

# item NAME: "X Y" (rounded) where the viewer last printed the widget NAME (it prints one when it
# appears or moves), nothing if never.
item() {
  awk -v name="$1" '$1 == "item" && $4 == name { x = $2; y = $3 } END { if (x != "") printf "%.0f %.0f\n", x, y }' "$log"
}

# press NAME: clicks the widget NAME where it was last printed (fails if never).
press() {
  local x y
  read -r x y < <(item "$1")
  [ -n "${x:-}" ] && [ "$x" -ge 0 ] || fail "no $1 button"
  click "$x" "$y"
}

# find_window: sets `window` to the viewer's X window (fails if there is none within 10 s).
find_window() {
  window=$(timeout 10 xdotool search --sync --onlyvisible --name 'Sweep' | head -n 1)
  [ -n "$window" ] || fail "no Sweep window found"
}

# click X Y: press and release the left button there in `window`, a frame or two apart.
click() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep 0.2
  xdotool mousedown 1
  sleep 0.2
  xdotool mouseup 1
}

# quit_viewer [HINT]: press Escape and wait (10 s at most) for the viewer to exit without an error;
# HINT says what it may mean if it does not quit.
quit_viewer() {
  xdotool key Escape
  for ((i = 0; i < 200; ++i)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill -0 "$pid" 2>/dev/null && fail "Escape did not quit${1:+ ($1)}"
  wait "$pid" || fail "the viewer exited with an error"
}
