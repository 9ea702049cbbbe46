#!/usr/bin/env bash
# Quick start: install what is missing, build, and open the viewer on the default scene.
# Without a display it says so and renders the scene to a PNG headless instead.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
scene="${1:-$root/swp/wineglass.swp}"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$root/build/sweep" view "$scene"
fi
out="$root/build/$(basename "${scene%.swp}").png"
echo "No display found (DISPLAY is not set): rendering $scene headless to $out instead."
exec "$root/build/sweep" render "$scene" -o "$out"
