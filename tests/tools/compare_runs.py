#!/usr/bin/env python3
"""Compares two trees of relslam run folders (e.g. scripts/reproduce.sh --quick before and after a
change) and prints every difference outside the measured times.

    tests/tools/compare_runs.py BEFORE AFTER

CSV files are compared cell by cell, except timing columns (wall-clock milliseconds, seconds,
memory): their names are listed in TIMING below. TUM trajectories must be byte-identical.
manifest.json files are compared with the fields that name the machine, the time, the build or
the data folder removed. Other files (images, logs, the HTML report) are not compared. Exit 0 when nothing
differs, 1 otherwise.
"""
import csv
import json
import re
import sys
from pathlib import Path

# Columns holding measured times or memory, not results.
TIMING = re.compile(r"(^t_\w+_ms$|_ms$|^runtime|seconds|_s$|^peak_rss_mb$|^time_per|^ms_|_ms_|^wall)")
# manifest.json fields that name the machine, the moment or the build, not the result.
MANIFEST_VOLATILE = {"created_utc", "host", "git", "wall_time_s", "libraries", "relslam_version", "command_line", "data"}


def timing_column(name):
    return bool(TIMING.search(name))


def compare_csv(a, b, problems, rel):
    with open(a, newline="") as fa, open(b, newline="") as fb:
        ra, rb = list(csv.reader(fa)), list(csv.reader(fb))
    if not ra or not rb:
        if ra != rb:
            problems.append(f"{rel}: one file is empty")
        return
    if ra[0] != rb[0]:
        problems.append(f"{rel}: header differs:\n  {ra[0]}\n  {rb[0]}")
        return
    keep = [i for i, name in enumerate(ra[0]) if not timing_column(name)]
    if len(ra) != len(rb):
        problems.append(f"{rel}: {len(ra) - 1} rows before, {len(rb) - 1} after")
    for line, (x, y) in enumerate(zip(ra[1:], rb[1:]), start=2):
        for i in keep:
            xi = x[i] if i < len(x) else None
            yi = y[i] if i < len(y) else None
            if xi != yi:
                problems.append(f"{rel}:{line}: {ra[0][i]}: {xi!r} before, {yi!r} after")
                return  # the first difference of a file is enough to find it


def strip_volatile(value):
    if isinstance(value, dict):
        return {k: strip_volatile(v) for k, v in value.items()
                if k not in MANIFEST_VOLATILE and not timing_column(k)}
    if isinstance(value, list):
        return [strip_volatile(v) for v in value]
    return value


def compare_json(a, b, problems, rel):
    ja, jb = (strip_volatile(json.loads(Path(p).read_text())) for p in (a, b))
    if ja != jb:
        problems.append(f"{rel}: differs outside the volatile fields")


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    before, after = Path(sys.argv[1]), Path(sys.argv[2])
    for root in (before, after):
        if not root.is_dir():
            print(f"compare_runs: {root}: not a folder", file=sys.stderr)
            return 2
    kinds = {".csv": compare_csv, ".tum": None, ".json": compare_json}

    def compared_files(root):  # JSON: run manifests only (benchmark output is all timings)
        return {p.relative_to(root) for p in root.rglob("*")
                if p.suffix in kinds and (p.suffix != ".json" or p.name == "manifest.json")}

    files_a, files_b = compared_files(before), compared_files(after)
    problems = [f"{p}: only before" for p in sorted(files_a - files_b)]
    problems += [f"{p}: only after" for p in sorted(files_b - files_a)]
    compared = 0
    for rel in sorted(files_a & files_b):
        a, b = before / rel, after / rel
        check = kinds[rel.suffix]
        if check is None:
            if a.read_bytes() != b.read_bytes():
                problems.append(f"{rel}: bytes differ")
        else:
            check(a, b, problems, rel)
        compared += 1
    for p in problems:
        print(p)
    print(f"compare_runs: {compared} files compared, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
