#!/usr/bin/env python3
"""Tables of every estimator against the batch optimum from scripts/optimum_sweep.sh's folders.

For each scenario folder OUT/<scenario>/ the sweep left six relslam sweeps over the same seeds
(the same frames: their input digests are checked): base/ (Relative Point with the scenario's
preset, the batch optimum), adaptive/ and relaxed/ (Relative Point alone), motion/ (the optimum
with the EKF's motion model), ekfmodel/ (the optimum with the EKF's motion and sensor model: the
least-squares solution of exactly the EKF's model), ekf/ (MRPT's 6D EKF). Only finished runs enter the statistics: an
interrupted, stopped, failed or missing run is named in "not ok (left out)", never averaged. This
prints per estimator the final mean landmark error and the ATE with their ratios to the optimum
(mean and 95 % Student-t interval over the seeds), the mean time per iteration, the optimum's
solve time, and per seed relaxed Relative Point over the EKF and over the optimum. "aligned" is
the mean landmark error after the best rigid fit of the map to the truth (rotation and
translation, Kabsch): the map's shape without the whole-map turn about the first frame that the
gauge leaves (docs/algorithms/batch-optimum.md).

    python3 scripts/optimum_table.py OUT
"""
import csv
import math
import statistics
import sys
from pathlib import Path

import numpy as np

# Two-sided 95 % Student-t quantiles by degrees of freedom.
T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228,
       11: 2.201, 12: 2.179, 13: 2.160, 14: 2.145, 15: 2.131, 19: 2.093, 29: 2.045}
ESTIMATORS = [("base", "relative_point", "Relative (scenario preset)"), ("adaptive", "relative_point", "Relative adaptive"),
              ("relaxed", "relative_point", "Relative relaxed"), ("ekf", "ekf6d", "EKF (MRPT 6D)"),
              ("base", "batch_optimum", "batch optimum"),
              ("motion", "batch_optimum", "batch optimum + EKF's motion model"),
              ("ekfmodel", "batch_optimum", "batch optimum with the EKF's whole model")]


def interval(values):
    values = [v for v in values if v == v]
    if not values:
        return "–"
    mean = statistics.fmean(values)
    if len(values) < 2:
        return f"{mean:.4g}"
    df = len(values) - 1
    t = T95.get(df) or T95[max(k for k in T95 if k <= df)]
    half = t * statistics.stdev(values) / math.sqrt(len(values))
    return f"{mean:.4g} ± {half:.2g}"


def runs(folder):
    """seed -> {algorithm: summary row (with its folder)} for every seed-N/summary.csv below folder."""
    out = {}
    if not folder.is_dir():
        return out
    for summary in sorted(folder.rglob("summary.csv")):
        seed = int(summary.parent.name.removeprefix("seed-"))
        out[seed] = {r["algorithm"]: dict(r, folder=summary.parent) for r in csv.DictReader(open(summary, newline=""))}
    return out


def aligned_error(seed_folder, algorithm):
    """Mean landmark error of a run's map after its best rigid fit to the truth (NaN without)."""
    try:
        truth = {int(r["id"]): [float(r[k]) for k in "xyz"]
                 for r in csv.DictReader(open(seed_folder / "ground_truth_landmarks.csv", newline=""))}
        rows = [r for r in csv.DictReader(open(seed_folder / algorithm / "landmarks.csv", newline=""))
                if r["error"] not in ("", "nan") and r["x"] != "" and int(r["true_id"]) in truth]
    except (OSError, KeyError, ValueError):
        return float("nan")
    if len(rows) < 3:
        return float("nan")
    p = np.array([[float(r[k]) for k in "xyz"] for r in rows])
    q = np.array([truth[int(r["true_id"])] for r in rows])
    u, _, vt = np.linalg.svd((p - p.mean(0)).T @ (q - q.mean(0)))
    d = np.diag([1, 1, np.sign(np.linalg.det(vt.T @ u.T))])
    rotation = vt.T @ d @ u.T
    return float(np.linalg.norm((p - p.mean(0)) @ rotation.T + q.mean(0) - q, axis=1).mean())


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError, TypeError):
        return float("nan")


def over_floor(row, floor):
    """row's final mean landmark error over a floor's, '–' when that floor did not finish."""
    if not floor or floor["status"] != "ok":
        return "–"
    return f"{number(row, 'final_mean_landmark_error') / number(floor, 'final_mean_landmark_error'):.3g}"


def scenario_table(folder):
    parts = {name: runs(folder / name) for name in ("base", "adaptive", "relaxed", "ekf", "motion", "ekfmodel")}
    seeds = sorted(parts["base"])
    if not seeds:
        print(f"\n### {folder.name}: no finished base run yet\n")
        return
    print(f"\n### {folder.name} (seeds {seeds[0]}–{seeds[-1]})\n")
    for seed in seeds:  # every estimator saw the same frames
        digests = {parts[p][seed][a]["input_digest"] for p, a, _ in ESTIMATORS if seed in parts[p] and a in parts[p][seed]}
        if len(digests) != 1:
            sys.exit(f"{folder}: seed {seed}: the estimators saw different frames ({digests})")
    optimum = {s: parts["base"][s]["batch_optimum"] for s in seeds}
    print("| estimator | seeds | not ok (left out) | landmark error | / optimum | aligned | / optimum | ATE | / optimum | ATE aligned "
          "| / optimum | ms/iteration (mean) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    optimum_aligned = {s: aligned_error(r["folder"], "batch_optimum") for s, r in optimum.items()}
    for part, algorithm, label in ESTIMATORS:
        every = {s: parts[part][s][algorithm] for s in seeds if s in parts[part] and algorithm in parts[part][s]}
        # Only finished runs enter the statistics: an interrupted, stopped or failed run is named
        # in "not ok" and left out, as is a seed whose optimum did not finish.
        bad = [f"{s} ({r['status']})" for s, r in every.items() if r["status"] != "ok"]
        bad += [f"{s} (not run)" for s in seeds if s not in every]
        rows = {s: r for s, r in every.items() if r["status"] == "ok" and optimum[s]["status"] == "ok"}
        if not rows:
            print(f"| {label} | 0 | {', '.join(bad) or '–'} | – | – | – | – | – | – | – | – | – |")
            continue
        err = [number(r, "final_mean_landmark_error") for r in rows.values()]
        ate = [number(r, "ate_rmse") for r in rows.values()]
        err_ratio = [number(r, "final_mean_landmark_error") / number(optimum[s], "final_mean_landmark_error")
                     for s, r in rows.items()]
        ate_ratio = [number(r, "ate_rmse") / number(optimum[s], "ate_rmse") for s, r in rows.items()]
        ate_aligned = [number(r, "ate_rmse_aligned") for r in rows.values()]
        ate_aligned_ratio = [number(r, "ate_rmse_aligned") / number(optimum[s], "ate_rmse_aligned") for s, r in rows.items()]
        ms = [number(r, "runtime_mean_ms") for r in rows.values()]
        aligned = {s: aligned_error(r["folder"], algorithm) for s, r in rows.items()}
        aligned_ratio = [a / optimum_aligned[s] for s, a in aligned.items()]
        print(f"| {label} | {len(rows)} | {', '.join(bad) or '–'} | {interval(err)} | {interval(err_ratio)} | "
              f"{interval(list(aligned.values()))} | {interval(aligned_ratio)} | {interval(ate)} | "
              f"{interval(ate_ratio)} | {interval(ate_aligned)} | {interval(ate_aligned_ratio)} | {interval(ms)} |")
    solve = [number(r, "solve_s") for r in optimum.values() if r["status"] == "ok"]
    print(f"\nbatch optimum solve time per run: {interval(solve)} s "
          f"(max {max(solve):.3g} s; its ms/iteration above is storing the frames only)\n")
    print("| seed | relaxed / EKF landmark error | relaxed / EKF ATE | relaxed / optimum landmark error "
          "| relaxed / optimum aligned | EKF / optimum + motion model | EKF / optimum with its whole model "
          "| EKF / optimum aligned | EKF status |")
    print("|---|---|---|---|---|---|---|---|---|")
    for s in seeds:
        if s not in parts["relaxed"]:
            continue
        relaxed, ekf = parts["relaxed"][s]["relative_point"], parts["ekf"].get(s, {}).get("ekf6d")
        status = ekf["status"] if ekf else "not run"
        if ekf and ekf["status"] != "ok":
            ekf = None  # an unfinished EKF is no comparison
        e = number(relaxed, "final_mean_landmark_error")
        ekf_floor = "– | – | –"
        if ekf:
            over = [over_floor(ekf, parts[p].get(s, {}).get("batch_optimum")) for p in ("motion", "ekfmodel")]
            ekf_floor = f"{' | '.join(over)} | {aligned_error(ekf['folder'], 'ekf6d') / optimum_aligned[s]:.3g}"
        over_ekf = (f"{e / number(ekf, 'final_mean_landmark_error'):.3g} | "
                    f"{number(relaxed, 'ate_rmse') / number(ekf, 'ate_rmse'):.3g}") if ekf else "– | –"
        print(f"| {s} | {over_ekf} | {e / number(optimum[s], 'final_mean_landmark_error'):.3g} | "
              f"{aligned_error(relaxed['folder'], 'relative_point') / optimum_aligned[s]:.3g} | {ekf_floor} | "
              f"{status} |")

def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    for folder in sorted(p for p in out.iterdir() if (p / "base").is_dir()):
        scenario_table(folder)


if __name__ == "__main__":
    main()
