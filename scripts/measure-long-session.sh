#!/usr/bin/env bash
# Measures a long editing session (issue 29): 10 000 random edit steps (moves, STEPS, undo, redo)
# on swp/wineglass.swp in one EditSession, printing the resident memory every 1 000 steps and its
# growth (goal: under 64 MiB; the history's caps, model/edit/history.hpp, bound it).
# Usage: scripts/measure-long-session.sh   (SWEEP_BUILD_DIR picks the build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tests="${SWEEP_BUILD_DIR:-$root/build}/tests/editor/sweep_editor_tests"
[ -x "$tests" ] || { echo "no $tests: build first (scripts/build.sh)" >&2; exit 1; }
SWEEP_LONG_SESSION=1 "$tests" --gtest_filter=LongSession.TenThousandEditStepsKeepMemoryBounded | grep -E "^(step|edits)|OK|FAILED"
