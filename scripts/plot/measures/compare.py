"""Relative Point against its baselines (thesis 6.7, 6.8): the numbers the report's summary page
and claims.md set side by side. Pure functions on the data frames relslam_data loads (summary.csv,
iterations.csv), so the unit tests (tests/plot/measures_test.py) feed them hand-made frames."""
import math

import numpy as np

# A claim such as Fig 147's "comparable" is a statement about a ratio; the bands are our reading [C]:
# within a factor of COMPARABLE either way it holds, within PARTLY it partly holds, beyond it does not.
COMPARABLE = 2.0
PARTLY = 4.0

# The columns of summary.csv the summary page shows, in its order, with their headings.
SUMMARY_COLUMNS = {
    "final_mean_landmark_error": "final landmark error per landmark (units)",
    "final_position_error": "final position error (units)",
    "ate_rmse": "ATE RMSE (units)",
    "runtime_median_ms": "median ms per iteration",
    "runtime_max_ms": "longest iteration (ms)",
}


def algorithm_rows(summary):
    """summary.csv without its ratio rows (relative_point/ekf6d), indexed by algorithm."""
    rows = summary[summary["status"] != "ratio"]
    return rows.set_index("algorithm", drop=False)


def ratio(a, b):
    """a ÷ b, NaN where either is missing or b is 0."""
    if a is None or b is None or not (math.isfinite(a) and math.isfinite(b)) or b == 0:
        return float("nan")
    return a / b


def band(r, comparable=COMPARABLE, partly=PARTLY):
    """'holds', 'partly' or 'does not hold' for a claim that two numbers are comparable, from their ratio."""
    if not math.isfinite(r) or r <= 0:
        return "does not hold"
    spread = max(r, 1 / r)
    return "holds" if spread <= comparable else "partly" if spread <= partly else "does not hold"


def common_iterations(a, b, column):
    """The column of two iterations tables over the iterations both processed (the EKF may stop
    early on its time budget): (a's values, b's values), NaNs of either dropped."""
    both = a[["iteration", column]].merge(b[["iteration", column]], on="iteration", suffixes=("_a", "_b"))
    both = both.dropna()
    return both[column + "_a"].to_numpy(dtype=float), both[column + "_b"].to_numpy(dtype=float)


def mean_ratio(a, b, column):
    """Mean of a's column ÷ mean of b's over the iterations both processed, and how many they are."""
    x, y = common_iterations(a, b, column)
    if len(x) == 0:
        return float("nan"), 0
    return ratio(float(np.mean(x)), float(np.mean(y))), len(x)


def comparable(a, b, column):
    """Is a's column comparable to b's over their common iterations? (verdict, ratio, iterations)."""
    r, n = mean_ratio(a, b, column)
    return band(r), r, n


def times_faster(rows, fast, slow, column="runtime_median_ms"):
    """How many times `fast` is quicker than `slow` by a summary column (NaN when either is absent)."""
    if fast not in rows.index or slow not in rows.index:
        return float("nan")
    return ratio(float(rows.loc[slow, column]), float(rows.loc[fast, column]))


def faster_verdict(speedup, at_least):
    """A claim 'A is at least N times faster than B': holds at N or more, partly above 1, else not."""
    if not math.isfinite(speedup):
        return "does not hold"
    return "holds" if speedup >= at_least else "partly" if speedup > 1 else "does not hold"


def side_by_side(frames, column, statistic="mean"):
    """What a figure of several algorithms' `column` shows: [(algorithm, iterations it ran, statistic
    over the iterations all of them ran, its last value)], in the frames' order. frames: {algorithm:
    DataFrame with iteration and column}."""
    shared = None
    for d in frames.values():
        its = set(d["iteration"][d[column].notna()])
        shared = its if shared is None else shared & its
    out = []
    for name, d in frames.items():
        both = d[d["iteration"].isin(shared or set())][column].to_numpy(dtype=float)
        value = float(np.median(both) if statistic == "median" else np.mean(both)) if len(both) else float("nan")
        last = d[column].dropna()
        out.append((name, len(d), value, float(last.iloc[-1]) if len(last) else float("nan")))
    return out, len(shared or ())
