#!/usr/bin/python3
"""E28's table (paper §III): noise_sweep.csv of a `relslam sweep` over the
point noise (scenarios/p-em-noise-sweep.json), one row per cell, aggregated over the seeds.

Per cell (the sweep's axis columns, e.g. `variant`): σ_pt and EM's d_in from the runs' manifest.json;
the extraction's frame means of em_frames.csv (recall, precision, normal error of the correct
detections) and its median ms per frame, averaged over the seeds; and the map of summary.csv's
relative_plane row (final mean e_ends with its standard deviation over the seeds, walls mapped of
those seen, duplicates, pose-valid share), averaged over the seeds. Rows in ascending σ_pt. It reads
CSV and JSON only, so it can be rerun on any sweep folder; scripts/reproduce.sh runs it after the
sweep, and figures.py (extra e28-noise-sweep) and claims.py (E28) read the table it writes.

Usage: /usr/bin/python3 scripts/plot/noise_sweep.py SWEEP   (writes SWEEP/noise_sweep.csv)
Exit codes: 0 written, 1 a file of the sweep is missing or malformed (the message names it), 2 bad
command line.
"""
import argparse
import csv
import os
import sys

import numpy as np

import relslam_plot as rp

NAME = "noise_sweep.csv"
PLANE = "relative_plane"
SUMMARY = ["final_mean_map_error", "walls_mapped", "walls_seen", "duplicates", "pose_valid_fraction"]
FRAMES = ["recall", "precision", "mean_normal_err_deg", "ms"]
COLUMNS = ["point_sigma", "inlier_distance", "seeds", "frames", "em_recall", "em_precision", "mean_normal_err_deg",
           "em_median_ms", "final_mean_map_error", "final_mean_map_error_std", "walls_mapped", "walls_seen", "duplicates",
           "pose_valid_fraction"]


def axes_of(path):
    """The sweep's axis columns: sweep.csv's columns before `seed`."""
    with open(path, newline="") as f:
        header = next(csv.reader(f), [])
    if "seed" not in header:
        raise rp.DataError(f"{path}: missing column(s) seed")
    return header[:header.index("seed")]


def setting(run, *keys):
    """A value of the scenario in RUN/manifest.json (every default resolved there)."""
    path = os.path.join(run, "manifest.json")
    try:
        value = rp.read_manifest(run)
    except (OSError, ValueError) as e:
        raise rp.DataError(f"{path}: {e}") from None
    for key in ("scenario", *keys):
        if not isinstance(value, dict) or key not in value:
            raise rp.DataError(f"{path}: no scenario.{'.'.join(keys)}")
        value = value[key]
    return float(value)


def one_run(run):
    """{column: value} of one seed's run: its extraction's frame means and its map."""
    frames = rp.read_table(os.path.join(run, "em_frames.csv"), FRAMES)
    if len(frames["recall"]) == 0:
        raise rp.DataError(f"{os.path.join(run, 'em_frames.csv')}: no rows")
    path = os.path.join(run, "summary.csv")
    s = rp.read_table(path, ["algorithm", *SUMMARY], text=("algorithm",))
    rows = np.nonzero(s["algorithm"] == PLANE)[0]
    if len(rows) == 0:
        raise rp.DataError(f"{path}: column algorithm: no {PLANE} row")
    normals = frames["mean_normal_err_deg"][np.isfinite(frames["mean_normal_err_deg"])]
    return {"point_sigma": setting(run, "planar", "noise", "point_sigma"),
            "inlier_distance": setting(run, "relative_plane", "em", "inlier_distance"),
            "frames": len(frames["recall"]), "em_recall": frames["recall"].mean(),
            "em_precision": frames["precision"].mean(),
            "mean_normal_err_deg": normals.mean() if len(normals) else float("nan"),
            "em_median_ms": float(np.median(frames["ms"])),
            **{c: s[c][rows[0]] for c in SUMMARY}}


def table(sweep):
    """[(cell labels {axis: value}, {column: value})] in ascending σ_pt: each cell's seeds averaged."""
    path = os.path.join(sweep, "sweep.csv")
    if not os.path.exists(path):
        raise rp.DataError(f"{path}: file not found")
    axes = axes_of(path)
    t = rp.read_table(path, [*axes, "folder", "algorithm"], text=(*axes, "folder", "algorithm"))
    cells = {}
    for k in range(len(t["folder"])):
        if t["algorithm"][k] == PLANE:
            cells.setdefault(tuple(t[a][k] for a in axes), []).append(one_run(os.path.join(sweep, t["folder"][k])))
    if not cells:
        raise rp.DataError(f"{path}: column algorithm: no {PLANE} rows")
    out = []
    for labels, runs in cells.items():
        row = {c: float(np.mean([r[c] for r in runs])) for c in runs[0]}
        errors = [r["final_mean_map_error"] for r in runs]
        row.update(seeds=len(runs), frames=sum(r["frames"] for r in runs),
                   final_mean_map_error_std=float(np.std(errors, ddof=1)) if len(runs) > 1 else float("nan"))
        out.append((dict(zip(axes, labels)), row))
    return sorted(out, key=lambda cell: cell[1]["point_sigma"])


def write(sweep):
    """SWEEP/noise_sweep.csv from table(); returns its path."""
    cells = table(sweep)
    axes = list(cells[0][0])
    path = os.path.join(sweep, NAME)
    with open(path, "w", newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(axes + COLUMNS)
        for labels, row in cells:
            out.writerow([labels[a] for a in axes] +
                         ["" if not np.isfinite(row[c]) else f"{row[c]:.10g}" for c in COLUMNS])
    return path


def read(sweep):
    """noise_sweep.csv as {column: array} (plots read the table, not the runs)."""
    path = os.path.join(sweep, NAME)
    if not os.path.exists(path):
        raise rp.DataError(f"{path}: file not found (make it with scripts/plot/noise_sweep.py {sweep})")
    t = rp.read_table(path, COLUMNS)
    if len(t["point_sigma"]) == 0:
        raise rp.DataError(f"{path}: no rows")
    return t


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep", help="a relslam sweep folder over the point noise (sweep.csv and its runs)")
    args = parser.parse_args()
    try:
        print(f"wrote {write(args.sweep)}")
    except rp.DataError as e:
        print(f"noise_sweep: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
