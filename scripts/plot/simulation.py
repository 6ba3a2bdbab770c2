#!/usr/bin/python3
"""Plots a `relslam simulate` run folder: top view, side view and visible points per iteration.

Usage: scripts/plot/simulation.py --run runs/demo [--out runs/demo/plots]

World frame as in the thesis: y is up, so the top view shows x against z.
"""
import argparse
import os

import matplotlib.pyplot as plt

import relslam_plot as rp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="run folder written by relslam simulate")
    parser.add_argument("--out", help="output folder (default: RUN/plots)")
    args = parser.parse_args()
    out = args.out or os.path.join(args.run, "plots")
    name = rp.read_manifest(args.run)["scenario"]["name"]

    landmarks = rp.read_columns(os.path.join(args.run, "ground_truth_landmarks.csv"), ["x", "y", "z", "dynamic"])
    path = rp.read_columns(os.path.join(args.run, "sim_iterations.csv"),
                           ["iteration", "arc_length", "x", "y", "z", "visible", "visible_dynamic"])
    written = []

    fig, ax = plt.subplots(figsize=(10, 5))
    static = [i for i, d in enumerate(landmarks["dynamic"]) if d == 0]
    moving = [i for i, d in enumerate(landmarks["dynamic"]) if d == 1]
    ax.scatter([landmarks["x"][i] for i in static], [landmarks["z"][i] for i in static], s=2, c="0.6", label="landmarks")
    if moving:
        ax.scatter([landmarks["x"][i] for i in moving], [landmarks["z"][i] for i in moving], s=12, c="tab:red",
                   label="dynamic landmarks (at iteration 0)")
    ax.plot(path["x"], path["z"], "b-", lw=1, label="robot path")
    ax.plot([0], [0], "ko", label="start (world origin)")
    ax.set_xlabel("x (units)")
    ax.set_ylabel("z (units)")
    # Seen from above with y up, z points down the page; inverting the axis keeps the view a
    # rotation of the world rather than its mirror image (the robot's left is +x).
    ax.invert_yaxis()
    ax.set_aspect("equal")
    ax.legend(loc="upper right", fontsize=8)
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
    if any(path["visible_dynamic"]):
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
