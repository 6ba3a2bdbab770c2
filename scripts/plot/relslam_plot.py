"""Shared helpers for the plot scripts: read run-folder CSVs by column name, save figures.

Plots read only CSV and manifest.json; they never rerun C++.

Usage: import relslam_plot as rp; rp.read_table("runs/f8/relative_point/iterations.csv", ["iteration"])
"""
import json
import os
import sys

import matplotlib

# The run-folder loader and the name table (python/relslam_data) are shared with plot_run.py.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
matplotlib.use("Agg")  # headless: CI and servers have no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import relslam_data  # noqa: E402


class DataError(Exception):
    """A run folder's file is missing or malformed; the message names the file (and column)."""


def read_table(path, names, text=()):
    """Returns {name: numpy array} for the requested columns: floats (empty fields are NaN), or
    strings for the names in `text`. Read by relslam_data's checked reader (python/relslam_data, the
    loader plot_run.py and load.py use); raises DataError naming the file, line and column."""
    try:
        frame = relslam_data.read_csv(path, required=names, numeric=[n for n in names if n not in text],
                                      strings=text)
    except relslam_data.DataError as e:
        raise DataError(str(e)) from None
    return {n: np.array(["" if v != v else str(v) for v in frame[n]], dtype=object) if n in text
            else frame[n].to_numpy(dtype=float) for n in names}


def read_columns(path, names):
    """Returns {name: [float, ...]} for the requested columns; empty fields become NaN.

    A missing file or column stops with a message naming it."""
    try:
        return {n: list(v) for n, v in read_table(path, names).items()}
    except DataError as e:
        sys.exit(f"plot: {e}")


def read_tum(path):
    """TUM trajectory -> {t, x, y, z, qx, qy, qz, qw} lists (relslam_data's checked reader)."""
    try:
        return {k: list(v) for k, v in relslam_data.read_tum(path).items()}
    except relslam_data.DataError as e:
        raise DataError(str(e)) from None


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
