#!/usr/bin/env bash
# Sweep from Python against scipy (issue 57): benchmarks/python/curve_speed.py with the module of
# the build tree and Debian's interpreter (python3-numpy, python3-scipy). Builds nothing.
# Usage: scripts/measure-python.sh [BUILD_DIR]   (default: $SWEEP_BUILD_DIR or build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-${SWEEP_BUILD_DIR:-$root/build}}"
[ -d "$build/python/sweep" ] || { echo "no $build/python/sweep: build first (scripts/build.sh)" >&2; exit 1; }
PYTHONPATH="$build/python" exec /usr/bin/python3 "$root/benchmarks/python/curve_speed.py"
