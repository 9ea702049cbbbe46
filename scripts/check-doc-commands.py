#!/usr/bin/env python3
"""Runs the commands the docs show, as a reader would: every `build/sweep ...` line (and `mkdir`)
of the code blocks in README.md's "A five-minute tour" section, and of each docs/*.md code block
whose opening fence is preceded by the line `<!-- runnable -->`, in order, in a temporary copy of
the repository's swp/ folder with build/sweep there, one block after another in that one folder.
Commands that open the viewer (`sweep view`, or the original form `sweep FILE.swp PREFIX`, which
exports and then opens it) are left out. Prints each command and its exit status; exits 1 when one
fails. Usage: check-doc-commands.py ROOT SWEEP. Run by ctest (docs.commands)."""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

root, sweep = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])


def blocks(path, section=None):
    """The code blocks of `path`: those under the heading `section` (up to the next heading of its
    level or higher), or those right after a `<!-- runnable -->` line."""
    found, current, inside, level, previous = [], None, section is None, 0, ""
    for line in open(path, encoding="utf-8"):
        if current is not None:
            if line.startswith("```"):
                found.append(current)
                current = None
            else:
                current.append(line.rstrip("\n"))
            continue
        heading = re.match(r"(#+) (.*)", line)
        if section is not None and heading:
            if heading.group(2).strip() == section:
                inside, level = True, len(heading.group(1))
            elif inside and len(heading.group(1)) <= level:
                inside = False
        if line.startswith("```") and (section is not None and inside or previous.strip() == "<!-- runnable -->"):
            current = []
        if line.strip():
            previous = line
    return found


def opens_viewer(words):
    if len(words) < 2:
        return True  # `build/sweep` alone: the viewer, empty
    return words[1] == "view" or words[1].endswith(".swp")


def commands():
    pages = [(os.path.join(root, "README.md"), "A five-minute tour")]
    docs = os.path.join(root, "docs")
    pages += [(os.path.join(docs, f), None) for f in sorted(os.listdir(docs)) if f.endswith(".md")]
    for path, section in pages:
        for block in blocks(path, section):
            for line in block:
                command = line.split(" #", 1)[0].strip()
                words = shlex.split(command) if command else []
                if not words or words[0] not in ("build/sweep", "mkdir"):
                    continue
                if words[0] == "build/sweep" and opens_viewer(words):
                    continue
                yield os.path.relpath(path, root), command


with tempfile.TemporaryDirectory() as folder:
    shutil.copytree(os.path.join(root, "swp"), os.path.join(folder, "swp"))
    os.makedirs(os.path.join(folder, "build"))
    os.symlink(sweep, os.path.join(folder, "build", "sweep"))
    failed = 0
    for page, command in commands():
        run = subprocess.run(["bash", "-c", command], cwd=folder, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True, timeout=600)
        print(f"{page}: {command}: exit {run.returncode}")
        if run.returncode != 0:
            failed += 1
            print(run.stderr.strip(), file=sys.stderr)
    sys.exit(1 if failed else 0)
