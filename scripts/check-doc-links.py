#!/usr/bin/env python3
"""Checks every relative link of README.md and docs/*.md: the file it names exists and, for a
link to a heading (FILE.md#anchor or #anchor), the heading is there (GitHub's anchors: lower case,
punctuation dropped, spaces as hyphens). Prints each broken link as FILE:LINE: link and exits 1
if there is one. Run by ctest (docs.links)."""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
pages = [os.path.join(root, "README.md")] + sorted(
    os.path.join(root, "docs", f) for f in os.listdir(os.path.join(root, "docs")) if f.endswith(".md"))


def slug(heading):
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    found, fenced = set(), False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and line.startswith("#"):
            found.add(slug(line.lstrip("#")))
    return found


broken = 0
for page in pages:
    fenced = False
    for number, line in enumerate(open(page, encoding="utf-8"), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for target in re.findall(r"\]\(([^)\s]+)\)", line):
            if re.match(r"[a-z]+:", target):
                continue  # http:, https:, mailto:
            path, _, anchor = target.partition("#")
            file = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            ok = os.path.exists(file)
            if ok and anchor and file.endswith(".md"):
                ok = anchor in anchors(file)
            if not ok:
                print(f"{os.path.relpath(page, root)}:{number}: {target}")
                broken += 1
print(f"{len(pages)} pages checked, {broken} broken links")
sys.exit(1 if broken else 0)
