#!/usr/bin/python3
"""EKF versus Relative Point run time in one run, as the EKF's map grows (thesis Fig 148).

Prints, per band of EKF map size, the median time per iteration of both algorithms and their
ratio, and the map size at which the EKF first needs more than --threshold ms per iteration
(median over a 12-iteration window, so one slow step does not count); plots both against the
map size.

Usage: scripts/plot/ekf_timing.py --run runs/bench-ekf [--band 50] [--threshold 100]
"""
import argparse
import os
import statistics

import matplotlib.pyplot as plt

import relslam_plot as rp

COLUMNS = ["iteration", "runtime_ms", "landmarks_in_map"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="run folder of relslam run with relative_point and ekf6d")
    parser.add_argument("--band", type=int, default=50, help="map-size band width (landmarks)")
    parser.add_argument("--threshold", type=float, default=100.0, help="EKF time per iteration to report, ms")
    parser.add_argument("--out", help="plot folder (default: RUN/plots)")
    args = parser.parse_args()
    ekf = rp.read_columns(os.path.join(args.run, "ekf6d", "iterations.csv"), COLUMNS)
    rel = rp.read_columns(os.path.join(args.run, "relative_point", "iterations.csv"), COLUMNS)
    n = min(len(ekf["iteration"]), len(rel["iteration"]))  # the EKF may have stopped early

    bands = {}
    for k in range(n):
        band = int(ekf["landmarks_in_map"][k]) // args.band
        bands.setdefault(band, ([], []))
        bands[band][0].append(ekf["runtime_ms"][k])
        bands[band][1].append(rel["runtime_ms"][k])
    print(f"{'EKF map size':>14} {'iterations':>10} {'EKF ms':>10} {'Relative ms':>12} {'EKF/Relative':>13}")
    for band in sorted(bands):
        e, r = (statistics.median(v) for v in bands[band])
        print(f"{band * args.band:>6}-{(band + 1) * args.band - 1:<7} {len(bands[band][0]):>10} {e:>10.3f} {r:>12.4f} "
              f"{e / r:>13.0f}")

    window = 12
    crossing = None
    for k in range(window, n):
        if statistics.median(ekf["runtime_ms"][k - window:k]) > args.threshold:
            crossing = k
            break
    if crossing is None:
        print(f"the EKF stayed under {args.threshold:g} ms per iteration for all {n} iterations "
              f"(map up to {int(max(ekf['landmarks_in_map'][:n]))} landmarks)")
    else:
        print(f"the EKF passes {args.threshold:g} ms per iteration at iteration {crossing}, "
              f"with {int(ekf['landmarks_in_map'][crossing])} landmarks on its map")

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(ekf["landmarks_in_map"][:n], ekf["runtime_ms"][:n], ".", ms=2, label="ekf6d")
    ax.plot(rel["landmarks_in_map"][:n], rel["runtime_ms"][:n], ".", ms=2, label="relative_point")
    ax.axhline(args.threshold, color="grey", lw=0.8, ls="--")
    ax.set_yscale("log")
    ax.set_xlabel("landmarks on the map (each algorithm's own)")
    ax.set_ylabel("run time per iteration (ms)")
    ax.legend()
    ax.set_title("run time against map size (thesis Fig 148)")
    print(f"plot: wrote {rp.save(fig, args.out or os.path.join(args.run, 'plots'), 'ekf_timing')}")


if __name__ == "__main__":
    main()
