#!/usr/bin/env bash
# Renders every starter file in swp/ in the three modes with `sweep render` (headless, OSMesa)
# and puts them on one contact sheet, assets/gallery.png (ImageMagick montage).
# Usage: scripts/make-gallery.sh [OUT.png]   (SWEEP_BUILD_DIR picks the build, default build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sweep="${SWEEP_BUILD_DIR:-$root/build}/sweep"
out="${1:-$root/assets/gallery.png}"
size="${GALLERY_TILE_SIZE:-320x240}"
[ -x "$sweep" ] || { echo "no $sweep: build first (scripts/build.sh)" >&2; exit 1; }
command -v montage >/dev/null || { echo "ImageMagick's montage is needed (apt-get install imagemagick)" >&2; exit 1; }

tiles="$(mktemp -d)"
trap 'rm -rf "$tiles"' EXIT
labels=()
for file in "$root"/swp/*.swp; do
  name="$(basename "$file" .swp)"
  "$sweep" render "$file" -o "$tiles/$name-1.png" --size "$size" --surface smooth --curves on --points off >/dev/null
  "$sweep" render "$file" -o "$tiles/$name-2.png" --size "$size" --surface wire --curves on --points off >/dev/null
  "$sweep" render "$file" -o "$tiles/$name-3.png" --size "$size" --surface off --curves frames --points on >/dev/null
  labels+=(-label "$name: smooth" "$tiles/$name-1.png" -label "$name: wire + normals" "$tiles/$name-2.png"
           -label "$name: curves + frames + points" "$tiles/$name-3.png")
done
mkdir -p "$(dirname "$out")"
montage -background '#1c1e23' -fill '#d0d4dc' -font DejaVu-Sans -pointsize 13 "${labels[@]}" \
  -tile 6x -geometry +3+3 "$out.tmp.png"
mv "$out.tmp.png" "$out"
echo "wrote $out"
