"""Shared helpers for the plot scripts: read run-folder CSVs by column name, save figures.

Plots read only CSV and manifest.json; they never rerun C++.

Usage: import relslam_plot as rp; rp.read_table("runs/f8/relative_point/iterations.csv", ["iteration"])
"""
import csv
import json
import os
import sys

import matplotlib

# The run-folder loader and the name table (python/relslam_data) are shared with plot_run.py.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
matplotlib.use("Agg")  # headless: CI and servers have no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


class DataError(Exception):
    """A run folder's file is missing or malformed; the message names the file (and column)."""


def read_table(path, names, text=()):
    """Returns {name: numpy array} for the requested columns: floats (empty fields are NaN), or
    strings for the names in `text`. Raises DataError naming the file, line and column."""
    if not os.path.exists(path):
        raise DataError(f"{path}: file not found")
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None) or []
        missing = [n for n in names if n not in header]
        if missing:
            raise DataError(f"{path}: missing column(s) {', '.join(missing)}")
        index = {n: header.index(n) for n in names}
        columns = {n: [] for n in names}
        for line, row in enumerate(reader, start=2):
            for n, i in index.items():
                field = row[i] if i < len(row) else None
                if field is None:
                    raise DataError(f"{path}:{line}: column {n}: row too short")
                columns[n].append(field if n in text else _number(field, path, line, n))
    return {n: np.array(v, dtype=object if n in text else float) for n, v in columns.items()}


def _number(field, path, line, name):
    if field == "":
        return float("nan")
    try:
        return float(field)
    except ValueError:
        raise DataError(f"{path}:{line}: column {name}: not a number: {field!r}") from None


def read_columns(path, names):
    """Returns {name: [float, ...]} for the requested columns; empty fields become NaN.

    A missing file or column stops with a message naming it."""
    try:
        return {n: list(v) for n, v in read_table(path, names).items()}
    except DataError as e:
        sys.exit(f"plot: {e}")


def read_tum(path):
    """TUM trajectory -> {t, x, y, z, qx, qy, qz, qw} lists."""
    if not os.path.exists(path):
        raise DataError(f"{path}: file not found")
    names = ("t", "x", "y", "z", "qx", "qy", "qz", "qw")
    cols = {k: [] for k in names}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = [float(s) for s in line.split()]
            for k, value in zip(names, v):
                cols[k].append(value)
    return cols


def moving_average(values, width):
    """Mean of each value and the width - 1 before it (fewer at the start), so the curve keeps its
    length and starts at the first iteration."""
    v = np.asarray(values, dtype=float)
    total = np.cumsum(v)
    total[width:] = total[width:] - total[:-width]
    return total / np.minimum(np.arange(1, len(v) + 1), width)


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


def save_png(fig, path, dpi=100):
    """Writes exactly one PNG of the figure's own size (no tight bounding box, so the pixel size is
    figsize x dpi and tests can check it)."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path
