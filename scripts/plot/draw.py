"""Shared drawing: the Figure record every chapter's registry entries use, the figure size, axis labels,
axes finishing and fitted curves."""
import dataclasses
import functools

import numpy as np
from matplotlib.collections import PathCollection

import catalogue
from measures.common import SHAPES, fit_scale
# The one table of readable names (ekf6d -> "EKF (MRPT, 6D)"), for every chapter's legends.
from relslam_data.names import algorithm_label as readable  # noqa: F401


FIGSIZE, DPI = (10, 6), 100  # 1000 x 600 pixels; plot_test.sh checks it
SMOOTH = 12  # Fig 136's moving average, iterations
MS = "ms per iteration"
LE = "landmark error (units)"


def draw_fits(ax, x, y, kinds, color=None):
    """Reference curves fitted to (x, y): SHAPES names through the origin, "poly" a quadratic
    (drawn only with 3 or more points: fewer determine no curvature)."""
    xs = np.linspace(min(x), max(x), 100)
    for kind in kinds:
        if kind == "poly":
            if len(x) >= 3:
                ax.plot(xs, np.polyval(np.polyfit(x, y, 2), xs), ":", color=color, label="quadratic fit")
            continue
        shape, name = SHAPES[kind]
        c = fit_scale(x, y, shape)
        ax.plot(xs, c * shape(xs), "--", color=color, lw=1, label=f"{name} fit, c = {c:.3g}")


def finish(ax, xlabel, ylabel, legend=True):
    """Axis labels, a light grid and the legend: legend="beside" puts it right of the axes, for maps
    and top views, whose every corner may hold data."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    if legend and ax.get_legend_handles_labels()[0]:
        if legend == "beside":
            ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1), borderaxespad=0)
        else:
            ax.legend(fontsize=8)


def label_densities(ax, x, y, densities):
    for xi, yi, d in zip(x, y, densities):
        ax.annotate(f"{d:g}", (xi, yi), textcoords="offset points", xytext=(3, 4), fontsize=7)


@dataclasses.dataclass
class Figure:
    id: object  # thesis figure number, or a name for an extra
    title: str
    runs: tuple  # files or folders below RUNS, passed to draw in this order
    draw: object  # draw(matplotlib figure, *run paths) -> None, or one line on what our run shows
    quick_title: str = ""  # for reproduce.sh --quick's shortened runs: "{loops}", "{iterations}" from the run

    @property
    def name(self):
        return f"fig{self.id}" if isinstance(self.id, int) else str(self.id)

    @property
    def caption(self):
        return catalogue.CATALOGUE[self.id][0]

    @property
    def statement(self):
        return catalogue.CATALOGUE[self.id][1]
P = functools.partial
POS = "position error (units)"


DESCRIBED = 6  # at most this many drawn series named in a figure's "what our run shows"


def describe_axes(fig):
    """What a figure shows, read back from what it drew: per labelled line its mean, range and last
    value over the points drawn, per labelled point set or bar set its size; for the figures whose
    drawing gives no text of its own (their data came from the run's files, so the numbers are the
    run's). Unlabelled lines of two points or fewer (reference lines) are left out."""
    parts = []
    for ax in fig.axes:
        ylabel = ax.get_ylabel()
        for line in ax.get_lines():
            label = line.get_label()
            x, y = np.asarray(line.get_xdata(), dtype=float), np.asarray(line.get_ydata(), dtype=float)
            keep = np.isfinite(x) & np.isfinite(y)
            x, y = x[keep], y[keep]
            if len(y) == 0 or (label.startswith("_") and len(y) <= 2):
                continue
            name = ylabel if label.startswith("_") else label
            if " fit" in name:
                parts.append(name)  # a fitted curve: its constant is in its name
            elif np.all(np.diff(x) >= 0):  # a series over the x axis (iterations, densities)
                parts.append(f"{name}: mean {np.mean(y):.3g}, from {np.min(y):.3g} to {np.max(y):.3g}, last "
                             f"{y[-1]:.3g} ({len(y)} points)")
            else:  # a path or a map
                parts.append(f"{name}: {len(y)} points over {np.ptp(x):.3g} × {np.ptp(y):.3g}")
        for points in ax.collections:
            label = points.get_label()
            if not label.startswith("_") and isinstance(points, PathCollection):  # a scatter, not a filled area
                parts.append(f"{label}: {len(points.get_offsets())} points")
        for bars in ax.containers:
            heights = [b.get_height() for b in bars]
            if heights:
                parts.append(f"{bars.get_label() if not bars.get_label().startswith('_') else ylabel}: "
                             + ", ".join(f"{h:.3g}" for h in heights[:8]) + (" …" if len(heights) > 8 else ""))
    more = f"; and {len(parts) - DESCRIBED} more series" if len(parts) > DESCRIBED else ""
    return "; ".join(parts[:DESCRIBED]) + more
