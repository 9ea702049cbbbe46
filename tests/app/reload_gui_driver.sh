#!/bin/bash
# Live reload with the real window: the viewer runs on FILE with OBJECT selected while this script
# rewrites FILE as other programs do: in place (a changed number), by writing a new file and
# renaming it over (as most editors save), with an error, then fixed. Runs inside xvfb-run.
# Usage: reload_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints the viewer's "reloaded ..." and "reload failed ..." lines, then "done".
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, click, quit_viewer, ...
start_viewer

wait_count '^panel ' 1 30 || fail "the viewer did not start"
original=$(cat "$file")
# 1. In place: the same file with its first number (the first object's STEPS) one digit longer.
printf '%s\n' "$original" | sed '1s/ \([0-9][0-9]*\)/ \11/' >"$out/edited.swp"
cat "$out/edited.swp" >"$file"
wait_count '^reloaded ' 1 5 || fail "no reload after an in-place write"
# 2. Rename-over: a new file beside it, renamed over it.
printf '%s\n' "$original" >"$file.tmp"
mv "$file.tmp" "$file"
wait_count '^reloaded ' 2 5 || fail "no reload after a rename-over"
# 3. An error: the viewer keeps the last good scene and says where.
printf 'circ broken 8\n' >"$file.tmp"
mv "$file.tmp" "$file"
wait_count '^reload failed ' 1 5 || fail "no error after a broken write"
# 4. Fixed again.
printf '%s\n' "$original" >"$file.tmp"
mv "$file.tmp" "$file"
wait_count '^reloaded ' 3 5 || fail "no reload after the fix"
grep -E '^reload' "$log"
quit_viewer
echo done
