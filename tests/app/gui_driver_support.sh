# Sourced by the *_gui_driver.sh scripts once they have started the viewer: they set `log` (its
# stdout), `out` (the folder with viewer.err) and `pid`.

# fail MESSAGE: say why, show what the viewer printed, stop it, exit 1.
fail() {
  echo "driver: $*" >&2
  echo "--- viewer stdout:" >&2; cat "$log" >&2
  echo "--- viewer stderr:" >&2; cat "$out/viewer.err" >&2
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
