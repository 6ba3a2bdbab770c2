"""Shared helpers for the plot scripts: read run-folder CSVs by column name, save figures.

Plots read only CSV and manifest.json (style.md 2.10); they never rerun C++.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless: CI and servers have no display
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path, names):
    """Returns {name: [float, ...]} for the requested columns; empty fields become NaN.

    A missing file or column stops with a message naming it."""
    if not os.path.exists(path):
        sys.exit(f"plot: {path}: file not found")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        missing = [n for n in names if n not in (reader.fieldnames or [])]
        if missing:
            sys.exit(f"plot: {path}: missing column(s) {', '.join(missing)}")
        columns = {n: [] for n in names}
        for row in reader:
            for n in names:
                columns[n].append(float(row[n]) if row[n] != "" else float("nan"))
    return columns


def read_tum(path):
    """TUM trajectory -> {t, x, y, z} lists."""
    cols = {k: [] for k in ("t", "x", "y", "z")}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = [float(s) for s in line.split()]
            for k, value in zip(("t", "x", "y", "z"), v):
                cols[k].append(value)
    return cols


def read_manifest(run):
    with open(os.path.join(run, "manifest.json")) as f:
        return json.load(f)


def save(fig, out_dir, name):
    """Writes name.png and name.pdf into out_dir; returns the PNG path."""
    os.makedirs(out_dir, exist_ok=True)
    png = os.path.join(out_dir, name + ".png")
    fig.savefig(png, dpi=120, bbox_inches="tight")
    fig.savefig(os.path.join(out_dir, name + ".pdf"), bbox_inches="tight")
    plt.close(fig)
    return png
