#!/bin/bash
# Another program writing the open file while the real window watches it (issue 29): 1 000
# rewrites in about 10 seconds, in place, by rename-over, half of them invalid, some written in two
# parts with a pause between (the first part alone is a valid file of one circle; now and then 60 ms,
# shorter than the watcher's settle time), a pause of 150 ms after a whole version every 100 writes
# (which the viewer should show), ending on a known valid version. Each complete valid version N is "circ a N 1" and "circ b N 1" (2 (N + 1) curve
# samples); the viewer prints its counts whenever they change (--select), so a half-read file (one
# circle: N + 1 samples) or any version it was never given would show. Runs inside xvfb-run.
# Usage: rewrites_gui_driver.sh SWEEP FILE.swp OBJECT OUTDIR
# Prints "written V valid I invalid T two-part R renamed", "shown K versions", "settled in S s", done.
set -u
sweep=$1 file=$2 object=$3 out=$4
source "$(dirname "$0")/gui_driver_support.sh"  # start_viewer, fail, wait_for, quit_viewer
start_viewer
wait_for '^counts ' 30 || fail "the viewer did not start"

valid=0 invalid=0 split=0 renamed=0
: >"$out/valid-samples.txt"
version_text() { printf 'circ a %d 1\ncirc b %d 1\n' "$1" "$1"; }
for ((i = 1; i <= 999; ++i)); do
  steps=$((10 + i))
  case $((i % 8)) in
    0 | 2 | 4 | 6)  # invalid: a radius missing, or a word where a number goes
      printf 'circ a %d\ncirc b x 1\n' "$steps" >"$file"
      invalid=$((invalid + 1)) ;;
    1)  # in two parts: the first a valid file of one circle; now and then a pause of 60 ms between
      gap=0.002; ((i % 40 == 1)) && gap=0.06
      { printf 'circ a %d 1\n' "$steps"; sleep $gap; printf 'circ b %d 1\n' "$steps"; } >"$file"
      split=$((split + 1)); valid=$((valid + 1)); echo $((2 * (steps + 1))) >>"$out/valid-samples.txt" ;;
    3)  # renamed over it, as editors save
      version_text "$steps" >"$file.tmp" && mv "$file.tmp" "$file"
      renamed=$((renamed + 1)); valid=$((valid + 1)); echo $((2 * (steps + 1))) >>"$out/valid-samples.txt" ;;
    *)  # in place
      version_text "$steps" >"$file"
      valid=$((valid + 1)); echo $((2 * (steps + 1))) >>"$out/valid-samples.txt" ;;
  esac
  sleep 0.004
  ((i % 100 == 3)) && sleep 0.15  # a pause after a whole version: the viewer reads it
done
final=7777
version_text "$final" >"$file"
last_write=$(date +%s.%N)
valid=$((valid + 1)); echo $((2 * (final + 1))) >>"$out/valid-samples.txt"
echo "written 1000 valid $valid invalid $invalid two-part $split renamed $renamed"
wait_for "^counts .* curve samples $((2 * (final + 1)))\$" 10 || fail "the final version was never shown"
shown=$(date +%s.%N)
awk -v a="$last_write" -v b="$shown" 'BEGIN { printf "settled in %.2f s\n", b - a }'
kill -0 "$pid" 2>/dev/null || fail "the viewer is gone"
# Every version shown is a complete valid one: the counts' samples are among those written.
first=1
grep '^counts ' "$log" | sed 's/.* curve samples //' | while read -r samples; do
  if [ $first = 1 ]; then first=0; continue; fi  # the file as opened
  grep -qx "$samples" "$out/valid-samples.txt" || { echo "driver: shown a version never written whole: $samples samples" >&2; exit 1; }
done || fail "a half-read file was shown"
echo "shown $(grep -c '^counts ' "$log") versions, skipped $(grep -c '^reload skipped ' "$log") read while changing, $(grep -c '^reload failed ' "$log") errors"
quit_viewer
echo done
