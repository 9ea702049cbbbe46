#!/usr/bin/env bash
# A monkey for the real window (issue 29): random input against `sweep view` under Xvfb for a
# bounded time: keys of the command table, clicks and drags with every button in the panels and
# the view, the wheel, typed text (numbers, words) into whatever field has the keyboard, and
# window resizes. Everything the viewer writes goes into a temporary folder (a copy of the file,
# HOME and the XDG folders). A watchdog fails the run when the viewer dies (a crash, a sanitizer
# report), stops using the CPU while it should be drawing continuously (--frame-time: a deadlock)
# for 10 s, or does not quit within 10 s when asked at the end (a hang); and when its resident
# memory passes the bound. A viewer that quits because the monkey pressed Ctrl+Q (and answered
# the question) is started again. The seed is printed: the same seed sends the same events.
# Dropped files are not sent: xdotool cannot drag from another program.
#
# Usage: scripts/monkey.sh [--seconds N] [--seed S] [--rss-mib M] FILE.swp...
#   (the time is split between the files; SWEEP_BUILD_DIR picks the build, e.g. a sanitizer one)
# Each file runs in an X server of its own with its own seed (SEED, SEED + 1, ...). Prints per file:
# events sent, restarts, peak resident memory, the frame time at the start and at the end (after
# putting the window's size back, undoing and resetting the camera); exits 1 on a failure, with
# the seed and the command that replays it.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=60 seed=$(( $(date +%s) % 100000 )) rss_mib=3072
args=("$@")
files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift ;;
    --seed) seed=$2; shift ;;
    --rss-mib) rss_mib=$2; shift ;;
    *) files+=("$1") ;;
  esac
  shift
done
[ ${#files[@]} -gt 0 ] || { echo "usage: scripts/monkey.sh [--seconds N] [--seed S] [--rss-mib M] FILE.swp..." >&2; exit 2; }
sweep="${SWEEP_BUILD_DIR:-$root/build}/sweep"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
if [ -z "${MONKEY_INSIDE_XVFB:-}" ]; then
  # Each file in an X server of its own, with a seed of its own (seed, seed + 1, ...).
    share=$((seconds / ${#files[@]})) index=0
  for file in "${files[@]}"; do
    env MONKEY_INSIDE_XVFB=1 xvfb-run -a -s '-screen 0 1600x1000x24' \
      bash "$0" --seconds "$share" --seed $((seed + index)) --rss-mib "$rss_mib" "$file" || exit 1
    index=$((index + 1))
  done
  echo "monkey: passed"
  exit 0
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export HOME="$work/home" XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state"
mkdir -p "$HOME"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1"  # the GL stack's leaks are not ours
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
RANDOM=$seed

keys=(ctrl+z ctrl+shift+z ctrl+s ctrl+shift+s ctrl+o ctrl+n ctrl+q Escape Return Tab space shift+space F1 f Home
      1 3 7 v s c p k a g r e x y z shift+g shift+c shift+s shift+y Delete BackSpace Up Down Left Right plus minus
      ctrl+a 0 5 9 period)
words=(12.5 -3 0 1e9 abc 7 0.001 "x y" 100000 nan)

fail() {
  echo "monkey: FAILED on $current: $*" >&2
  [ -f "$work/viewer.err" ] && tail -n 40 "$work/viewer.err" >&2
  echo "monkey: replay with: scripts/monkey.sh --seconds $seconds --seed $seed ${files[*]}" >&2
  exit 1
}
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null || echo 0; }
rss_kib() { awk '/^VmRSS:/ {print $2}' "/proc/$1/status" 2>/dev/null || echo 0; }

start_viewer() {
  # The in-app browser: a desktop dialog (portal, zenity) would be a window the monkey cannot see.
  SWEEP_FILE_CHOOSER=in-app "$sweep" view "$copy" --size 1000x700 --frame-time >"$work/viewer.out" 2>"$work/viewer.err" &
  pid=$!
  window=""
  for _ in $(seq 100); do
    window=$(xdotool search --onlyvisible --name 'Sweep' 2>/dev/null | head -n 1) && [ -n "$window" ] && break
    kill -0 "$pid" 2>/dev/null || fail "the viewer did not start: $(cat "$work/viewer.err")"
    sleep 0.1
  done
  [ -n "$window" ] || fail "no window"
  last_ticks=$(cpu_ticks "$pid") last_progress=$SECONDS
}

# One random event inside the window (1000 x 700 unless resized).
event() {
  local x=$((RANDOM % width)) y=$((RANDOM % height)) kind=$((RANDOM % 20))
  if ((kind < 7)); then
    xdotool key --window "$window" "${keys[RANDOM % ${#keys[@]}]}"
  elif ((kind < 12)); then
    xdotool mousemove --window "$window" "$x" "$y" click $((1 + RANDOM % 3))
  elif ((kind < 15)); then
    local button=$((1 + RANDOM % 3)) x2=$((RANDOM % width)) y2=$((RANDOM % height))
    xdotool mousemove --window "$window" "$x" "$y" mousedown "$button" \
      mousemove --window "$window" $(((x + x2) / 2)) $(((y + y2) / 2)) mousemove --window "$window" "$x2" "$y2" \
      mouseup "$button"
  elif ((kind < 17)); then
    xdotool mousemove --window "$window" "$x" "$y" click $((4 + RANDOM % 2))
  elif ((kind < 19)); then
    xdotool type --window "$window" --delay 20 -- "${words[RANDOM % ${#words[@]}]}"
  else
    width=$((600 + RANDOM % 800)) height=$((400 + RANDOM % 500))
    xdotool windowsize "$window" "$width" "$height"
  fi
}

# The viewer is still up and drawing (it draws continuously with --frame-time), within its memory.
watchdog() {
  kill -0 "$pid" 2>/dev/null || return 1
  local ticks rss
  ticks=$(cpu_ticks "$pid")
  if [ "$ticks" != "$last_ticks" ]; then last_ticks=$ticks last_progress=$SECONDS; fi
  ((SECONDS - last_progress < 10)) || fail "no CPU used for 10 s: hung"
  rss=$(rss_kib "$pid")
  ((rss / 1024 <= rss_mib)) || fail "resident memory $((rss / 1024)) MiB over the bound"
  ((rss > peak_kib)) && peak_kib=$rss
  return 0
}

# The viewer quits when asked (Escape closes what is open; Ctrl+S makes quitting ask nothing).
quit_viewer() {
  for _ in 1 2; do
    xdotool key --window "$window" Escape Escape Escape ctrl+s Escape Escape ctrl+q 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    kill -0 "$pid" 2>/dev/null || break
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "monkey: $current did not quit when asked (a dialog left open?); stopped" >&2
    kill "$pid"; wait "$pid" 2>/dev/null || true
    return
  fi
  wait "$pid" || fail "the viewer exited with status $?"
}

share=$((seconds / ${#files[@]}))
total_events=0
for file in "${files[@]}"; do
  current=$(basename "$file")
  copy="$work/$current"
  cp "$file" "$copy"
  width=1000 height=700 events=0 restarts=0 peak_kib=0
  start_viewer
  sleep 1
  end=$((SECONDS + share))
  while ((SECONDS < end)); do
    if ! watchdog; then
      wait "$pid" && status=0 || status=$?
      [ "$status" = 0 ] || fail "the viewer died with status $status"
      grep -q "ERROR: AddressSanitizer\|runtime error" "$work/viewer.err" && fail "sanitizer report"
      restarts=$((restarts + 1))  # quit by the monkey's own Ctrl+Q
      width=1000 height=700
      start_viewer
    fi
    event 2>/dev/null || true
    events=$((events + 1))
  done
  # Back towards the state it started in (the window's size, the edits undone, the camera reset),
  # so the last frames' time compares with the first frames'; the display toggles stay as left.
  xdotool windowsize "$window" 1000 700 key --window "$window" --delay 5 Escape Escape Escape 2>/dev/null || true
  for _ in $(seq 30); do xdotool key --window "$window" --delay 2 ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z ctrl+z 2>/dev/null || true; done
  xdotool key --window "$window" space 2>/dev/null || true
  sleep 5
  quit_viewer
  grep -q "ERROR: AddressSanitizer\|runtime error" "$work/viewer.err" && fail "sanitizer report"
  frames=$(grep -E "^median frame time" "$work/viewer.out" | tail -n 1 || true)
  echo "$current: $events events, $restarts restarts, peak resident $((peak_kib / 1024)) MiB; ${frames:-no frame-time summary}"
  total_events=$((total_events + events))
done
echo "monkey: $total_events events, seed $seed"
