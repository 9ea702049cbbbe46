#!/usr/bin/env python3
"""Runs the two CI recipes of docs/screenshot-regression.md (GitHub Actions and GitLab CI) on this
machine, step by step: each shard's `sweep snapshot` line with the CI's variables filled in, the
artifacts moved where the next job finds them, then the merge job's line. The merged report must
hold what one unsharded run writes (its results file, without times) and exit as that run does.

Usage: ci_recipe_test.py DOC SWEEP SWP_DIR WORK_DIR"""
import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

SHARDS = 3


def yaml_block(doc, heading):
    """The first ```yaml block after the line that starts with `heading`."""
    at = doc.index(heading)
    start = doc.index("```yaml\n", at) + len("```yaml\n")
    return doc[start:doc.index("```", start)]


def sweep_lines(block, prefix):
    """The recipe's `sweep` commands, in order (install and build are this test's build)."""
    lines = [line.strip()[len(prefix):] for line in block.splitlines() if line.strip().startswith(prefix)]
    return [line for line in lines if line.startswith("build/sweep ")]


def run(command, cwd, sweep):
    line = command.replace("build/sweep", shlex.quote(sweep), 1)
    done = subprocess.run(line, shell=True, cwd=cwd, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def untimed_cases(report):
    cases = json.loads((report / "results.json").read_text())["cases"]
    for case in cases:
        case.pop("seconds")
        case.pop("render_seconds")
    return cases


def models_with_one_change(work, swp, sweep):
    """models/ with references, then one control point of the wineglass moved: 3 cases fail."""
    shutil.rmtree(work, ignore_errors=True)
    (work / "models").mkdir(parents=True)
    for stem in ("wineglass", "circles", "tor"):
        shutil.copy(swp / f"{stem}.swp", work / "models")
    status, out = run("build/sweep snapshot models/ -q --update", work, sweep)
    assert status == 0, out
    glass = work / "models" / "wineglass.swp"
    text = glass.read_text()
    assert "[-1.164785 1.105511]" in text
    glass.write_text(text.replace("[-1.164785 1.105511]", "[-1.214785 1.105511]"))


def check(name, work, sweep, shard_steps, merge_step, artifact):
    """Runs the shard steps (for K = 1..SHARDS), `artifact(work, k)` after each, then the merge."""
    status, out = run("build/sweep snapshot models/ -q --report whole", work, sweep)
    assert status == 1, f"{name}: the unsharded run exits {status}\n{out}"
    for k in range(1, SHARDS + 1):
        for step in shard_steps:
            line = step.replace("${{ matrix.shard }}", str(k)).replace("$CI_NODE_INDEX", str(k))
            run(line.replace("$CI_NODE_TOTAL", str(SHARDS)), work, sweep)
        artifact(work, k)
    merged, out = run(merge_step, work, sweep)
    assert merged == status, f"{name}: merge exits {merged}, the unsharded run {status}\n{out}"
    assert untimed_cases(work / "report") == untimed_cases(work / "whole"), f"{name}: merged results differ"
    junit = (work / "report" / "junit.xml").read_text()
    assert re.search(r'tests="9" failures="3" errors="0"', junit), junit[:400]
    print(f"{name}: {SHARDS} shards merged as one run ({out.splitlines()[0]})")


def github_artifact(work, k):
    """upload-artifact of report/ as report-K, download-artifact into shards/report-K."""
    (work / "shards").mkdir(exist_ok=True)
    shutil.move(str(work / "report"), str(work / "shards" / f"report-{k}"))


def main():
    doc_path, sweep = sys.argv[1], str(Path(sys.argv[2]).resolve())
    swp, work = Path(sys.argv[3]).resolve(), Path(sys.argv[4]).resolve()
    doc = Path(doc_path).read_text()
    github = sweep_lines(yaml_block(doc, "GitHub Actions, a matrix"), "- run: ")
    gitlab = sweep_lines(yaml_block(doc, "GitLab CI, `parallel:`"), "- ")
    assert len(github) == 2 and len(gitlab) == 2, (github, gitlab)
    models_with_one_change(work / "github", swp, sweep)
    check("GitHub Actions", work / "github", sweep, github[:1], github[1], github_artifact)
    models_with_one_change(work / "gitlab", swp, sweep)
    check("GitLab CI", work / "gitlab", sweep, gitlab[:1], gitlab[1], lambda work, k: None)


if __name__ == "__main__":
    main()
