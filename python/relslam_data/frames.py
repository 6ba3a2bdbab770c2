"""Pure computations on loaded runs and sweeps: the tables the figures draw, nothing drawn here.

Kept apart from matplotlib so they can be tested on tiny data frames and reused in a notebook
(e.g. `iterations_long(run)` is the tidy table for seaborn or groupby).
"""
from dataclasses import dataclass, field

import pandas as pd

# Per-iteration error columns, in the order the figure stacks them; point runs have the landmark
# errors, planar runs the map errors and heading.
ERROR_COLUMNS = ("mean_landmark_error", "landmark_error", "mean_map_error", "map_error", "position_error",
                 "heading_error_deg")
MAP_SIZE_COLUMNS = ("landmarks_in_map", "planes_in_map")


def iterations_long(run):
    """All algorithms' iterations.csv in one table with an `algorithm` column, summary.csv order."""
    frames = [a.iterations.assign(algorithm=name) for name, a in run.algorithms.items()]
    if not frames:
        return pd.DataFrame(columns=["algorithm", "iteration"])
    return pd.concat(frames, ignore_index=True)


def present_columns(frame, candidates):
    """The candidates the frame has with at least one value (an all-empty column has nothing to draw)."""
    return [c for c in candidates if c in frame.columns and frame[c].notna().any()]


def moving_average(values, width):
    """Mean of each value and the width - 1 before it (fewer at the start): the curve keeps its
    length and starts at the first iteration, and one slow iteration does not hide the trend."""
    return pd.Series(values, dtype=float).rolling(width, min_periods=1).mean().to_numpy()


@dataclass
class TopView:
    """What a top view draws, in the world's x-z plane (y is up): paths as (label, x, z) frames,
    truth landmarks and walls, each algorithm's estimated map points."""

    paths: list = field(default_factory=list)
    truth_points: object = None  # DataFrame x, z
    walls: object = None  # DataFrame a_x, a_z, b_x, b_z
    maps: dict = field(default_factory=dict)  # algorithm -> DataFrame x, z

    @property
    def empty(self):
        """Nothing to draw: no path and no truth (a run of a data set without ground truth)."""
        return not self.paths and self.truth_points is None and self.walls is None


def top_view(run):
    """The top view of a run: the true path first (where the run has one), then each algorithm's
    trajectory, the true landmarks or walls and the estimated landmarks or plane segments."""
    view = TopView()
    if run.truth_path is not None:
        view.paths.append(("truth", run.truth_path[["x", "z"]]))
    for name, algorithm in run.algorithms.items():
        if algorithm.trajectory is not None and len(algorithm.trajectory):
            view.paths.append((name, algorithm.trajectory[["x", "z"]]))
        if algorithm.landmarks is not None:
            view.maps[name] = algorithm.landmarks[["x", "z"]].dropna()
        elif algorithm.planes is not None and {"kp1_x", "kp2_x"} <= set(algorithm.planes.columns):
            view.maps[name] = _plane_ends(algorithm.planes)
    if run.truth_landmarks is not None:
        view.truth_points = run.truth_landmarks[["x", "z"]]
    if run.truth_walls is not None:
        view.walls = run.truth_walls[["a_x", "a_z", "b_x", "b_z"]]
    return view


def _plane_ends(planes):
    """A plane's two key points, one row each, so estimated planes show as their end points."""
    ends = [planes[[f"kp{k}_x", f"kp{k}_z"]].set_axis(["x", "z"], axis=1) for k in (1, 2)]
    return pd.concat(ends, ignore_index=True).dropna()


def is_ratio(algorithm):
    """summary.csv's and aggregate.csv's quotient rows are named 'a/b' (relative_point/ekf6d)."""
    return "/" in str(algorithm)


def is_numeric_axis(values):
    """True when every value of the axis reads as a number: drawn on a number line, else as
    categories in plan order."""
    return bool(len(values)) and pd.to_numeric(pd.Series(values).astype(str), errors="coerce").notna().all()


def axis_order(sweep, axis):
    """The axis's values as strings: by value for a numeric axis; else in plan.json's order
    (the order of --param or of the scenario's variants), else in order of appearance."""
    labels = list(dict.fromkeys(sweep.aggregate[axis].astype(str)))
    if is_numeric_axis(labels):
        return sorted(labels, key=float)
    planned = [v["label"] for a in (sweep.plan or {}).get("axes", []) if a.get("name") == axis
               for v in a.get("values", [])]
    return [v for v in planned if v in labels] + [v for v in labels if v not in planned]


def metric_vs_axis(sweep, metric, axis, ratios=False):
    """One metric against one swept axis: rows algorithm, series (the other axes' values, '' when
    only one axis is swept), label (the axis value as written), x (its position: the value, or
    its index for a category), mean and ci95 (half-width of the 95 % interval; NaN when only one
    seed finished). Sorted so each (algorithm, series) is one line from left to right.
    The quotient rows (relative_point/ekf6d) are left out, or with ratios=True are the only rows:
    a ratio and a score share no scale."""
    agg = sweep.aggregate
    agg = agg[agg["algorithm"].map(is_ratio) == ratios]
    order = axis_order(sweep, axis)
    labels = agg[axis].astype(str)
    numeric = is_numeric_axis(order)
    others = [a for a in sweep.axes if a != axis]
    table = pd.DataFrame({
        "algorithm": agg["algorithm"].astype(str),
        "series": agg[others].astype(str).apply(lambda r: ", ".join(f"{a}={v}" for a, v in r.items()), axis=1)
        if others else "",
        "label": labels,
        "x": labels.astype(float) if numeric else labels.map({v: i for i, v in enumerate(order)}).astype(float),
        "mean": agg[f"{metric}_mean"].astype(float),
        "ci95": agg[f"{metric}_ci95"].astype(float),
    })
    # Algorithms and the other axes' values keep aggregate.csv's order (the sweep's plan order).
    ranks = {f"_{c}": table[c].map({v: i for i, v in enumerate(dict.fromkeys(table[c]))}) for c in ("algorithm", "series")}
    return table.assign(**ranks).sort_values([*ranks, "x"]).drop(columns=list(ranks)).reset_index(drop=True)


def dodge(table, width=0.08):
    """x shifted a little per line on a categorical axis, so the intervals of lines sharing a
    category do not hide each other; a numeric axis keeps its true values."""
    lines = list(dict.fromkeys(zip(table["algorithm"], table["series"])))
    offset = {line: (i - (len(lines) - 1) / 2) * width for i, line in enumerate(lines)}
    return table["x"] + [offset[line] for line in zip(table["algorithm"], table["series"])]
