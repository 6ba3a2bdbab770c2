"""The pieces every chapter's measures share: columns of a loaded table, means over seeds, fitted curves.

Every measure in this package is a pure function: it takes the data frames load.py reads (or, in tests,
frames built by hand) and returns numbers; nothing here opens a file or draws.
"""
import numpy as np

import relslam_plot as rp


ALG = "relative_point"
PLANE = "relative_plane"
STEADY_FROM = 200  # thesis 6: density means are over iterations 200..end (Fig 136 also starts there)


def source(table):
    """The file a table was read from (load.py records it), for messages."""
    return getattr(table, "attrs", {}).get("path", "table")


def arrays(table, names, strings=()):
    """{name: numpy array} of a table's columns: floats (empty fields NaN), or str for the `strings`
    (empty ones ""). The table is a DataFrame (load.py's) or already such a dict; a missing column or a
    field that is not a number is a DataError naming the file."""
    missing = [n for n in names if n not in table]
    if missing:
        raise rp.DataError(f"{source(table)}: missing column(s) {', '.join(missing)}")
    out = {}
    for n in names:
        if n in strings:
            out[n] = np.array(["" if v is None or (isinstance(v, float) and v != v) else str(v) for v in table[n]],
                              dtype=object)
            continue
        try:
            out[n] = np.asarray(table[n], dtype=float)
        except (TypeError, ValueError):
            raise rp.DataError(f"{source(table)}: {first_non_number(table[n])}column {n}: not a number") from None
    return out


def first_non_number(values):
    """'line L: ' of the first value that is not a number (line 1 is a CSV file's header), else ''."""
    for row, v in enumerate(values):
        try:
            float(v)
        except (TypeError, ValueError):
            return f"line {row + 2}: "
    return ""


def seed_means(runs, columns):
    """{column: per-iteration mean over the runs} of tables of the same columns (one per seed), each cut
    to the shortest."""
    n = min(len(r[columns[0]]) for r in runs)
    return {c: np.mean([np.asarray(r[c], dtype=float)[:n] for r in runs], axis=0) for c in columns}


def steady(values):
    """Iterations from STEADY_FROM on; shortened (quick) runs keep their second half instead."""
    return values[STEADY_FROM:] if len(values) >= 2 * STEADY_FROM else values[len(values) // 2:]


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

