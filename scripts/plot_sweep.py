#!/usr/bin/python3
"""Plots a relslam sweep folder: each metric of aggregate.csv against each swept axis, one line per
algorithm (and per value of the other axes), the mean over the seeds with its 95 % interval.

Usage: scripts/plot_sweep.py SWEEP [--out DIR] [--metric NAME ...] [--ratios]
  SWEEP     a folder written by `relslam sweep` (sweep.csv, aggregate.csv, plan.json, manifest.json)
  --out     where the PNGs go (default SWEEP/plots): one METRIC.png per metric, a panel per axis
  --metric  only these metrics (aggregate.csv's column names without _mean), e.g. ate_rmse
  --ratios  also METRIC_ratio.png of the relative_point/ekf6d quotient rows, where the sweep has them
An axis whose values are not all numbers is drawn as categories in the order of the sweep's plan.
Exit status 2 with a message naming the file when the folder is damaged (missing or cut file).
"""
import argparse
import sys
from pathlib import Path

# The package next to this script, whether or not it is pip-installed (python/README.md).
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "python"))
import matplotlib  # noqa: E402

matplotlib.use("Agg")  # headless: CI and servers have no display
import matplotlib.pyplot as plt  # noqa: E402

from relslam_data import DataError, load_sweep  # noqa: E402
from relslam_data import frames  # noqa: E402
from relslam_data.names import algorithm_label, axis_label, metric_label  # noqa: E402

DPI = 120
MARKERS = "osD^vP*X"
DASHES = ["-", "--", ":", "-."]


class UnknownMetric(Exception):
    """--metric names a column aggregate.csv does not have: a usage error (exit 2), not a damaged folder."""


def line_label(algorithm, series):
    """Legend entry: the algorithm's readable name, then the other axes' values if any."""
    return f"{algorithm_label(algorithm)}, {series}" if series else algorithm_label(algorithm)


def styles(table):
    """(algorithm, series) -> matplotlib style: the colour tells the algorithm (the same in every
    panel), the marker and dash the values of the other axes."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    algorithms = list(dict.fromkeys(table["algorithm"]))
    series = list(dict.fromkeys(table["series"]))
    return {(a, s): {"color": colours[algorithms.index(a) % len(colours)],
                     "marker": MARKERS[series.index(s) % len(MARKERS)], "ls": DASHES[series.index(s) % len(DASHES)]}
            for a, s in zip(table["algorithm"], table["series"])}


def draw_panel(ax, sweep, metric, axis, ratios):
    """One metric against one axis, its own legend below; returns False when nothing is drawn."""
    table = frames.metric_vs_axis(sweep, metric, axis, ratios=ratios)
    table = table[table["mean"].notna()]
    if table.empty:
        ax.set_axis_off()
        return False
    order = frames.axis_order(sweep, axis)
    numeric = frames.is_numeric_axis(order)
    x = table["x"] if numeric else frames.dodge(table)
    style = styles(table)
    for (algorithm, series), rows in table.groupby(["algorithm", "series"], sort=False):
        line = dict(style[(algorithm, series)], lw=1) if numeric else dict(style[(algorithm, series)], ls="none")
        # A missing interval (one finished seed) is drawn as none rather than as zero width.
        ax.errorbar(x[rows.index], rows["mean"], yerr=rows["ci95"].fillna(0), ms=4, capsize=3, elinewidth=1,
                    label=line_label(algorithm, series), **line)
    rotate = long_ticks(order, numeric)
    if not numeric:
        ax.set_xticks(range(len(order)), order, rotation=30 if rotate else 0, ha="right" if rotate else "center")
        ax.set_xlim(-0.5, len(order) - 0.5)
    ax.set_xlabel(axis_label(axis))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.3 if rotate else -0.15))
    return True


def long_ticks(order, numeric):
    """Rotated category names need more room between the axis and the legend below it."""
    return not numeric and max(map(len, order)) > 8


def plot_metric(sweep, metric, ratios=False):
    """A figure with one panel per swept axis for the metric, or None when no row has a value."""
    fig, axes = plt.subplots(1, len(sweep.axes), figsize=(6.5 * len(sweep.axes), 4.5), squeeze=False)
    drawn = [draw_panel(ax, sweep, metric, axis, ratios) for ax, axis in zip(axes[0], sweep.axes)]
    if not any(drawn):
        plt.close(fig)
        return None
    label = metric_label(metric)
    axes[0, 0].set_ylabel(f"{label.split(' (')[0]} (ratio)" if ratios else label)
    seeds = sweep.runs["seed"].nunique()
    what = "ratio relative_point/ekf6d, mean" if ratios else "mean"
    fig.suptitle(f"{sweep.name}: {label.split(' (')[0]}\n{what} over {seeds} seed(s), bars: 95 % interval", fontsize=11)
    return fig


def plot_sweep(folder, out, metrics=None, ratios=False):
    """Loads the sweep and writes one PNG per metric (and per ratio metric with `ratios`);
    returns the paths. DataError when the folder is damaged, UnknownMetric for a --metric it lacks."""
    sweep = load_sweep(folder)
    if not sweep.axes:
        raise DataError(Path(folder) / "aggregate.csv", "no swept axis (no column before algorithm)")
    unknown = [m for m in metrics or [] if m not in sweep.metrics]
    if unknown:
        raise UnknownMetric(f"unknown metric(s) {', '.join(unknown)}; aggregate.csv has {', '.join(sweep.metrics)}")
    has_ratios = sweep.aggregate["algorithm"].map(frames.is_ratio).any()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for metric in metrics or sweep.metrics:
        for ratio in [False, True] if ratios and has_ratios else [False]:
            fig = plot_metric(sweep, metric, ratio)
            if fig is None:
                continue
            path = out / f"{metric}{'_ratio' if ratio else ''}.png"
            fig.savefig(path, dpi=DPI, bbox_inches="tight")
            plt.close(fig)
            written.append(path)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep", help="sweep folder written by relslam sweep")
    parser.add_argument("--out", help="output folder (default: SWEEP/plots)")
    parser.add_argument("--metric", nargs="+", help="only these metrics (default: every one with a 95 %% interval)")
    parser.add_argument("--ratios", action="store_true", help="also plot the relative_point/ekf6d ratio rows")
    args = parser.parse_args(argv)
    try:
        written = plot_sweep(args.sweep, args.out or Path(args.sweep) / "plots", args.metric, args.ratios)
    except DataError as e:
        print(f"plot_sweep: {e}", file=sys.stderr)
        return 2
    except UnknownMetric as e:
        parser.error(str(e))
    for path in written:
        print(f"plot_sweep: wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
