#!/usr/bin/env python3
"""Markdown table of Relative Point / EKF ratios from a relslam sweep's aggregate.csv.

Each run's summary.csv has a row "relative_point/ekf6d" (the ratio on the same stream);
aggregate.csv gives its mean and 95 % confidence interval over the seeds of each cell. This
prints them per cell for ATE, mean landmark error (final) and median time per iteration, and
marks the cells where the ATE ratio's mean exceeds the goal (1.5).

    python3 scripts/sweep_ratio_table.py runs/sweep16/aggregate.csv [--goal 1.5]
"""
import argparse
import csv
import sys

METRICS = [("ate_rmse", "ATE"), ("final_mean_landmark_error", "mean landmark error"),
           ("runtime_median_ms", "median ms/iteration")]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("aggregate", help="aggregate.csv of relslam sweep")
    parser.add_argument("--ratio", default="relative_point/ekf6d", help="the ratio row's algorithm name")
    parser.add_argument("--goal", type=float, default=1.5, help="ATE ratio goal")
    args = parser.parse_args()
    try:
        rows = list(csv.DictReader(open(args.aggregate, newline="")))
    except OSError as e:
        sys.exit(f"{args.aggregate}: {e.strerror}")
    fixed = {"algorithm", "runs", "ok", "not_ok_seeds"}
    if not rows or "algorithm" not in rows[0]:
        sys.exit(f"{args.aggregate}:1: algorithm: not an aggregate.csv of relslam sweep")
    axes = [c for c in rows[0] if c not in fixed and not c.endswith(("_mean", "_std", "_ci95"))]
    ratios = [r for r in rows if r["algorithm"] == args.ratio]
    if not ratios:
        sys.exit(f"{args.aggregate}: algorithm: no row '{args.ratio}' (run both algorithms)")
    print("| " + " | ".join(axes + [f"{label} RP/EKF (95 % CI)" for _, label in METRICS]) + " | runs ok |")
    print("|" + "---|" * (len(axes) + len(METRICS) + 1))
    missed = 0
    for r in ratios:
        cells = [r[a] for a in axes]
        for key, _ in METRICS:
            mean, ci = r.get(key + "_mean", ""), r.get(key + "_ci95", "")
            known = mean not in ("", "nan") and ci not in ("", "nan")
            text = f"{float(mean):.3g} ± {float(ci):.2g}" if known else "—"
            if key == "ate_rmse" and mean not in ("", "nan") and float(mean) > args.goal:
                text += " ✗"
                missed += 1
            cells.append(text)
        cells.append(f"{r['ok']}/{r['runs']}")
        print("| " + " | ".join(cells) + " |")
    print(f"\n{len(ratios) - missed} of {len(ratios)} cells meet the ATE goal (RP/EKF ≤ {args.goal}).")


if __name__ == "__main__":
    main()
