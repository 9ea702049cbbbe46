#!/usr/bin/env bash
# Builds the libFuzzer harnesses for the SWP reader and the SVG drawing reader with clang
# (address + undefined sanitizers) and fuzzes each for a bounded time (SWEEP_FUZZ_SECONDS, default
# 60, for SWP; SWEEP_SVG_FUZZ_SECONDS, default 20, for SVG) from the committed corpus, the starter
# files and the recorded regressions. A crash, leak, hang or violated property fails the run and
# leaves the input in the build folder's artifacts/ (copy it to tests/data/fuzz-regressions/, or
# tests/data/svg-fuzz-regressions/, so ctest replays it from then on).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SWEEP_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${SWEEP_FUZZ_SECONDS:-60}"
svg_seconds="${SWEEP_SVG_FUZZ_SECONDS:-20}"
bash "$root/scripts/install-deps.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSWEEP_WERROR=ON \
  -DSWEEP_FUZZ=ON -DSWEEP_GUI=OFF -DSWEEP_TESTS=OFF -DSWEEP_BENCHMARKS=OFF \
  -DSWEEP_SANITIZE=fuzzer-no-link,address,undefined >/dev/null
cmake --build "$build" --target swp_fuzzer svg_fuzzer -j "$(nproc)"

# libFuzzer adds what it finds to the first folder; the committed corpus stays as it is.
work="$build/ci-corpus"
rm -rf "$work" "$build/ci-artifacts"
mkdir -p "$work" "$build/ci-artifacts"
cp "$root"/fuzz/corpus/* "$work"/ 2>/dev/null || true
echo "Fuzzing the SWP reader for ${seconds}s"
"$build/fuzz/swp_fuzzer" "$work" "$root/swp" "$root/tests/data/fuzz-regressions" \
  -dict="$root/fuzz/swp.dict" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -artifact_prefix="$build/ci-artifacts/" -print_final_stats=1 2>"$build/ci-fuzz.log" || {
  tail -n 60 "$build/ci-fuzz.log"
  echo "fuzzing found a problem; the input is in $build/ci-artifacts/"
  exit 1
}
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^Done" "$build/ci-fuzz.log" || true

# The SVG reader: seeds from fuzz/svg-corpus, the test drawings and the drawn example in swp/.
svg_work="$build/ci-svg-corpus"
rm -rf "$svg_work"
mkdir -p "$svg_work"
cp "$root"/fuzz/svg-corpus/* "$root"/tests/data/svg/*.svg "$root"/swp/*.svg "$svg_work"/ 2>/dev/null || true
echo "Fuzzing the SVG reader for ${svg_seconds}s"
"$build/fuzz/svg_fuzzer" "$svg_work" "$root/tests/data/svg-fuzz-regressions" \
  -dict="$root/fuzz/svg.dict" -max_total_time="$svg_seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -artifact_prefix="$build/ci-artifacts/" -print_final_stats=1 2>"$build/ci-svg-fuzz.log" || {
  tail -n 60 "$build/ci-svg-fuzz.log"
  echo "fuzzing the SVG reader found a problem; the input is in $build/ci-artifacts/"
  exit 1
}
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^Done" "$build/ci-svg-fuzz.log" || true
