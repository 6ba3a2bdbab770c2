#!/usr/bin/python3
"""Plots a relslam run folder: errors, run time and map size over the iterations (every algorithm
of summary.csv in each figure) and a top view of the trajectories over the truth.

Usage: scripts/plot_run.py RUN [--out DIR] [--smooth N]
  RUN    a folder written by `relslam run` (or victoria-park, or one seed-N cell of a sweep)
  --out  where the PNGs go (default RUN/plots): errors.png, runtime.png, map_size.png, top_view.png,
         and for a laser run with ICP-SLAM wall_map.png (the walls over ICP-SLAM's point map)
Exit status 2 with a message naming the file when the folder is damaged (missing or cut file).
"""
import argparse
import sys
from pathlib import Path

# The package next to this script, whether or not it is pip-installed (python/README.md).
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "python"))
sys.path.insert(0, str(Path(__file__).resolve().parent / "plot"))
import matplotlib  # noqa: E402

matplotlib.use("Agg")  # headless: CI and servers have no display
import matplotlib.pyplot as plt  # noqa: E402

from relslam_data import DataError, load_run  # noqa: E402
from relslam_data import frames  # noqa: E402
from relslam_data.names import algorithm_label, metric_label  # noqa: E402
from laser_map import plot_wall_map  # noqa: E402

DPI = 120
TRUTH_COLOUR = "black"


def colours(run):
    """One colour per algorithm, the same in every figure of the set."""
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    return {name: cycle[i % len(cycle)] for i, name in enumerate(run.algorithms)}


def save(fig, out, name):
    """Writes out/name.png and closes the figure; returns the path."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"{name}.png"
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_errors(run, colour):
    """One panel per error column any algorithm reports (landmark or map error, position, heading)."""
    long = frames.iterations_long(run)
    columns = frames.present_columns(long, frames.ERROR_COLUMNS)
    if not columns:
        return None
    fig, axes = plt.subplots(len(columns), 1, figsize=(10, 2.2 * len(columns) + 1), sharex=True, squeeze=False)
    for ax, column in zip(axes[:, 0], columns):
        for name, algorithm in run.algorithms.items():
            if column in algorithm.iterations.columns:
                ax.plot(algorithm.iterations["iteration"], algorithm.iterations[column], lw=1,
                        color=colour[name], label=algorithm_label(name))
        ax.set_ylabel(metric_label(column), fontsize=8)
    axes[-1, 0].set_xlabel("iteration")
    axes[0, 0].legend(fontsize=8)
    axes[0, 0].set_title(f"{run.name}: errors against the truth")
    return fig


def plot_runtime(run, colour, width):
    """Run time per iteration, a moving mean over `width` iterations; log scale when algorithms
    differ by orders of magnitude (the EKF against the Relative algorithms)."""
    fig, ax = plt.subplots(figsize=(10, 3.5))
    means = []
    for name, algorithm in run.algorithms.items():
        if "runtime_ms" not in algorithm.iterations.columns:
            continue
        smooth = frames.moving_average(algorithm.iterations["runtime_ms"], width)
        means.append(algorithm.iterations["runtime_ms"].mean())
        ax.plot(algorithm.iterations["iteration"], smooth, lw=0.8, color=colour[name],
                label=f"{algorithm_label(name)} ({width}-iteration mean)")
    if not means:
        plt.close(fig)
        return None
    if len(means) > 1 and min(means) > 0 and max(means) / min(means) > 20:
        ax.set_yscale("log")
    ax.set_xlabel("iteration")
    ax.set_ylabel(metric_label("runtime_ms"))
    ax.legend(fontsize=8)
    ax.set_title(f"{run.name}: run time (algorithm only)")
    return fig


def plot_map_size(run, colour):
    """Landmarks (or planes) on each algorithm's map per iteration."""
    long = frames.iterations_long(run)
    columns = frames.present_columns(long, frames.MAP_SIZE_COLUMNS)
    if not columns:
        return None
    fig, ax = plt.subplots(figsize=(10, 3.5))
    for name, algorithm in run.algorithms.items():
        column = next((c for c in columns if c in algorithm.iterations.columns), None)
        if column:
            ax.plot(algorithm.iterations["iteration"], algorithm.iterations[column], lw=1, color=colour[name],
                    label=algorithm_label(name))
    ax.set_xlabel("iteration")
    ax.set_ylabel(metric_label(columns[0]).replace("(count)", "").strip())
    ax.legend(fontsize=8)
    ax.set_title(f"{run.name}: map size")
    return fig


def plot_top_view(run, colour):
    """Trajectories seen from above (x against z, y is up) over the true path and landmarks or walls;
    each algorithm's estimated map as small dots of its colour."""
    view = frames.top_view(run)
    if view.empty:
        return None
    fig, ax = plt.subplots(figsize=(9, 7))
    planes = {name: a.planes for name, a in run.algorithms.items()
              if a.planes is not None and {"kp1_x", "kp1_z", "kp2_x", "kp2_z"} <= set(a.planes.columns)}
    # As `relslam render` draws each half from above: point worlds z right, x up; planar worlds (true
    # walls or mapped planes, also a run of your own plane file) x right, z up. Both are rotations of
    # the world, never its mirror image.
    h, v = ("x", "z") if view.walls is not None or planes else ("z", "x")
    if view.truth_points is not None:
        ax.scatter(view.truth_points[h], view.truth_points[v], s=4, c="0.7", label="true landmarks")
    if view.walls is not None:
        for i, wall in enumerate(view.walls.itertuples(index=False)):
            ax.plot([wall.a_x, wall.b_x], [wall.a_z, wall.b_z], color="0.5", lw=3, alpha=0.6,
                    label="true walls" if i == 0 else None)
    for name, points in view.maps.items():
        if name in planes:  # a plane map is drawn as its segments, key point to key point
            ends = planes[name][["kp1_x", "kp1_z", "kp2_x", "kp2_z"]].dropna()
            for i, p in enumerate(ends.itertuples(index=False)):
                ax.plot([p.kp1_x, p.kp2_x], [p.kp1_z, p.kp2_z], color=colour[name], lw=1.5,
                        label=f"{algorithm_label(name)} map ({len(ends)} planes)" if i == 0 else None)
            continue
        ax.scatter(points[h], points[v], s=6, color=colour[name], alpha=0.7, marker="x",
                   label=f"{algorithm_label(name)} map")
    for name, path in view.paths:
        truth = name == "truth"
        ax.plot(path[h], path[v], lw=1.6 if truth else 1, ls="--" if truth else "-",
                color=TRUTH_COLOUR if truth else colour[name],
                label="true path" if truth else f"{algorithm_label(name)} path")
    ax.set_xlabel(f"{h} (units)")
    ax.set_ylabel(f"{v} (units)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))  # beside the map, never over it
    ax.set_title(f"{run.name}: top view")
    return fig


def plot_run(folder, out, width=12):
    """Loads the run and writes its figure set; returns the PNG paths (DataError if damaged)."""
    run = load_run(folder)
    colour = colours(run)
    figures = {"errors": plot_errors(run, colour), "runtime": plot_runtime(run, colour, width),
               "map_size": plot_map_size(run, colour), "top_view": plot_top_view(run, colour),
               "wall_map": plot_wall_map(run, colour, algorithm_label)}
    return [save(fig, Path(out), name) for name, fig in figures.items() if fig is not None]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="run folder written by relslam run")
    parser.add_argument("--out", help="output folder (default: RUN/plots)")
    parser.add_argument("--smooth", type=int, default=12, help="iterations in the run-time moving mean")
    args = parser.parse_args(argv)
    if args.smooth < 1:
        parser.error("--smooth must be at least 1")
    try:
        written = plot_run(args.run, args.out or Path(args.run) / "plots", args.smooth)
    except DataError as e:
        print(f"plot_run: {e}", file=sys.stderr)
        return 2
    for path in written:
        print(f"plot_run: wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
