#!/usr/bin/env python3
"""Prints a Markdown table of every benchmark's median wall time, before and after, from the
merged results scripts/bench.sh writes (build-bench/results/*.json, or benchmarks/baseline.json).

Usage: scripts/bench-table.py BEFORE.json AFTER.json [AFTER_ONE_THREAD.json]

Columns: the benchmark, its median wall time in BEFORE, in AFTER, AFTER / BEFORE, and, when a third
file is given (a run with SWEEP_THREADS=1), the median wall time on one thread. A benchmark missing
from a file shows "-". Wall time (real_time), not CPU time: with threads, CPU time is one thread's.
"""
import json
import sys

TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
# A benchmark that came to measure wall time across its threads has this suffix now: the same one.
WALL_SUFFIX = "/process_time/real_time"


def medians(path):
    """The median wall time (ms) per benchmark name, in the file's order."""
    out = {}
    for run in json.load(open(path))["benchmarks"]:
        if run.get("run_type") == "aggregate" and run.get("aggregate_name") == "median":
            name = run["run_name"].removesuffix(WALL_SUFFIX)
            out[name] = run["real_time"] * TO_MS[run.get("time_unit", "ns")]
    return out


def shown(ms):
    if ms is None:
        return "-"
    if ms >= 100:
        return "%.0f ms" % ms
    if ms >= 1:
        return "%.1f ms" % ms
    return "%.3f ms" % ms


def main(argv):
    if len(argv) not in (3, 4):
        sys.exit(__doc__)
    before, after = medians(argv[1]), medians(argv[2])
    one = medians(argv[3]) if len(argv) == 4 else None
    names = list(after) + [n for n in before if n not in after]
    header = "| benchmark | before | after | after / before |"
    rule = "| --- | --- | --- | --- |"
    if one is not None:
        header += " after, one thread |"
        rule += " --- |"
    print(header)
    print(rule)
    for name in names:
        b, a = before.get(name), after.get(name)
        ratio = "%.2f" % (a / b) if a is not None and b else "-"
        row = "| `%s` | %s | %s | %s |" % (name, shown(b), shown(a), ratio)
        if one is not None:
            row += " %s |" % shown(one.get(name))
        print(row)


if __name__ == "__main__":
    main(sys.argv)
