#!/usr/bin/env bash
# Runs the benchmarks (benchmarks/sweep_benchmarks) and compares them, in one of three modes:
#
#   scripts/bench.sh                    against the committed baseline, benchmarks/baseline.json
#   scripts/bench.sh --update-baseline  measures anew and rewrites benchmarks/baseline.json
#   scripts/bench.sh --against [REV]    against a build of REV, run alternately in this run
#   --quick (or SWEEP_BENCH_QUICK=1)    with the first or the last: 1 round of 1 repetition,
#                                       min time 0.05 s (CI's report)
#
# Every mode builds sweep_benchmarks (Release, no tests, no GUI, ccache if present) at the working
# tree, uncommitted changes included, in build-bench/new/, runs it SWEEP_BENCH_ROUNDS times and
# merges the runs into results/new.json: every repetition plus recomputed mean, median and stddev.
#
# Baseline (no argument): prints Google Benchmark's compare.py report (`compare.py -a benchmarks
# baseline.json new.json`, libbenchmark-tools) and a table of the median CPU time per benchmark,
# baseline vs new, with a `WORSE:` line for each benchmark more than 15 % slower. The baseline
# was measured in another process at another time, perhaps in a checkout at a path of another
# length (which shifts the code layout, see below), so only a large change means anything: the
# threshold is wide, and a WORSE: line wants an --against run before it is believed.
#
# --update-baseline: the same run, the same report against the old baseline, then writes the
# merged aggregates (median, mean, stddev per benchmark; no single repetitions, compare.py -a
# needs none) into benchmarks/baseline.json, with the machine (num_cpus, mhz_per_cpu, cpu_model,
# load) and the commit in its context block. A change that makes a figure better commits the new
# baseline with it; one that makes a figure worse says why in its commit message. Refused with
# --quick or any SWEEP_BENCH_* setting but JOBS: a baseline covers every benchmark at the full
# settings, so that regenerating it is this one command.
#
# --against [REV]: also builds REV (default: the merge base of HEAD with the last landed commit,
# origin/main, else main) in build-bench/old/ from a temporary `git worktree add --detach`
# checkout (removed afterwards), runs the two binaries alternately (base, new, new, base, ...) so
# that machine load falls on both alike, and prints compare.py's report and the median table with
# a `SLOWER:` line for each benchmark more than 5 % slower. Same-run figures are the only ones
# to trust on a shared machine: use this to decide whether a change made something slower.
#
# Every mode is a report: exits 0 whether or not anything got slower (1 when a build or a run
# fails, 2 on a usage error or a missing baseline).
#
#   SWEEP_BENCH_FILTER    regex passed as --benchmark_filter (default: every benchmark)
#   SWEEP_BENCH_REPS      --benchmark_repetitions of each run (default 3; --quick: 1)
#   SWEEP_BENCH_ROUNDS    runs of each binary, alternating (default 5; --quick: 1)
#   SWEEP_BENCH_MIN_TIME  --benchmark_min_time in seconds (default 0.1; --quick: 0.05)
#   SWEEP_BENCH_JOBS      parallel compile jobs (default 2)
#   SWEEP_BENCH_QUICK     1: the same as --quick
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
baseline="$root/benchmarks/baseline.json"

usage() {
  echo "usage: scripts/bench.sh [--quick] [--update-baseline | --against [REV]]" >&2
  exit 2
}
mode=baseline
quick="${SWEEP_BENCH_QUICK:-0}"
base_rev=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --update-baseline) [ "$mode" = baseline ] || usage; mode=update ;;
    --against)
      [ "$mode" = baseline ] || usage
      mode=against
      if [ $# -gt 1 ] && [ "${2#--}" = "$2" ]; then base_rev="$2"; shift; fi
      ;;
    *) usage ;;
  esac
  shift
done
if [ "$quick" != 0 ] && [ "$quick" != 1 ]; then
  echo "bench.sh: SWEEP_BENCH_QUICK is 0 or 1" >&2
  exit 2
fi

if [ "$quick" = 1 ]; then reps_default=1 rounds_default=1 min_time_default=0.05
else reps_default=3 rounds_default=5 min_time_default=0.1; fi
reps="${SWEEP_BENCH_REPS:-$reps_default}"
rounds="${SWEEP_BENCH_ROUNDS:-$rounds_default}"
min_time="${SWEEP_BENCH_MIN_TIME:-$min_time_default}"
jobs="${SWEEP_BENCH_JOBS:-2}"
filter="${SWEEP_BENCH_FILTER:-}"

if [ "$mode" = update ]; then
  if [ "$quick" = 1 ] || [ -n "$filter" ] || [ -n "${SWEEP_BENCH_REPS:-}${SWEEP_BENCH_ROUNDS:-}${SWEEP_BENCH_MIN_TIME:-}" ]; then
    echo "bench.sh: --update-baseline measures every benchmark at the full settings: unset SWEEP_BENCH_QUICK, SWEEP_BENCH_FILTER, SWEEP_BENCH_REPS, SWEEP_BENCH_ROUNDS and SWEEP_BENCH_MIN_TIME, no --quick" >&2
    exit 2
  fi
elif [ "$mode" = baseline ] && [ ! -f "$baseline" ]; then
  echo "bench.sh: no ${baseline#"$root"/}; make one with scripts/bench.sh --update-baseline" >&2
  exit 2
fi

# The base revision of --against: the one given, or the merge base with the last landed commit.
base_sha=""
if [ "$mode" = against ]; then
  if [ -z "$base_rev" ]; then
    landed=""
    for ref in origin/main main origin/master master; do
      if git rev-parse -q --verify "$ref^{commit}" >/dev/null; then landed="$ref"; break; fi
    done
    if [ -z "$landed" ]; then
      echo "bench.sh: no main branch to take the merge base with; pass --against REV" >&2
      exit 2
    fi
    base_rev="$(git merge-base HEAD "$landed")"
  fi
  if ! base_sha="$(git rev-parse -q --verify "$base_rev^{commit}")"; then
    echo "bench.sh: '$base_rev' is not a revision" >&2
    exit 2
  fi
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

# Python with scipy for compare.py (pyenv shims may hide the Debian one).
py=python3
if ! python3 -c 'import scipy, numpy' 2>/dev/null && /usr/bin/python3 -c 'import scipy, numpy' 2>/dev/null; then
  py=/usr/bin/python3
fi

# The JSON work, as subcommands:
#   merge RESULTS SIDE ROUNDS: merges RESULTS/SIDE.{1..ROUNDS}.json into RESULTS/SIDE.json (every
#     repetition, plus recomputed mean, median and stddev over all of them);
#   describe FILE: one line saying where and when FILE's figures were measured;
#   table OLD NEW LABEL THRESHOLD MARK: the median CPU table of OLD vs NEW, with a `MARK:` line
#     for each benchmark more than THRESHOLD % slower in NEW;
#   baseline NEW OUT COMMIT ROUNDS REPS MIN_TIME: writes NEW's aggregates alone into OUT, with
#     the machine and the settings added to its context.
py_code="$(cat <<'PY'
import json, os, statistics, sys

def load(path):
    with open(path) as f:
        return json.load(f)

def merge(results, side, rounds):
    context, runs, order = None, {}, []
    for r in range(1, rounds + 1):
        data = load(f"{results}/{side}.{r}.json")
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

def medians(path):
    """{run_name: (median cpu_time, time_unit, repetitions)}, in the file's order."""
    return {b["run_name"]: (b["cpu_time"], b["time_unit"], b.get("repetitions", 1))
            for b in load(path)["benchmarks"]
            if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median"}

def describe(path):
    c = load(path)["context"]
    s = c.get("sweep", {})
    load_avg = " ".join(f"{x:.1f}" for x in c.get("load_avg", []))
    where = f"{c.get('num_cpus', '?')} x {c.get('mhz_per_cpu', '?')} MHz"
    if s.get("cpu_model"):
        where += f" ({s['cpu_model']})"
    what = f"commit {s['commit']}, " if s.get("commit") else ""
    how = (f", {s['rounds']} rounds x {s['repetitions']} repetitions, min time {s['min_time']} s"
           if s.get("rounds") else "")
    print(f"{what}{c.get('date', '?')} on {where}, load {load_avg or '?'}{how}")

def table(old_path, new_path, label, threshold, mark):
    old, new = medians(old_path), medians(new_path)
    names = list(new) + [n for n in old if n not in new]
    width = max([len(n) for n in names] + [9])
    print(f"{'benchmark':<{width}}  {label + ' cpu':>12}  {'new cpu':>12}  {'change':>8}")
    worse, missing = [], []
    for n in names:
        if n not in old or n not in new:
            b = f"{old[n][0]:.3f} {old[n][1]}" if n in old else "-"
            c = f"{new[n][0]:.3f} {new[n][1]}" if n in new else "-"
            print(f"{n:<{width}}  {b:>12}  {c:>12}  {'only ' + (label if n in old else 'new'):>8}")
            missing.append(n)
            continue
        (b, unit, _), (c, unit_new, _) = old[n], new[n]
        if unit != unit_new:
            print(f"{n:<{width}}  {b:>9.3f} {unit:<2}  {c:>9.3f} {unit_new:<2}  {'units?':>8}")
            continue
        change = (c - b) / b * 100 if b > 0 else 0.0
        flag = f"  <-- {mark.lower()}" if change > threshold else ""
        print(f"{n:<{width}}  {b:>9.3f} {unit:<2}  {c:>9.3f} {unit_new:<2}  {change:>+7.1f}%{flag}")
        if change > threshold:
            worse.append(f"{mark}: {n}: median CPU {b:.3f} {unit} -> {c:.3f} {unit_new} ({change:+.1f} %)")
    print()
    if missing:
        print(f"({len(missing)} benchmark(s) measured on one side only)")
    print("\n".join(worse) if worse else
          f"No benchmark is more than {threshold:g} % slower (median CPU time).")

def baseline(new_path, out, commit, rounds, reps, min_time):
    data = load(new_path)
    context = data["context"]
    context.pop("executable", None)  # build-bench/...: says nothing about the machine
    cpu_model = ""
    try:
        with open("/proc/cpuinfo") as f:
            cpu_model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "")
    except OSError:
        pass
    context["sweep"] = {
        "commit": commit, "cpu_model": cpu_model,
        "load_avg_at_end": [round(float(x), 2) for x in open("/proc/loadavg").read().split()[:3]],
        "rounds": int(rounds), "repetitions": int(reps), "min_time": float(min_time),
        "regenerate": "bash scripts/bench.sh --update-baseline",
    }
    context["load_avg"] = [round(x, 2) for x in context.get("load_avg", [])]
    aggregates = [b for b in data["benchmarks"] if b.get("run_type") == "aggregate"]
    # The context indented, one benchmark a line: a new baseline's diff reads line by line.
    text = json.dumps({"context": context, "benchmarks": []}, indent=1)
    rows = ",\n".join("  " + json.dumps(b) for b in aggregates)
    with open(out, "w") as f:
        f.write(text[: text.rindex("[]")] + "[\n" + rows + "\n ]\n}\n")

cmd, args = sys.argv[1], sys.argv[2:]
if cmd == "merge":
    merge(args[0], args[1], int(args[2]))
elif cmd == "describe":
    describe(args[0])
elif cmd == "table":
    table(args[0], args[1], args[2], float(args[3]), args[4])
elif cmd == "baseline":
    baseline(*args)
PY
)"
pyjson() { "$py" -c "$py_code" "$@"; }

dirty=""
# Changes that cannot reach the binary do not count (a baseline written by an earlier
# --update-baseline is the output, the scripts and the docs are not compiled).
if [ -n "$(git status --porcelain --untracked-files=no -- . ':!benchmarks/baseline.json' \
             ':!scripts' ':!.ci' ':!docs' ':!*.md')" ]; then
  dirty=" + uncommitted changes"
fi
case "$mode" in
  against) echo "base:     $(git log -1 --format='%h %s' "$base_sha" | cut -c1-100)" ;;
  *) echo "baseline: $(pyjson describe "$baseline" 2>/dev/null || echo "none (${baseline#"$root"/} is missing)")" ;;
esac
echo "new:      working tree at $(git log -1 --format='%h' HEAD)$dirty, load $(cut -d' ' -f1-3 /proc/loadavg)"

if [ "$mode" = against ]; then
  base_tree="$(mktemp -d "${TMPDIR:-/tmp}/sweep-bench-base.XXXXXX")"
  git worktree add --detach --quiet "$base_tree" "$base_sha"
  build "$base_tree" old "base ($(git rev-parse --short "$base_sha"))"
fi
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

# shellcheck disable=SC2016  # the quotes around $filter are inside double quotes: it expands
echo "Running $rounds round(s) of $reps repetition(s) each (min time ${min_time}s)${filter:+, filter '$filter'} ..."
for ((r = 1; r <= rounds; r++)); do
  if [ "$mode" != against ]; then run new "$r"
  elif ((r % 2)); then run base "$r"; run new "$r"
  else run new "$r"; run base "$r"; fi
done

pyjson merge "$results" new "$rounds"
if [ "$mode" = against ]; then
  pyjson merge "$results" base "$rounds"
  old_json="$results/base.json" label=base threshold=5 mark=SLOWER
else
  old_json="$baseline" label=baseline threshold=15 mark=WORSE
fi

compare="$(dpkg -L libbenchmark-tools 2>/dev/null | grep '/compare\.py$' | head -n 1 || true)"
if [ -f "$old_json" ]; then
  echo
  if [ -n "$compare" ] && "$py" -c 'import scipy, numpy' 2>/dev/null; then
    echo "== compare.py ($label vs new; aggregates, negative is faster) =="
    # (without the stddev rows: a change in the spread of a few repetitions says little)
    "$py" "$compare" --no-color -a benchmarks "$old_json" "$results/new.json" | sed '/^Comparing /d; /_stddev /d'
  else
    echo "(compare.py skipped: install libbenchmark-tools and python3-scipy, see scripts/install-deps.sh)"
  fi
  echo
  echo "== median CPU time, $label vs new ($((rounds * reps)) repetition(s) of new) =="
  pyjson table "$old_json" "$results/new.json" "$label" "$threshold" "$mark"
fi

if [ "$mode" = update ]; then
  commit="$(git rev-parse --short=12 HEAD)${dirty:+-dirty}"
  pyjson baseline "$results/new.json" "$baseline" "$commit" "$rounds" "$reps" "$min_time"
  echo
  echo "Wrote ${baseline#"$root"/} (commit $commit): commit it with the change that made a figure better."
fi
echo
echo "Results: ${results#"$root"/}/$([ "$mode" = against ] && echo '{base,new}' || echo new).json"
