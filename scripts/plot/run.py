#!/usr/bin/python3
"""Plots a `relslam run` folder: landmark error, position error and run time per iteration,
one line per algorithm (every algorithm listed in summary.csv).

Usage: scripts/plot/run.py --run runs/demo [--out runs/demo/plots]
"""
import argparse
import os
import sys

import matplotlib.pyplot as plt

import relslam_plot as rp

# The run folder is read by the relslam_data package (python/), which checks every file.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from relslam_data import DataError, load_run  # noqa: E402
from relslam_data.names import algorithm_label  # noqa: E402

COLUMNS = ["iteration", "landmark_error", "mean_landmark_error", "position_error", "ex", "ey", "ez", "runtime_ms",
           "landmarks_in_map"]


def iterations(run):
    """{legend name: iterations.csv} of every algorithm (not summary.csv's ratio row); stops with a
    message naming the file when one is missing, damaged or lacks a column these figures draw."""
    try:
        loaded = load_run(run)
    except DataError as e:
        sys.exit(f"plot: {e}")
    for algorithm in loaded.algorithms.values():
        missing = [c for c in COLUMNS if c not in algorithm.iterations.columns]
        if missing:
            sys.exit(f"plot: {algorithm.folder / 'iterations.csv'}: missing column(s) {', '.join(missing)}")
    return loaded.name, {algorithm_label(a): alg.iterations for a, alg in loaded.algorithms.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="run folder written by relslam run")
    parser.add_argument("--out", help="output folder (default: RUN/plots)")
    args = parser.parse_args()
    out = args.out or os.path.join(args.run, "plots")
    name, data = iterations(args.run)
    written = []

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    for a, d in data.items():
        top.plot(d["iteration"], d["landmark_error"], lw=1, label=a)
        bottom.plot(d["iteration"], d["mean_landmark_error"], lw=1, label=a)
    top.set_ylabel("landmark error (units, sum)")
    bottom.set_ylabel("per landmark (units)")
    bottom.set_xlabel("iteration")
    top.legend(fontsize=8)
    top.set_title(f"{name}: landmark error (sum of distances to the nearest true landmark)")
    written.append(rp.save(fig, out, "landmark_error"))

    fig, axes = plt.subplots(4, 1, figsize=(10, 8), sharex=True)
    for a, d in data.items():
        for ax, column in zip(axes, ["position_error", "ex", "ey", "ez"]):
            ax.plot(d["iteration"], d[column], lw=0.8, label=a)
    for ax, label in zip(axes, ["position error", "x error", "y error (up)", "z error"]):
        ax.set_ylabel(f"{label} (units)", fontsize=8)
    axes[-1].set_xlabel("iteration")
    axes[0].legend(fontsize=8)
    axes[0].set_title(f"{name}: position error, estimate minus truth (thesis Figs 130-135)")
    written.append(rp.save(fig, out, "position_error"))

    fig, ax = plt.subplots(figsize=(10, 3.5))
    for a, d in data.items():
        ax.plot(d["iteration"], rp.moving_average(d["runtime_ms"], 12), lw=0.8, label=f"{a} (12-iteration mean)")
    ax.set_xlabel("iteration")
    ax.set_ylabel("run time per iteration (ms)")
    if len(data) > 1:
        ax.set_yscale("log")  # the EKF is orders of magnitude slower (thesis Fig 148)
    ax.legend(fontsize=8)
    ax.set_title(f"{name}: run time (algorithm only; thesis Figs 136, 148)")
    written.append(rp.save(fig, out, "runtime"))

    fig, ax = plt.subplots(figsize=(10, 3.5))
    for a, d in data.items():
        ax.plot(d["iteration"], d["landmarks_in_map"], lw=1, label=a)
    ax.set_xlabel("iteration")
    ax.set_ylabel("landmarks on the map")
    ax.legend(fontsize=8)
    ax.set_title(f"{name}: map size (thesis Fig 149)")
    written.append(rp.save(fig, out, "map_size"))

    for p in written:
        print(f"plot: wrote {p}")


if __name__ == "__main__":
    main()
