"""Reading run folders and fitting curves: the pieces every chapter's measures share."""
import json
import os

import numpy as np

import relslam_plot as rp


ALG = "relative_point"


STEADY_FROM = 200  # thesis 6: density means are over iterations 200..end (Fig 136 also starts there)


def iterations(run, columns, algorithm=ALG):
    """One algorithm's iterations.csv columns (plus `iteration`); an empty file is an error."""
    path = os.path.join(run, algorithm, "iterations.csv")
    table = rp.read_table(path, ["iteration", *columns])
    if len(table["iteration"]) == 0:
        raise rp.DataError(f"{path}: no rows")
    return table


def algorithms(run):
    """Algorithms of a run, in summary.csv order (the relative_point/ekf6d row holds ratios)."""
    t = rp.read_table(os.path.join(run, "summary.csv"), ["algorithm", "status"], text=("algorithm", "status"))
    return [a for a, s in zip(t["algorithm"], t["status"]) if s != "ratio"]


def sweep_runs(sweep, axis, algorithm=ALG):
    """[(axis value, run folder)] of a `relslam sweep` folder, one algorithm's rows, sweep order."""
    path = os.path.join(sweep, "sweep.csv")
    t = rp.read_table(path, [axis, "folder", "algorithm"], text=(axis, "folder", "algorithm"))
    runs = [(v, os.path.join(sweep, f)) for v, f, a in zip(t[axis], t["folder"], t["algorithm"]) if a == algorithm]
    if not runs:
        raise rp.DataError(f"{path}: column algorithm: no {algorithm} rows")
    return runs


def sweep_series(sweep, columns, axis="variant", algorithm=ALG):
    """{axis value: {column: per-iteration mean over the seeds}} (seeds cut to the shortest run)."""
    grouped = {}
    for value, folder in sweep_runs(sweep, axis, algorithm):
        grouped.setdefault(value, []).append(iterations(folder, columns, algorithm))
    out = {}
    for value, runs in grouped.items():
        n = min(len(r["iteration"]) for r in runs)
        out[value] = {c: np.mean([r[c][:n] for r in runs], axis=0) for c in ["iteration", *columns]}
    return out


def steady(values):
    """Iterations from STEADY_FROM on; shortened (quick) runs keep their second half instead."""
    return values[STEADY_FROM:] if len(values) >= 2 * STEADY_FROM else values[len(values) // 2:]


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise rp.DataError(f"{path}: {e}") from None


def n_log_n(n):
    return n * np.log(n)


SHAPES = {"n": (lambda n: n, "c·n"), "nlogn": (n_log_n, "c·n·ln n")}


def fit_scale(x, y, shape):
    """Least-squares c of y ≈ c·shape(x): the thesis's reference curves pass through the origin."""
    b = shape(np.asarray(x, float))
    return float(b @ np.asarray(y, float) / (b @ b))


def line_fit(x, y):
    """(slope, intercept) of the least-squares line."""
    slope, intercept = np.polyfit(np.asarray(x, float), np.asarray(y, float), 1)
    return float(slope), float(intercept)


PLANE = "relative_plane"
