#!/usr/bin/env bash
# Builds the libFuzzer harnesses for the SWP reader, the SVG drawing reader and the snapshot suite
# reader with clang (address + undefined sanitizers) and fuzzes each for a bounded time
# (SWEEP_FUZZ_SECONDS, default 60, for SWP; SWEEP_SVG_FUZZ_SECONDS, default 20, for SVG;
# SWEEP_SUITE_FUZZ_SECONDS, default 10, for suites; SWEEP_RESULTS_FUZZ_SECONDS, default 10, for the
# snapshot results files `sweep snapshot merge` reads) from the committed corpus, the starter files
# and the recorded regressions. A crash, leak, hang or violated property fails the run and leaves
# the input in the build folder's artifacts/ (copy it to tests/data/fuzz-regressions/, or
# tests/data/svg-fuzz-regressions/, so ctest replays it from then on; a suite input goes to
# fuzz/suite-corpus/, whose every file tests/snapshot/suite_test.cpp replays).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SWEEP_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${SWEEP_FUZZ_SECONDS:-60}"
svg_seconds="${SWEEP_SVG_FUZZ_SECONDS:-20}"
suite_seconds="${SWEEP_SUITE_FUZZ_SECONDS:-10}"
results_seconds="${SWEEP_RESULTS_FUZZ_SECONDS:-10}"
bash "$root/scripts/install-deps.sh"
# -O1 -gline-tables-only: libFuzzer's advised flags (faster to build than -O2 -g; reports keep lines).
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSWEEP_WERROR=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DSWEEP_FUZZ=ON -DSWEEP_GUI=OFF -DSWEEP_TESTS=OFF -DSWEEP_BENCHMARKS=OFF \
  -DSWEEP_SANITIZE=fuzzer-no-link,address,undefined >/dev/null
cmake --build "$build" --target swp_fuzzer svg_fuzzer suite_fuzzer results_fuzzer -j "$(nproc)"

rm -rf "$build/ci-artifacts"
mkdir -p "$build/ci-artifacts"

# fuzz NAME SECONDS MAX_LEN SEEDS -- FOLDERS...: runs fuzz/NAME_fuzzer with fuzz/NAME.dict for
# SECONDS on a fresh working corpus (libFuzzer adds what it finds to the first folder, so the
# committed seeds stay as they are) copied from SEEDS (files), then FOLDERS as they are.
fuzz() {
  local name=$1 time=$2 max_len=$3
  shift 3
  local work="$build/ci-$name-corpus"
  rm -rf "$work"
  mkdir -p "$work"
  local seeds=()
  while [ "$1" != "--" ]; do
    seeds+=("$1")
    shift
  done
  shift
  cp "${seeds[@]}" "$work"/
  echo "Fuzzing the ${name^^} reader for ${time}s"
  "$build/fuzz/${name}_fuzzer" "$work" "$@" -dict="$root/fuzz/$name.dict" -max_total_time="$time" -timeout=10 \
    -rss_limit_mb=2048 -max_len="$max_len" -artifact_prefix="$build/ci-artifacts/" -print_final_stats=1 \
    2>"$build/ci-$name-fuzz.log" || {
    tail -n 60 "$build/ci-$name-fuzz.log"
    echo "fuzzing the ${name^^} reader found a problem; the input is in $build/ci-artifacts/"
    exit 1
  }
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^Done" "$build/ci-$name-fuzz.log" || true
}

fuzz swp "$seconds" 4096 "$root"/fuzz/corpus/* -- "$root/swp" "$root/tests/data/fuzz-regressions"
# The SVG reader: seeds from fuzz/svg-corpus, the test drawings and the drawn example in swp/.
fuzz svg "$svg_seconds" 8192 "$root"/fuzz/svg-corpus/* "$root"/tests/data/svg/*.svg "$root"/swp/*.svg -- \
  "$root/tests/data/svg-fuzz-regressions"
# The suite reader: seeds from fuzz/suite-corpus; lines up to twice the line cap.
fuzz suite "$suite_seconds" 8192 "$root"/fuzz/suite-corpus/* --
# The results file `sweep snapshot merge` reads: seeds from fuzz/results-corpus.
fuzz results "$results_seconds" 16384 "$root"/fuzz/results-corpus/* --
