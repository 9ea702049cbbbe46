#!/usr/bin/env bash
# Configures and builds Sweep into build/ (Release with -Werror unless told otherwise).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SWEEP_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="${SWEEP_BUILD_TYPE:-Release}" -DSWEEP_WERROR=ON "$@" >/dev/null
cmake --build "$build" -j "$(nproc)"
