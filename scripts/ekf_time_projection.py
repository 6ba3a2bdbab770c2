#!/usr/bin/env python3
"""The EKF's time on a scenario it was not run on, from its step times where it was.

    scripts/ekf_time_projection.py MEASURED_SWEEP TARGET_SWEEP [SEED ...]

MEASURED_SWEEP: a sweep folder with ekf6d runs (seed-N/ekf6d/iterations.csv: runtime_ms,
landmarks_in_map, visible_points); SEEDS picks the runs to fit (those of a quiet machine; all
by default). Fits ms per step = a + b n^2 + c v n^2 (n landmarks in the map, v points in view:
the covariance update is quadratic in the state, each observation one update) and applies it
to every seed of TARGET_SWEEP (any run folder of it: observations.csv with true_id), whose map
grows as the truth's landmarks are first seen (docs/algorithms/batch-optimum.md).
"""
import sys
from pathlib import Path

import numpy as np
import pandas as pd


def features(n, v):
    n = np.asarray(n, dtype=float)
    return np.c_[np.ones_like(n), n * n, np.asarray(v, dtype=float) * n * n]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    measured, target = Path(sys.argv[1]), Path(sys.argv[2])
    seeds = [int(s) for s in sys.argv[3:]]
    runs = sorted(measured.glob("seed-*/ekf6d/iterations.csv"))
    if seeds:
        runs = [r for r in runs if int(r.parts[-3].split("-")[1]) in seeds]
    d = pd.concat([pd.read_csv(r) for r in runs])
    coef, *_ = np.linalg.lstsq(features(d.landmarks_in_map, d.visible_points), d.runtime_ms.values, rcond=None)
    print(f"fit over {len(runs)} runs: ms per step = {coef[0]:.3g} + {coef[1]:.3g} n^2 + {coef[2]:.3g} v n^2")
    total = 0.0
    for obs in sorted({p.parent / "observations.csv" for p in target.glob("seed-*/*/observations.csv")} |
                      set(target.glob("seed-*/observations.csv"))):
        if not obs.exists():
            continue
        o = pd.read_csv(obs)
        steps = np.arange(o.iteration.max() + 1)
        first = np.sort(o.groupby("true_id").iteration.min().values)
        n = np.searchsorted(first, steps, side="right")
        v = o.groupby("iteration").size().reindex(steps, fill_value=0).values
        ms = features(n, v) @ coef
        total += ms.sum()
        print(f"{obs.parent.name}: {len(steps)} steps, map {n[-1]}, {ms.mean():.0f} ms per step, {ms.sum() / 3.6e6:.1f} h")
    print(f"all: {total / 3.6e6:.1f} h")


if __name__ == "__main__":
    main()
