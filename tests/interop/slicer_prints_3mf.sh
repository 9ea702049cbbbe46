#!/usr/bin/env bash
# A slicer as the judge of the print exports (issue 58): `sweep export FILE OUT --format 3mf
# --height MM` (FORMAT stl: `--format stl --merge --height MM`, one OUT.stl), then PrusaSlicer
# slices the file headless (`--export-gcode`). It must write G-code, print no warning, and its
# highest layer must lie within 0.5 mm of MM. Exit 77 (ctest: skipped, with a message) when
# prusa-slicer is not installed; scripts/install-deps.sh installs it.
# Usage: slicer_prints_3mf.sh SWEEP FILE.swp HEIGHT_MM WORK_DIR [3mf|stl]
set -euo pipefail
sweep=$1 file=$2 height=$3 work=$4 format=${5:-3mf}
if ! command -v prusa-slicer >/dev/null; then
  echo "skipped: prusa-slicer is not installed (bash scripts/install-deps.sh installs it)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
merge=()
[ "$format" = stl ] && merge=(--merge)
"$sweep" export "$file" "$work/model" --format "$format" "${merge[@]}" --height "$height" >"$work/export.txt"
grep -q "^model size .* x $height.0 mm (scaled to the height asked" "$work/export.txt" || { cat "$work/export.txt"; exit 1; }
prusa-slicer --export-gcode --center 100,100 "$work/model.$format" --output "$work/model.gcode" >"$work/slicer.txt" 2>&1 || {
  cat "$work/slicer.txt"
  exit 1
}
# What PrusaSlicer says besides its progress ("NN => ...") and trace lines: only the result.
said=$(grep -v -E '=>|\[trace\]|^$' "$work/slicer.txt")
[ "$said" = "Slicing result exported to $work/model.gcode" ] || { echo "prusa-slicer said: $said"; exit 1; }
top=$(sed -n 's/^;Z:\([0-9.]*\)$/\1/p' "$work/model.gcode" | sort -g | tail -n 1)
awk -v top="$top" -v height="$height" 'BEGIN { d = top - height; exit !(d <= 0.5 && d >= -0.5) }' ||
  { echo "the highest layer is at $top mm, the model $height mm tall"; exit 1; }
echo "sliced $(basename "$file") as $format at $height mm: highest layer $top mm, no warning"
