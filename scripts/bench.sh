#!/usr/bin/env bash
# Compares the benchmarks of the working tree with those of a base revision, side by side.
# Builds benchmarks/sweep_benchmarks (Release, no tests, no GUI) at the working tree, in
# build-bench/new/, and at BASE_REV, in build-bench/old/ from a temporary `git worktree add
# --detach` checkout (removed afterwards). Runs the two binaries alternately (base, new, new,
# base, ...) so that machine load falls on both alike, then prints Google Benchmark's compare.py
# report and a table of the median CPU time per benchmark, base vs new, with a `SLOWER:` line for
# each benchmark more than 5 % slower. It is a report: exits 0 whether or not anything got slower (non-zero only when a
# build or a run fails).
#
# Usage: scripts/bench.sh [BASE_REV]
#   BASE_REV              any revision; default: the merge base of HEAD with the last landed
#                         commit (origin/main, else main)
#   SWEEP_BENCH_FILTER    regex passed as --benchmark_filter (default: every benchmark)
#   SWEEP_BENCH_REPS      --benchmark_repetitions of each run (default 3)
#   SWEEP_BENCH_ROUNDS    runs of each binary, alternating (default 5)
#   SWEEP_BENCH_MIN_TIME  --benchmark_min_time in seconds (default 0.1)
#   SWEEP_BENCH_JOBS      parallel compile jobs (default 2)
# Results (JSON, merged per side, and the logs) stay in build-bench/results/.
#
# Each tree is built through a symlink, build-bench/{new,old}/src, with its build folder beside it
# in build-bench/{new,old}/build: the absolute source path compiled into the benchmarks
# (SWEEP_SWP_DIR) then has the same length in both, so identical sources give identical code
# layout (with the checkout's longer path the two builds of one commit differed by 116 bytes of
# code), and ccache sees the same relative paths for both trees. Repetitions within one process
# agree to a few percent, while processes of one binary differed by up to 40 % as other builds
# came and went, hence many short alternating rounds rather than a few long ones.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bench_dir="$root/build-bench"
results="$bench_dir/results"
reps="${SWEEP_BENCH_REPS:-3}"
rounds="${SWEEP_BENCH_ROUNDS:-5}"
min_time="${SWEEP_BENCH_MIN_TIME:-0.1}"
jobs="${SWEEP_BENCH_JOBS:-2}"
filter="${SWEEP_BENCH_FILTER:-}"
threshold=5

if [ $# -gt 1 ]; then
  echo "usage: scripts/bench.sh [BASE_REV]" >&2
  exit 2
fi

# The base revision: the one given, or the merge base with the last landed commit.
if [ $# -eq 1 ]; then
  base_rev="$1"
else
  landed=""
  for ref in origin/main main origin/master master; do
    if git rev-parse -q --verify "$ref^{commit}" >/dev/null; then landed="$ref"; break; fi
  done
  if [ -z "$landed" ]; then
    echo "bench.sh: no main branch to take the merge base with; pass BASE_REV" >&2
    exit 2
  fi
  base_rev="$(git merge-base HEAD "$landed")"
fi
if ! base_sha="$(git rev-parse -q --verify "$base_rev^{commit}")"; then
  echo "bench.sh: '$base_rev' is not a revision" >&2
  exit 2
fi

cmake_args=(-DCMAKE_BUILD_TYPE=Release -DSWEEP_TESTS=OFF -DSWEEP_GUI=OFF -DSWEEP_BENCHMARKS=ON
            -DSWEEP_PRECONDITIONS=OFF)
if command -v ccache >/dev/null; then
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths relative to the build folder: the two trees and repeated runs share the cache.
  if [ -z "$(ccache -k base_dir 2>/dev/null || true)" ]; then export CCACHE_BASEDIR="$root"; fi
fi

# builds TREE SIDE LABEL: configures and builds sweep_benchmarks of TREE through the symlink
# build-bench/SIDE/src, in build-bench/SIDE/build; logs there.
build() {
  local tree="$1" side="$2" label="$3" src="$bench_dir/$2/src" dir="$bench_dir/$2/build"
  mkdir -p "$dir"
  ln -sfn "$tree" "$src"
  echo "Building $label in ${dir#"$root"/} ..."
  if ! cmake -S "$src" -B "$dir" "${cmake_args[@]}" >"$dir/configure.log" 2>&1; then
    tail -n 30 "$dir/configure.log" >&2
    echo "bench.sh: configuring $label failed (log: $dir/configure.log)" >&2
    exit 1
  fi
  if [ ! -d "$dir/benchmarks" ]; then  # benchmarks/ is only added when benchmark is found
    echo "bench.sh: $label has no sweep_benchmarks target (is Google Benchmark, libbenchmark-dev, installed?)" >&2
    exit 1
  fi
  if ! cmake --build "$dir" --target sweep_benchmarks -j "$jobs" >"$dir/build.log" 2>&1; then
    tail -n 40 "$dir/build.log" >&2
    echo "bench.sh: building $label failed (log: $dir/build.log)" >&2
    exit 1
  fi
}

base_tree=""
cleanup() {
  if [ -n "$base_tree" ] && [ -d "$base_tree" ]; then
    git -C "$root" worktree remove --force "$base_tree" 2>/dev/null || rm -rf "$base_tree"
    git -C "$root" worktree prune
    rm -f "$bench_dir/old/src"
  fi
}
trap cleanup EXIT

mkdir -p "$bench_dir"
rm -rf "$results"
mkdir -p "$results"

dirty=""
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then dirty=" + uncommitted changes"; fi
echo "base: $(git log -1 --format='%h %s' "$base_sha" | cut -c1-100)"
echo "new:  working tree at $(git log -1 --format='%h' HEAD)$dirty"

base_tree="$(mktemp -d "${TMPDIR:-/tmp}/sweep-bench-base.XXXXXX")"
git worktree add --detach --quiet "$base_tree" "$base_sha"
build "$base_tree" old "base ($(git rev-parse --short "$base_sha"))"
build "$root" new "new (working tree)"

run_args=(--benchmark_repetitions="$reps" --benchmark_min_time="$min_time"
          --benchmark_display_aggregates_only=true --benchmark_out_format=json)
if [ -n "$filter" ]; then run_args+=(--benchmark_filter="$filter"); fi

# runs SIDE ROUND: one run of that side's binary, JSON and console log into results/.
run() {
  local side="$1" round="$2" bin
  # Paths of equal length: argv[0]'s length shifts the stack (3-5 % on one benchmark here).
  if [ "$side" = base ]; then bin="$bench_dir/old/build/benchmarks/sweep_benchmarks"
  else bin="$bench_dir/new/build/benchmarks/sweep_benchmarks"; fi
  echo "  round $round: $side"
  if ! (cd "$results" && "$bin" "${run_args[@]}" --benchmark_out="$results/$side.$round.json") >"$results/$side.$round.log" 2>&1; then
    tail -n 20 "$results/$side.$round.log" >&2
    echo "bench.sh: the $side benchmarks failed (log: $results/$side.$round.log)" >&2
    exit 1
  fi
}

echo "Running $rounds rounds of $reps repetitions each (min time ${min_time}s)${filter:+, filter '$filter'} ..."
for ((r = 1; r <= rounds; r++)); do
  if ((r % 2)); then run base "$r"; run new "$r"; else run new "$r"; run base "$r"; fi
done

# Python with scipy for compare.py (pyenv shims may hide the Debian one).
py=python3
if ! python3 -c 'import scipy, numpy' 2>/dev/null && /usr/bin/python3 -c 'import scipy, numpy' 2>/dev/null; then
  py=/usr/bin/python3
fi

# Merges the rounds of each side into results/{base,new}.json (every repetition, plus recomputed
# mean, median and stddev) and prints the median table with the SLOWER: lines.
table="$("$py" - "$results" "$rounds" "$threshold" <<'PY'
import json, statistics, sys
results, rounds, threshold = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])

def merge(side):
    context, runs, order = None, {}, []
    for r in range(1, rounds + 1):
        with open(f"{results}/{side}.{r}.json") as f:
            data = json.load(f)
        context = context or data["context"]
        for b in data["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
                continue
            name = b.get("run_name", b["name"])
            if name not in runs:
                runs[name] = []
                order.append(name)
            runs[name].append(b)
    out = []
    for name in order:
        reps = runs[name]
        for i, b in enumerate(reps):
            out.append(dict(b, repetition_index=i, repetitions=len(reps)))
        for agg, fn in (("mean", statistics.mean), ("median", statistics.median),
                        ("stddev", lambda v: statistics.stdev(v) if len(v) > 1 else 0.0)):
            first = reps[0]
            out.append({
                "name": f"{name}_{agg}", "family_index": first.get("family_index", 0),
                "per_family_instance_index": first.get("per_family_instance_index", 0),
                "run_name": name, "run_type": "aggregate", "repetitions": len(reps),
                "threads": first.get("threads", 1), "aggregate_name": agg, "aggregate_unit": "time",
                "iterations": len(reps), "time_unit": first["time_unit"],
                "real_time": fn([b["real_time"] for b in reps]),
                "cpu_time": fn([b["cpu_time"] for b in reps]),
            })
    with open(f"{results}/{side}.json", "w") as f:
        json.dump({"context": context, "benchmarks": out}, f, indent=1)
    return {n: (statistics.median(b["cpu_time"] for b in runs[n]), runs[n][0]["time_unit"]) for n in order}, order

base, _ = merge("base")
new, order = merge("new")
names = order + [n for n in base if n not in new]
width = max([len(n) for n in names] + [9])
print(f"{'benchmark':<{width}}  {'base cpu':>12}  {'new cpu':>12}  {'change':>8}")
slower = []
for n in names:
    if n not in base or n not in new:
        b = f"{base[n][0]:.3f} {base[n][1]}" if n in base else "-"
        c = f"{new[n][0]:.3f} {new[n][1]}" if n in new else "-"
        print(f"{n:<{width}}  {b:>12}  {c:>12}  {'only ' + ('base' if n in base else 'new'):>8}")
        continue
    (b, unit), (c, unit_new) = base[n], new[n]
    change = (c - b) / b * 100 if b > 0 else 0.0
    mark = "  <-- slower" if change > threshold else ""
    print(f"{n:<{width}}  {b:>9.3f} {unit:<2}  {c:>9.3f} {unit_new:<2}  {change:>+7.1f}%{mark}")
    if change > threshold:
        slower.append(f"SLOWER: {n}: median CPU {b:.3f} {unit} -> {c:.3f} {unit_new} ({change:+.1f} %)")
print()
print("\n".join(slower) if slower else f"No benchmark is more than {threshold:g} % slower (median CPU time).")
PY
)"

compare="$(dpkg -L libbenchmark-tools 2>/dev/null | grep '/compare\.py$' | head -n 1 || true)"
echo
if [ -n "$compare" ] && "$py" -c 'import scipy, numpy' 2>/dev/null; then
  echo "== compare.py (base vs new; aggregates over $((rounds * reps)) repetitions, negative is faster) =="
  "$py" "$compare" --no-color -a benchmarks "$results/base.json" "$results/new.json" | sed '/^Comparing /d'
else
  echo "(compare.py skipped: install libbenchmark-tools and python3-scipy, see scripts/install-deps.sh)"
fi
echo
echo "== median CPU time over $((rounds * reps)) repetitions per side =="
echo "$table"
echo
echo "Results: ${results#"$root"/}/{base,new}.json"
