#!/usr/bin/python3
"""Thesis charts from the run folders `relslam` writes: Chapter 4's Relative Plane figures (Figs 64-102,
the paper's Figs 1-5, chapter4.py), Chapter 5's (Figs 46, 55-61, 105-108, the paper's Figs 6-8,
chapter5.py) and Chapter 6's Relative Point figures (Figs 110-171, chapter6.py). This file holds the
one registry of figures (each chapter module lists its own; here they are joined and sorted once),
and draws them.

Every figure reads only CSV/JSON files below RUNS (the folder names of scripts/reproduce.sh, listed
in each Figure's runs) and writes one PNG, OUT/fig<N>.png (extras: OUT/<name>.png), of
FIGSIZE x DPI pixels. A figure whose run folder is missing is skipped with a line naming the
folder; a malformed file is reported with its name and column, and the other figures go on.

Usage:
  /usr/bin/python3 scripts/plot/figures.py --runs RUNS --out OUT [--fig 146 147 ...] [--list] [--quick]
Exit codes: 0 every figure rendered or skipped for missing runs, 1 some file was malformed,
2 bad command line.
"""
import argparse
import dataclasses
import os
import sys

import matplotlib.pyplot as plt

import chapter4
import chapter5
import chapter6
import relslam_plot as rp
from draw import DPI, FIGSIZE, Figure, describe_axes
from measures.common import ALG
from load import read_json


def chapter_of(figure):
    """4, 5 or 6: the thesis chapter a registry entry belongs to (the paper's figures go with their chapter)."""
    return 4 if figure in chapter4.FIGURES else 5 if figure in chapter5.FIGURES else 6


def order(figure):
    """Numbered figures by number, then the paper's, then the extras (each group in chapter order)."""
    if isinstance(figure.id, int):
        return (0, figure.id, "")
    return (1 if str(figure.id).startswith("paper") else 2, chapter_of(figure), str(figure.id))


FIGURES = sorted(chapter4.FIGURES + chapter5.FIGURES + chapter6.FIGURES, key=order)
BY_ID = {str(f.id): f for f in FIGURES}


# ---- rendering -------------------------------------------------------------------------------

@dataclasses.dataclass
class Result:
    figure: Figure
    status: str  # "ok", "missing" or "error"
    detail: str  # the PNG path, the missing runs, or the error message
    shows: str = ""  # what our run shows, measured from its files
    title: str = ""  # the title drawn (in quick mode the one that says what was run)


def what_was_run(run):
    """{loops, iterations} of a simulated run folder (a sweep: its first cell), from its manifest and
    iterations.csv, for a quick-mode title; empty where the folder has neither."""
    for folder in [run] + sorted(os.path.join(root, d) for root, dirs, _ in os.walk(run) for d in dirs):
        path = os.path.join(folder, "manifest.json")
        if os.path.isfile(path) and os.path.isfile(os.path.join(folder, "summary.csv")):
            sim = read_json(path).get("scenario", {}).get("sim", {})
            it = os.path.join(folder, ALG, "iterations.csv")
            n = sum(1 for _ in open(it)) - 1 if os.path.isfile(it) else sim.get("iterations")
            return {"loops": sim.get("loops"), "iterations": n}
    return {}


def title(figure, runs, quick):
    """The figure's title; in quick mode the one that says what was run, where the figure has one."""
    if not (quick and figure.quick_title):
        return figure.title
    facts = what_was_run(os.path.join(runs, figure.runs[0]))
    try:
        return figure.quick_title.format(**facts)
    except (KeyError, ValueError):
        return figure.title + " (quick run)"


def render(figure, runs, out, quick=False):
    """Draws one figure into OUT/<name>.png, or says why not. quick: the runs are reproduce.sh's
    shortened ones, so the title says what was run (Figure.quick_title) rather than the thesis's run."""
    missing = [r for r in figure.runs if not os.path.exists(os.path.join(runs, r))]
    if missing:
        return Result(figure, "missing", ", ".join(missing))
    fig = plt.figure(figsize=FIGSIZE, layout="constrained")
    try:
        shows = figure.draw(fig, *[os.path.join(runs, r) for r in figure.runs])
    except rp.DataError as e:
        plt.close(fig)
        return Result(figure, "error", str(e))
    prefix = (f"Fig. {figure.id} — " if isinstance(figure.id, int)
              else f"Paper Fig. {figure.id[5:]} — " if str(figure.id).startswith("paper") else "Extra — ")
    drawn = title(figure, runs, quick)
    fig.suptitle(prefix + drawn)
    # a drawing helper may return its axes instead of its own text: then the drawn series say it
    shows = shows if isinstance(shows, str) and shows else describe_axes(fig)
    return Result(figure, "ok", rp.save_png(fig, os.path.join(out, figure.name + ".png"), DPI), shows, drawn)


def render_all(runs, out, ids=None, log=print, quick=False):
    results = []
    for figure in FIGURES if not ids else [BY_ID[i] for i in ids]:
        r = render(figure, runs, out, quick)
        log({"ok": f"{figure.name}: wrote {r.detail}",
             "missing": f"{figure.name}: skipped, missing {r.detail} in {runs}",
             "error": f"{figure.name}: error: {r.detail}"}[r.status])
        results.append(r)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", help="folder holding the run folders (scripts/reproduce.sh's layout)")
    parser.add_argument("--out", help="folder for the PNGs")
    parser.add_argument("--fig", nargs="+", metavar="ID", help="only these figures (numbers or extra names)")
    parser.add_argument("--list", action="store_true", help="list the figures and the runs each needs")
    parser.add_argument("--quick", action="store_true", help="the runs are reproduce.sh --quick's: titles say so")
    args = parser.parse_args()
    if args.list:
        for f in FIGURES:
            print(f"{f.name}\t{' '.join(f.runs)}\t{f.caption}")
        return 0
    if not args.runs or not args.out:
        parser.error("--runs and --out are required")
    unknown = [i for i in args.fig or [] if i not in BY_ID]
    if unknown:
        parser.error(f"unknown figure(s) {', '.join(unknown)}; --list shows them")
    results = render_all(args.runs, args.out, args.fig, quick=args.quick)
    return 1 if any(r.status == "error" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
