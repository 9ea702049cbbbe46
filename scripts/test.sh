#!/usr/bin/env bash
# Install what is missing, build with -Wall -Wextra -Werror, and run every test through ctest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
cd "${SWEEP_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)"
