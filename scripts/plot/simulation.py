#!/usr/bin/python3
"""Plots a `relslam simulate` run folder: top view, side view and visible points per iteration.

Usage: scripts/plot/simulation.py --run runs/demo [--out runs/demo/plots]

World frame as in the thesis: y is up, so the top view shows x against z.
"""
import argparse
import os
import sys

import matplotlib.pyplot as plt

import relslam_plot as rp

# The files are read by the relslam_data package (python/), which checks every one.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from relslam_data import DataError, read_csv, read_json  # noqa: E402

PATH_COLUMNS = ["iteration", "arc_length", "x", "y", "z", "visible", "visible_dynamic"]


def read(run):
    """The scenario's name, the true landmarks and the per-iteration path of a simulate folder;
    stops with a message naming the file when one is missing or damaged."""
    try:
        name = read_json(os.path.join(run, "manifest.json"))["scenario"]["name"]
        landmarks = read_csv(os.path.join(run, "ground_truth_landmarks.csv"), required=["x", "y", "z", "dynamic"],
                             numeric=["x", "y", "z", "dynamic"])
        path = read_csv(os.path.join(run, "sim_iterations.csv"), required=PATH_COLUMNS, numeric=PATH_COLUMNS)
    except DataError as e:
        sys.exit(f"plot: {e}")
    return name, landmarks, path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="run folder written by relslam simulate")
    parser.add_argument("--out", help="output folder (default: RUN/plots)")
    args = parser.parse_args()
    out = args.out or os.path.join(args.run, "plots")
    name, landmarks, path = read(args.run)
    written = []

    fig, ax = plt.subplots(figsize=(10, 5))
    static = landmarks[landmarks["dynamic"] == 0]
    moving = landmarks[landmarks["dynamic"] == 1]
    # Seen from above as `relslam render` draws it (z right, x up): a rotation of the world, not its
    # mirror image, and the same orientation as the renders next to these plots.
    ax.scatter(static["z"], static["x"], s=2, c="0.6", label="landmarks")
    if len(moving):
        ax.scatter(moving["z"], moving["x"], s=12, c="tab:red", label="dynamic landmarks (at iteration 0)")
    ax.plot(path["z"], path["x"], "b-", lw=1, label="robot path")
    ax.plot([0], [0], "ko", label="start (world origin)")
    ax.set_xlabel("z (units)")
    ax.set_ylabel("x (units)")
    ax.set_aspect("equal")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8)  # beside the map, never over it
    ax.set_title(f"{name}: top view of path and landmarks")
    written.append(rp.save(fig, out, "sim_top_view"))

    fig, ax = plt.subplots(figsize=(10, 3))
    ax.plot(path["iteration"], path["y"], "b-")
    ax.set_xlabel("iteration")
    ax.set_ylabel("height y (units)")
    ax.set_title(f"{name}: robot height (the incline peaks over the start, thesis 6.6.1)")
    written.append(rp.save(fig, out, "sim_height"))

    fig, ax = plt.subplots(figsize=(10, 3))
    ax.plot(path["iteration"], path["visible"], "k-", lw=0.8, label="visible points")
    if path["visible_dynamic"].any():
        ax.plot(path["iteration"], path["visible_dynamic"], "r-", lw=0.8, label="of which dynamic")
    ax.set_xlabel("iteration")
    ax.set_ylabel("points per observation")
    ax.legend(fontsize=8)
    ax.set_title(f"{name}: visible points per iteration")
    written.append(rp.save(fig, out, "sim_visible"))

    for p in written:
        print(f"plot: wrote {p}")


if __name__ == "__main__":
    main()
