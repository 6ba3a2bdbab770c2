#!/usr/bin/python3
"""Thesis charts from the run folders `relslam` writes: Chapter 4's Relative Plane figures (Figs 64-102,
the paper's Figs 1-5), Chapter 5's (Figs 46, 55-61, 105-108, the paper's Figs 6-8) and Chapter 6's
Relative Point figures (Figs 110-171).

Every figure reads only CSV/JSON files below RUNS (the folder names of scripts/reproduce.sh, listed
in FIGURES) and writes one PNG, OUT/fig<N>.png (extras: OUT/components.png, OUT/vp-timing.png,
OUT/vp-bridged.png), of
FIGSIZE x DPI pixels. A figure whose run folder is missing is skipped with a line naming the
folder; a malformed file is reported with its name and column, and the other figures go on.

Usage:
  /usr/bin/python3 scripts/plot/figures.py --runs RUNS --out OUT [--fig 146 147 ...] [--list]
Exit codes: 0 every figure rendered or skipped for missing runs, 1 some file was malformed,
2 bad command line.
"""
import argparse
import dataclasses
import functools
import json
import os
import sys

import matplotlib.pyplot as plt
import numpy as np

import catalogue
import noise_sweep
import relslam_plot as rp

FIGSIZE, DPI = (10, 6), 100  # 1000 x 600 pixels; plot_test.sh checks it
ALG = "relative_point"
STEADY_FROM = 200  # spec §8: density means are over iterations 200..end (Fig 136 also starts there)
SMOOTH = 12  # Fig 136's moving average, iterations
COMPONENTS = ["t_init_ms", "t_load_ms", "t_compute_ms", "t_create_ms"]  # thesis 6.6.3's buckets
COMPONENT_NAMES = {"t_init_ms": "init", "t_load_ms": "load", "t_compute_ms": "compute", "t_create_ms": "create",
                   "t_pose_ms": "pose", "t_other_ms": "other"}
VISIBLE = "mean visible points per iteration n (labels: density)"
MS = "ms per iteration"
LE = "landmark error (units)"
BASELINE = {"color": "deeppink", "lw": 2.8, "zorder": 5}  # the thesis draws its baseline pink and thick
PAIRING = "every_bin"  # the thesis's pairing rule: it shows Fig 113's polynomial growth (README, RltBinning)
REFERENCES = {"n_minus_1": "n − 1", "n_ln_n": "n·ln n", "three_n_ln_n": "3n·ln n", "n_squared_half": "n²/2"}
TENS = tuple(range(0, 100, 10))
THESIS_VP_MS = {1: 0.296, 2: 0.40, 3: 0.57}  # thesis 6.8, seconds per iteration x 1000
VP_FITTED = "landmarks_similarity_fit.csv"  # x,y in the GPS frame after map_comparison's fit


# ---- reading run folders -------------------------------------------------------------------

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


def density_table(sweep):
    """Per density, ascending: steady-state means of run time, visible points and components, averaged
    over the seeds (the thesis's density.csv, spec §7.2)."""
    columns = ["runtime_ms", "visible_points", *COMPONENTS]
    per_density = {}
    for value, folder in sweep_runs(sweep, "sim.density"):
        d = iterations(folder, columns)
        per_density.setdefault(float(value), []).append([steady(d[c]).mean() for c in columns])
    densities = sorted(per_density)
    means = np.array([np.mean(per_density[d], axis=0) for d in densities])
    table = {"density": np.array(densities), **{c: means[:, i] for i, c in enumerate(columns)}}
    table["t_other_ms"] = table["runtime_ms"] - sum(table[c] for c in COMPONENTS)
    return table


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise rp.DataError(f"{path}: {e}") from None


# ---- fits ------------------------------------------------------------------------------------

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


# ---- drawing helpers -------------------------------------------------------------------------

def finish(ax, xlabel, ylabel, legend=True):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)


def label_densities(ax, x, y, densities):
    for xi, yi, d in zip(x, y, densities):
        ax.annotate(f"{d:g}", (xi, yi), textcoords="offset points", xytext=(3, 4), fontsize=7)


# ---- figure bodies: each draws into an empty matplotlib figure ------------------------------

def single_series(fig, run, column, ylabel, stride=1, zero=False):
    """One relative_point column against the iteration (Figs 130, 132, 134, 167-171)."""
    d = iterations(run, [column])
    ax = fig.subplots()
    label = ALG if stride == 1 else f"{ALG} (every {stride}th iteration)"
    ax.plot(d["iteration"][::stride], d[column][::stride], lw=0.8, label=label)
    if zero:
        ax.axhline(0, color="grey", lw=0.6)
    finish(ax, "iteration", ylabel)


def location(fig, run, axis):
    """True and estimated robot coordinate (Figs 131, 133, 135); estimate = truth + signed error."""
    truth = rp.read_table(os.path.join(run, "sim_iterations.csv"), ["iteration", axis])
    d = iterations(run, ["e" + axis])
    n = min(len(truth[axis]), len(d["iteration"]))
    ax = fig.subplots()
    ax.plot(truth["iteration"][:n], truth[axis][:n], lw=1.5, label=f"true {axis}")
    ax.plot(d["iteration"][:n], truth[axis][:n] + d["e" + axis][:n], lw=0.8, label=f"estimated {axis} ({ALG})")
    finish(ax, "iteration", f"{axis} location (units)")


def compare_runs(fig, *runs, column, ylabel, labels):
    """The same relative_point column of several runs (Fig 119)."""
    ax = fig.subplots()
    for run, label in zip(runs, labels):
        d = iterations(run, [column])
        ax.plot(d["iteration"], d[column], lw=1, label=label)
    finish(ax, "iteration", ylabel)


def compare_algorithms(fig, run, column, ylabel, logy=False):
    """Every algorithm of one run on the same stream (Figs 146-152)."""
    ax = fig.subplots()
    for algorithm in algorithms(run):
        d = iterations(run, [column], algorithm)
        ax.plot(d["iteration"], d[column], lw=0.9, label=algorithm)
    if logy:
        ax.set_yscale("log")  # the EKF is orders of magnitude slower (thesis Fig 148)
    finish(ax, "iteration", ylabel)
    return ax


def point_count(fig, run):
    """Fig 149: map sizes, plus the true landmarks seen so far when observations.csv was written."""
    ax = compare_algorithms(fig, run, "landmarks_in_map", "landmarks on the map")
    path = os.path.join(run, "observations.csv")
    if os.path.exists(path):
        obs = rp.read_table(path, ["iteration", "true_id"])
        _, first = np.unique(obs["true_id"], return_index=True)
        first_seen = np.sort(obs["iteration"][first])
        it = np.unique(obs["iteration"])
        ax.plot(it, np.searchsorted(first_seen, it, side="right"), "k:", lw=1, label="true points seen so far")
        ax.legend(fontsize=8)


def runtime_difference(fig, a, b, label, trend=False):
    """Per-iteration run time of run a minus run b (Fig 110: incremental - rebuilt; Fig 117: binning
    on - off), raw and smoothed, optionally with its linear trend."""
    da, db = iterations(a, ["runtime_ms"]), iterations(b, ["runtime_ms"])
    n = min(len(da["iteration"]), len(db["iteration"]))
    it, diff = da["iteration"][:n], da["runtime_ms"][:n] - db["runtime_ms"][:n]
    ax = fig.subplots()
    ax.plot(it, diff, color="lightgrey", lw=0.5, label=f"{label}, per iteration")
    ax.plot(it, rp.moving_average(diff, SMOOTH), lw=1, label=f"{SMOOTH}-iteration moving average "
                                                            f"(mean {np.mean(diff):.3g} ms)")
    if trend:
        slope, intercept = line_fit(it, diff)
        ax.plot(it, slope * it + intercept, "r--", label=f"linear trend, slope {slope * 1000:.3g} ms per 1000 it.")
    ax.axhline(0, color="black", lw=0.6)
    finish(ax, "iteration", f"Δ run time (ms): {label}")


def runtime_trend(fig, run):
    """Fig 136: run time from iteration 200, smoothed, with its regression line."""
    d = iterations(run, ["runtime_ms"])
    it, t = steady(d["iteration"]), steady(d["runtime_ms"])
    slope, intercept = line_fit(it, t)
    ax = fig.subplots()
    ax.plot(it, rp.moving_average(t, SMOOTH), lw=0.8, label=f"{ALG}, {SMOOTH}-iteration moving average")
    ax.plot(it, slope * it + intercept, "r--", label=f"linear regression, slope {slope * 1000:.3g} ms per 1000 it.")
    finish(ax, "iteration", MS)


def variant_lines(fig, sweep, columns, ylabels, emphasis=(), only=None):
    """Group-constant sweep (Figs 120-126): one line per variant, the baseline pink and thick, the
    `emphasis` variants thick, the rest thin when something is emphasised."""
    series = sweep_series(sweep, columns)
    names = [v for v in series if only is None or v in only]
    if not names:
        raise rp.DataError(f"{sweep}/sweep.csv: column variant: none of {', '.join(only)}")
    axes = np.atleast_1d(fig.subplots(len(columns), 1, sharex=True))
    colours = dict(zip(series, plt.cm.tab20(np.linspace(0, 1, 20))))  # 13 variants outrun the default 10 colours
    for ax, column, ylabel in zip(axes, columns, ylabels):
        for name in names:
            ax.plot(series[name]["iteration"], series[name][column], label=name,
                    **{"color": colours[name], **variant_style(name, emphasis)})
        finish(ax, "iteration" if ax is axes[-1] else "", ylabel, legend=False)
    axes[0].legend(fontsize=7, ncol=2)  # one legend: every panel has the same variants


def variant_style(name, emphasis):
    if name == "baseline":
        return BASELINE
    if name in emphasis:
        return {"lw": 2.2, "zorder": 6}  # above the baseline: these are what the figure is about
    return {"lw": 0.7, "alpha": 0.55} if emphasis else {"lw": 1}


def binning_lines(fig, run, column, ylabel, heuristic, percents=TENS, refs=(), correlated=False):
    """S-BIN means (Figs 111-116): one line per share of uncorrelated points, reference curves from
    the file, optionally Fig 114's correlated mix."""
    path = os.path.join(run, "binning_bench_means.csv")
    t = rp.read_table(path, ["variant", "pairing", "heuristic", "percent", "n", column, *refs],
                      text=("variant", "pairing"))
    rows = (t["pairing"] == PAIRING) & (t["heuristic"] == heuristic)
    uncorrelated = rows & (t["variant"] == "uncorrelated")
    shown = [p for p in sorted(set(t["percent"][uncorrelated])) if p in percents]
    if not shown:
        raise rp.DataError(f"{path}: column percent: none of {percents} for {PAIRING}, heuristic {heuristic}")
    ax = fig.subplots()
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(shown)))
    for p, colour in zip(shown, colours):
        sel = uncorrelated & (t["percent"] == p)
        ax.plot(t["n"][sel], t[column][sel], ".-", color=colour, lw=1, label=f"{p:g} % uncorrelated")
    if correlated:
        sel = rows & (t["variant"] == "correlated")
        ax.plot(t["n"][sel], t[column][sel], "k.-", lw=2, label="corr: 50 % static, 10 % noise, 4 × 10 % correlated")
    ref_rows = uncorrelated & (t["percent"] == shown[0])
    for ref, style in zip(refs, ["--", "-.", ":", (0, (5, 1, 1, 1))]):
        ax.plot(t["n"][ref_rows], t[ref][ref_rows], ls=style, color="dimgrey", lw=1.2, label=REFERENCES[ref])
    finish(ax, "points binned n", ylabel)
    ax.set_title(f"pairing {PAIRING}, priority heuristic {'on' if heuristic else 'off'}", fontsize=9)


def density_series(ax, sweep, column, label, fits, color=None):
    t = density_table(sweep)
    x, y = t["visible_points"], t[column]
    ax.plot(x, y, "o-", color=color, label=label)
    label_densities(ax, x, y, t["density"])
    draw_fits(ax, x, y, fits, color)


def density_component(fig, sweep, column, fits):
    """Figs 137-141: one time component against the visible points, with fitted reference curves."""
    ax = fig.subplots()
    density_series(ax, sweep, column, f"measured ({COMPONENT_NAMES.get(column, 'total')})", fits)
    finish(ax, VISIBLE, MS)


def density_pair(fig, *sweeps, labels, fits):
    """Figs 144, 145: total time of two density sweeps, each with its fits."""
    ax = fig.subplots()
    for sweep, label, color in zip(sweeps, labels, ["C0", "C1"]):
        density_series(ax, sweep, "runtime_ms", label, fits, color)
    finish(ax, VISIBLE, MS)


def density_shares(fig, sweep):
    """Fig 142: each component's share of the run time, stacked, per density."""
    t = density_table(sweep)
    ax = fig.subplots()
    bottom = np.zeros(len(t["density"]))
    for c in [*COMPONENTS, "t_other_ms"]:
        share = 100 * t[c] / t["runtime_ms"]
        ax.bar([f"{d:g}" for d in t["density"]], share, bottom=bottom, label=COMPONENT_NAMES[c])
        bottom += share
    ax.axhline(65, color="black", ls="--", lw=1, label="thesis: init + load + compute ≈ 65 %")
    finish(ax, "density (points per 100 units)", "share of run time (%)")


def density_excess(fig, sweep):
    """Fig 143: measured time minus its linear extrapolation from the lowest density, total vs load."""
    t = density_table(sweep)
    x = t["visible_points"]
    ax = fig.subplots()
    excess = {name: t[c] - t[c][0] * x / x[0] for c, name in [("runtime_ms", "total"), ("t_load_ms", "load")]}
    for name, y in excess.items():
        ax.plot(x, y, "o-", label=f"{name}: measured − linear extrapolation")
    label_densities(ax, x, excess["total"], t["density"])
    ax.axhline(0, color="grey", lw=0.6)
    finish(ax, VISIBLE, "ms per iteration above linear")


def components(fig, run):
    """Extra: the run-time components of one run over its iterations, stacked and smoothed."""
    names = [*COMPONENTS, "t_pose_ms"]
    d = iterations(run, names)
    ax = fig.subplots()
    ax.stackplot(d["iteration"], *[rp.moving_average(d[c], SMOOTH) for c in names],
                 labels=[COMPONENT_NAMES[c] for c in names])
    finish(ax, "iteration", f"{MS} ({SMOOTH}-iteration moving average)")


def vp_landmarks(run, algorithm, name="landmarks_gps_frame.csv"):
    return rp.read_table(os.path.join(run, algorithm, name), ["x", "y"])


def vp_gps(ax, run, **style):
    gps = rp.read_tum(os.path.join(run, "gps.tum"))
    ax.plot(gps["x"], gps["y"], ".", label="GPS fixes", **style)


def vp_map(fig, run):
    """Figs 163, 165 and vp-bridged: the maps and trajectories over the GPS fixes, in the GPS frame (ekf2d's
    where the run has it)."""
    ax = fig.subplots()
    for algorithm, marker, colour in [(ALG, "s", "tab:blue"), ("ekf2d", "o", "tab:orange")]:
        if algorithm != ALG and not os.path.isdir(os.path.join(run, algorithm)):
            continue
        path = rp.read_table(os.path.join(run, algorithm, "trajectory_gps_frame.csv"), ["x", "y"])
        ax.plot(path["x"], path["y"], color=colour, lw=1, label=f"{algorithm} trajectory")
        lm = vp_landmarks(run, algorithm)
        ax.plot(lm["x"], lm["y"], marker, color=colour, mfc="none", ls="none", label=f"{algorithm} landmarks")
    vp_gps(ax, run, color="black", ms=3)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (m, GPS frame)", "y (m, GPS frame)")


def vp_overlay(fig, run):
    """Figs 164, 166: Relative landmarks (blue squares) over the ekf2d reference map (yellow circles),
    standing in for [PiPa08]; the similarity-fit residuals come from map_comparison.csv. The Relative
    landmarks are drawn after the similarity fit when the run has them (VP_FITTED), else as placed by
    their trajectory's rigid fit to GPS."""
    path = os.path.join(run, "map_comparison.csv")
    fit = rp.read_table(path, ["algorithm", "landmarks", "matched", "rms", "scale"], text=("algorithm",))
    if ALG not in list(fit["algorithm"]):
        raise rp.DataError(f"{path}: column algorithm: no {ALG} row")
    row = list(fit["algorithm"]).index(ALG)
    ax = fig.subplots()
    fitted = os.path.exists(os.path.join(run, ALG, VP_FITTED))
    ref, rel = vp_landmarks(run, "ekf2d"), vp_landmarks(run, ALG, VP_FITTED if fitted else "landmarks_gps_frame.csv")
    ax.plot(ref["x"], ref["y"], "o", ms=11, mfc="gold", mec="black", ls="none", label="ekf2d reference map")
    ax.plot(rel["x"], rel["y"], "s", ms=5, color="blue", ls="none",
            label=f"{ALG} ({'after the similarity fit' if fitted else 'rigid GPS fit of its trajectory'}): "
                  f"{fit['matched'][row]:.0f} of {fit['landmarks'][row]:.0f} matched, similarity-fit RMS "
                  f"{fit['rms'][row]:.3g} m, scale {fit['scale'][row]:.4g}")
    vp_gps(ax, run, color="lightgrey", ms=2)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (m, GPS frame)", "y (m, GPS frame)")


def vp_benchmarks(path):
    """{window: {levels: ms per scan}} from relslam_bench_victoria_park's JSON (labels "levels L,
    window W"); with --benchmark_repetitions only the mean aggregate counts."""
    measured = {}
    for b in read_json(path).get("benchmarks", []):
        levels, _, window = b.get("label", "").partition(", window ")
        repeated = b.get("run_type") == "aggregate" or b.get("repetitions", 1) > 1
        if levels.startswith("levels ") and "ms_per_scan" in b and (not repeated or b.get("aggregate_name") == "mean"):
            measured.setdefault(window, {})[int(levels.split()[1])] = b["ms_per_scan"]
    if not measured:
        raise rp.DataError(f"{path}: no benchmark with label 'levels L, window W' and counter ms_per_scan")
    return measured


def vp_timing(fig, path):
    """Extra: Victoria Park ms per scan per grouping level (Google Benchmark JSON) vs the thesis."""
    measured = vp_benchmarks(path)
    series = {"thesis (Athlon 64 3400+)": THESIS_VP_MS, **{f"ours, window {w}": v for w, v in measured.items()}}
    ax = fig.subplots()
    width = 0.8 / len(series)
    for i, (name, values) in enumerate(series.items()):
        levels = sorted(values)
        bars = ax.bar(np.array(levels) + (i - (len(series) - 1) / 2) * width, [values[k] for k in levels], width,
                      label=name)
        ax.bar_label(bars, fmt="%.3g", fontsize=7)
    ax.set_xticks([1, 2, 3])
    ax.set_yscale("log")  # a 2004 CPU against today's: ratios, not milliseconds, are comparable
    finish(ax, "grouping levels", "ms per scan")


# ---- Chapter 4: the Relative Plane half (spec relative_plane_em.md §6) -----------------------

PLANE = "relative_plane"
MAP_ERROR = "map error per plane (units)"  # mean e_ends, spec §7.2
WALL = {"color": "gold", "lw": 5, "solid_capstyle": "butt", "zorder": 1}  # the thesis draws true walls yellow
MAPPED = {"color": "blue", "lw": 1.6, "zorder": 3}  # and mapped planes blue (Fig 70's text)


def plane_table(run, name, columns, text=()):
    return rp.read_table(os.path.join(run, PLANE, name), columns, text=text)


def true_walls(run):
    return rp.read_table(os.path.join(run, "ground_truth_walls.csv"), ["id", "a_x", "a_z", "b_x", "b_z"])


def true_path(run):
    """{iteration, x, z, psi_deg} of ground_truth_path.tum (TUM time = iteration)."""
    return planar_track(os.path.join(run, "ground_truth_path.tum"))


def planar_track(path):
    """{iteration, x, z, psi_deg} of a planar run's TUM file. The planar turn by ψ is a rotation about −y
    (core/planar_pose.hpp), so q = (0, −sin ψ/2, 0, cos ψ/2)."""
    t = rp.read_tum(path)
    psi = np.degrees(2 * np.arctan2(-np.asarray(t["qy"]), np.asarray(t["qw"])))
    return {"iteration": np.asarray(t["t"]), "x": np.asarray(t["x"]), "z": np.asarray(t["z"]),
            "psi_deg": (psi + 180) % 360 - 180}


def run_loops(run):
    """(loops, iterations) of a planar run from its manifest (0 loops: the map's own path)."""
    path = os.path.join(run, "manifest.json")
    m = read_json(path)
    try:
        return int(m["scenario"]["planar"]["loops"]), int(m["planar_simulation"]["iterations"])
    except (KeyError, TypeError, ValueError):
        raise rp.DataError(f"{path}: no scenario.planar.loops or planar_simulation.iterations") from None


def loop_means(run, column):
    """[(first iteration, last iteration, mean of column)] per loop: the run cut into its loops of equal
    length (the last iteration closes the final loop). Invalid poses (empty fields) are left out."""
    loops, n = run_loops(run)
    if loops < 1:
        raise rp.DataError(f"{os.path.join(run, 'manifest.json')}: scenario.planar.loops is {loops}: no loops")
    d = iterations(run, [column], PLANE)
    edges = np.linspace(0, n, loops + 1).round().astype(int)
    out = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        values = d[column][(d["iteration"] >= lo) & (d["iteration"] < hi)]
        out.append((lo, hi - 1, float(np.nanmean(values)) if np.isfinite(values).any() else float("nan")))
    return out


def group_layout(run):
    """{group id: (x, z, [member plane ids])}: a label at the mean of the member planes' mapped midpoints,
    as the paper draws its X labels ("for display purposes the centroid of the group", paper §II.D)."""
    g = plane_table(run, "groups.csv", ["group_id", "planes"], text=("planes",))
    p = plane_table(run, "planes.csv", ["id", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    mid = {int(i): ((ax + bx) / 2, (az + bz) / 2)
           for i, ax, az, bx, bz in zip(p["id"], p["kp1_x"], p["kp1_z"], p["kp2_x"], p["kp2_z"])
           if np.isfinite([ax, az, bx, bz]).all()}
    out = {}
    for gid, planes in zip(g["group_id"], g["planes"]):
        members = [int(s) for s in planes.split(";") if s and int(s) in mid]
        if members:
            out[int(gid)] = (np.mean([mid[m][0] for m in members]), np.mean([mid[m][1] for m in members]), members)
    return out, mid


def plane_overlay(ax, run, groups=False, title=None):
    """Top-down map (spec §6.0): true walls yellow, mapped planes blue, true path orange, estimated
    path blue; with `groups` each group's X label and a line from it to each member plane."""
    w = true_walls(run)
    for i, (ax_, az, bx, bz) in enumerate(zip(w["a_x"], w["a_z"], w["b_x"], w["b_z"])):
        ax.plot([ax_, bx], [az, bz], label="true walls" if i == 0 else None, **WALL)
    p = plane_table(run, "planes.csv", ["kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    shown = np.isfinite(p["kp1_x"])
    for i, k in enumerate(np.nonzero(shown)[0]):
        ax.plot([p["kp1_x"][k], p["kp2_x"][k]], [p["kp1_z"][k], p["kp2_z"][k]],
                label=f"mapped planes ({shown.sum()})" if i == 0 else None, **MAPPED)
    truth = true_path(run)
    ax.plot(truth["x"], truth["z"], color="orange", lw=1, label="true path")
    est = rp.read_tum(os.path.join(run, PLANE, "trajectory.tum"))
    ax.plot(est["x"], est["z"], color="tab:blue", lw=0.6, ls="--", label="estimated path (valid poses)")
    if groups:
        layout, mid = group_layout(run)
        for gid, (gx, gz, members) in layout.items():
            for m in members:
                ax.plot([gx, mid[m][0]], [gz, mid[m][1]], color="grey", lw=0.5, zorder=2)
            ax.annotate(f"X{gid}", (gx, gz), ha="center", va="center", fontsize=8, zorder=4,
                        bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "grey", "lw": 0.5})
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (units)", "z (units)")
    if title:
        ax.set_title(title, fontsize=9)


def count_summary(run):
    s = rp.read_table(os.path.join(run, "summary.csv"), ["algorithm", "final_mean_map_error", "walls_mapped",
                                                          "walls_seen", "duplicates", "pose_valid_fraction"],
                      text=("algorithm",))
    rows = [i for i, a in enumerate(s["algorithm"]) if a == PLANE]
    if not rows:
        raise rp.DataError(f"{os.path.join(run, 'summary.csv')}: column algorithm: no {PLANE} row")
    return {c: s[c][rows[0]] for c in s if c != "algorithm"}


def map_overlay(fig, run, groups=False):
    """Figs 64, 67: the final map over the true walls."""
    ax = fig.subplots()
    plane_overlay(ax, run, groups)
    s = count_summary(run)
    shows = (f"{s['walls_mapped']:.0f} of {s['walls_seen']:.0f} seen walls mapped, {s['duplicates']:.0f} duplicates, "
             f"final mean map error {s['final_mean_map_error']:.3g} units per plane, pose valid in "
             f"{100 * s['pose_valid_fraction']:.0f} % of the iterations")
    if groups:
        shows += f"; {len(group_layout(run)[0])} groups"
    return shows


def four_planes_errors(fig, run):
    """Fig 70 (E03): map and pose error over the loops of Map A; each loop's mean drawn as a step, since
    "no drift" (thesis 4.3.1) means the last loop's mean is no higher than the first's."""
    d = iterations(run, ["mean_map_error", "position_error"], PLANE)
    axes = fig.subplots(2, 1, sharex=True)
    texts = []
    for ax, column, ylabel in zip(axes, ["mean_map_error", "position_error"], [MAP_ERROR, POS]):
        ax.plot(d["iteration"], d[column], lw=0.4, color="lightsteelblue", label="per iteration")
        loops = loop_means(run, column)
        for k, (lo, hi, mean) in enumerate(loops):
            ax.plot([lo, hi], [mean, mean], color="darkblue", lw=2, label="mean per loop" if k == 0 else None)
        finish(ax, "iteration" if ax is axes[-1] else "", ylabel)
        texts.append(f"{column}: loop 1 mean {loops[0][2]:.3g}, loop {len(loops)} mean {loops[-1][2]:.3g}, "
                     f"max {np.nanmax(d[column]):.3g}")
    return "; ".join(texts)


def rltplane_rows(run, wall=0, first=6):
    """Rows of one plane's untransformed observations (thesis Fig 65: iteration, location, orientation;
    paper Fig 1 adds the plane equation's d): midpoint m, normal n = tangent turned +90° (spec §2.2)
    as (nx, ny, nz) with ny = 0 (2½D), d = −n·m, robot frame."""
    o = rp.read_table(os.path.join(run, "plane_observations.csv"),
                      ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    sel = np.nonzero(o["true_wall"] == wall)[0]
    if len(sel) == 0:
        raise rp.DataError(f"{os.path.join(run, 'plane_observations.csv')}: column true_wall: no wall {wall}")
    rows = []
    for k in [*sel[:first], sel[-1]]:
        a = np.array([o["kp1_x"][k], o["kp1_z"][k]])
        b = np.array([o["kp2_x"][k], o["kp2_z"][k]])
        u = (b - a) / np.linalg.norm(b - a)
        n, m = np.array([-u[1], u[0]]), (a + b) / 2
        rows.append([f"{o['iteration'][k]:.0f}", f"({m[0]:.3f}, {m[1]:.3f})", f"({n[0]:.3f}, 0, {n[1]:.3f})",
                     f"{-n @ m:.3f}", f"({a[0]:.2f}, {a[1]:.2f}) – ({b[0]:.2f}, {b[1]:.2f})"])
    return rows, len(sel)


def rltplane_table(fig, run, wall=0):
    """Fig 65 / paper Fig 1: the RltPlane structure as a table of one plane's untransformed observations."""
    rows, total = rltplane_rows(run, wall)
    rows.insert(len(rows) - 1, ["…"] * 5)
    ax = fig.subplots()
    ax.axis("off")
    table = ax.table(cellText=rows, loc="center", cellLoc="center",
                     colLabels=["iteration", "location m (x, z)", "orientation n (nx, ny, nz)", "d = −n·m",
                                "key points KP1 – KP2"], colWidths=[0.1, 0.2, 0.22, 0.12, 0.36])
    table.auto_set_font_size(False)
    table.set_fontsize(10)
    table.scale(1, 1.8)
    ax.set_title(f"the RltPlane of true wall {wall}: {total} observations, robot frame "
                 f"(plane_observations.csv)", fontsize=10)
    return f"wall {wall} observed {total} times; its location and orientation change with every robot pose"


def invariance(run):
    """E01: per iteration with both walls, the raw midpoint difference m2 − m1 and the Rule 3 offset
    Rot(−θ1)(m2 − m1), θ1 = plane 1's direction a→b (spec §2.4), with the robot's true heading; plus
    the offset the true walls give."""
    o = rp.read_table(os.path.join(run, "plane_observations.csv"),
                      ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    walls = sorted(set(o["true_wall"]))[:2]
    if len(walls) < 2:
        raise rp.DataError(f"{os.path.join(run, 'plane_observations.csv')}: column true_wall: fewer than two walls")
    pose = {"m": {}, "theta": {}}
    for k in range(len(o["iteration"])):
        w = o["true_wall"][k]
        if w in walls:
            key = (o["iteration"][k], walls.index(w))
            pose["m"][key] = np.array([o["kp1_x"][k] + o["kp2_x"][k], o["kp1_z"][k] + o["kp2_z"][k]]) / 2
            pose["theta"][key] = np.arctan2(o["kp2_z"][k] - o["kp1_z"][k], o["kp2_x"][k] - o["kp1_x"][k])
    both = sorted(i for i, j in pose["m"] if j == 0 and (i, 1) in pose["m"])
    raw = np.array([pose["m"][(i, 1)] - pose["m"][(i, 0)] for i in both])
    rel = np.array([planar_rotation(-pose["theta"][(i, 0)]) @ r for i, r in zip(both, raw)])
    path = true_path(run)
    heading = dict(zip(path["iteration"], path["psi_deg"]))
    w = true_walls(run)
    ends = {int(i): (np.array([ax_, az]), np.array([bx, bz]))
            for i, ax_, az, bx, bz in zip(w["id"], w["a_x"], w["a_z"], w["b_x"], w["b_z"])}
    (a1, b1), (a2, b2) = ends[int(walls[0])], ends[int(walls[1])]
    expected = planar_rotation(-np.arctan2(*(b1 - a1)[::-1])) @ ((a2 + b2) / 2 - (a1 + b1) / 2)
    return np.array([heading.get(i, np.nan) for i in both]), raw, rel, expected


def planar_rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def invariance_scatter(fig, run):
    """Fig 66 / paper Fig 3 (E01): raw midpoint difference and Rule 3 offset against the heading."""
    psi, raw, rel, expected = invariance(run)
    axes = fig.subplots(1, 2, sharex=True)
    for ax, j, name in zip(axes, [0, 1], ["Δx", "Δz"]):
        ax.plot(psi, raw[:, j], ".", color="tab:orange", ms=4, label="raw: m2 − m1")
        ax.plot(psi, rel[:, j], ".", color="tab:blue", ms=4, label="Rule 3: Rot(−θ1)(m2 − m1)")
        ax.axhline(expected[j], color="black", lw=0.8, ls="--", label=f"true walls' offset {expected[j]:.3g}")
        finish(ax, "robot heading ψ (degrees)", f"{name} (units)")
    return (f"{len(psi)} iterations with both walls, headings {np.nanmin(psi):.0f}° to {np.nanmax(psi):.0f}°: raw "
            f"std (Δx, Δz) = ({raw[:, 0].std():.3g}, {raw[:, 1].std():.3g}), Rule 3 std = ({rel[:, 0].std():.3g}, "
            f"{rel[:, 1].std():.3g}) about the true ({expected[0]:.3g}, {expected[1]:.3g})")


def hallway_groups(fig, run):
    """Fig 71 (E04): Map B with its groups, and groups and links as the robot goes down the hallway."""
    top, bottom = fig.subplots(2, 1, height_ratios=[1.3, 1])
    plane_overlay(top, run, groups=True)
    d = iterations(run, ["groups", "links"], PLANE)
    # links.csv's first row anchors X0 to the world (Rule 4), so links run level with groups
    for column, style in [("groups", {"lw": 3, "alpha": 0.5}), ("links (incl. X0's anchor)", {"lw": 1.2, "ls": "--"})]:
        bottom.plot(d["iteration"], d[column.split()[0]], drawstyle="steps-post", label=column, **style)
    finish(bottom, "iteration", "count")
    links = plane_table(run, "links.csv", ["from", "linking_planes"], text=("linking_planes",))
    per_link = [len([s for s in p.split(";") if s]) for f, p in zip(links["from"], links["linking_planes"])
                if np.isfinite(f)]
    s = count_summary(run)
    return (f"{d['groups'][-1]:.0f} groups, {len(per_link)} links with {', '.join(map(str, per_link))} linking "
            f"planes; {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls mapped, final mean map error "
            f"{s['final_mean_map_error']:.3g}")


def plane_variants(fig, sweep, columns, ylabels):
    """Figs 72, 73: one line per variant of a planar sweep, one panel per column."""
    series = sweep_series(sweep, columns, algorithm=PLANE)
    axes = np.atleast_1d(fig.subplots(len(columns), 1, sharex=True))
    for ax, column, ylabel in zip(axes, columns, ylabels):
        for (name, d), style in zip(series.items(), [("-", 2.4), ("--", 1.4), (":", 1.4)] * 4):
            # dashed over solid: variants that agree (as Rule 12 on and off may) stay told apart
            ax.plot(d["iteration"], d[column], ls=style[0], lw=style[1], label=name)
        finish(ax, "iteration" if ax is axes[-1] else "", ylabel, legend=False)
    axes[0].legend(fontsize=8)
    return "; ".join(f"{name}: " + ", ".join(f"last {c} {last_finite(d[c]):.3g}" for c in columns)
                     for name, d in series.items())


def last_finite(values):
    """The last value that is not NaN (an iteration without a valid pose leaves its error empty)."""
    finite = np.asarray(values)[np.isfinite(values)]
    return finite[-1] if len(finite) else float("nan")


# ---- registry --------------------------------------------------------------------------------

@dataclasses.dataclass
class Figure:
    id: object  # thesis figure number, or a name for an extra
    title: str
    runs: tuple  # files or folders below RUNS, passed to draw in this order
    draw: object  # draw(matplotlib figure, *run paths) -> None, or one line on what our run shows

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


def _axis_figures():
    out = []
    for axis, error_fig, location_fig, forty_fig in [("x", 130, 131, 169), ("y", 132, 133, 170), ("z", 134, 135, 171)]:
        ylabel = f"{axis} error, estimate − truth (units)"
        out += [Figure(error_fig, f"{axis} error", ("s-f8",), P(single_series, column="e" + axis, ylabel=ylabel,
                                                                 zero=True)),
                Figure(location_fig, f"{axis} location", ("s-f8",), P(location, axis=axis)),
                Figure(forty_fig, f"{axis} error over 40 loops", ("s-40",),
                       P(single_series, column="e" + axis, ylabel=ylabel, stride=10, zero=True))]
    return out


def _binning(number, title, column, ylabel, heuristic, **kw):
    return Figure(number, title, ("s-bin",), P(binning_lines, column=column, ylabel=ylabel, heuristic=heuristic, **kw))


def _variants(number, title, sweep, columns, ylabels, **kw):
    return Figure(number, title, (sweep,), P(variant_lines, columns=columns, ylabels=ylabels, **kw))


def _compare(number, title, run, column, ylabel, **kw):
    return Figure(number, title, (run,), P(compare_algorithms, column=column, ylabel=ylabel, **kw))


def _density(number, title, column, fits):
    return Figure(number, title, ("s-dens-q",), P(density_component, column=column, fits=fits))


CMP = "comparisons"
GROUPS = ["groups", "final_groups"]
GROUP_LABELS = ["groups created", "final groups"]
ALL_REFS = ("n_minus_1", "n_ln_n", "n_squared_half")
POS = "position error (units)"

E05 = ("p-e05-edge-on",)
E06 = ("p-e06-rule12",)

FIGURES = sorted([
    Figure(64, "four planes problem: Map A, true walls and mapped planes, E03", ("p-four-planes",), map_overlay),
    Figure(65, "the RltPlane structure (also paper Fig. 1)", ("p-four-planes",), rltplane_table),
    Figure(66, "invariance issue, E01 (also paper Fig. 3)", ("p-e01-invariance",), invariance_scatter),
    Figure(67, "completed map of Map D with its groups, E21 (also paper Fig. 2)", ("p-e21-completed-map",),
           P(map_overlay, groups=True)),
    Figure(70, "four planes problem: map and pose error per loop, E03", ("p-four-planes",), four_planes_errors),
    Figure(71, "hallway problem: groups and links, E04", ("p-hallway",), hallway_groups),
    Figure(72, "edge-on wall: back-face culling and Rule 10, E05 (a)-(c)", E05,
           P(plane_variants, columns=["position_error", "rlt_planes", "mean_map_error"],
             ylabels=[POS, "RltPlanes", MAP_ERROR])),
    Figure(73, "full simulation: Rule 12 on and off, E06", E06,
           P(plane_variants, columns=["groups", "links", "mean_map_error"], ylabels=["groups", "links", MAP_ERROR])),
    Figure(110, "incremental minus rebuilt global index run time", ("s-f8-2l", "s-f8-2l-rebuilt"),
           P(runtime_difference, label="incremental − rebuilt")),
    _binning(111, "binning comparisons, no heuristic", CMP, "pairwise comparisons", 0, refs=ALL_REFS),
    _binning(112, "points in the highest bin", "highest_bin", "points in the highest bin", 0),
    _binning(113, "binning comparisons (detail)", CMP, "pairwise comparisons", 0, percents=(0, 10, 20, 30, 40),
             refs=("n_ln_n",)),
    _binning(114, "binning with correlated movers", CMP, "pairwise comparisons", 0,
             refs=("n_minus_1", "n_ln_n", "three_n_ln_n", "n_squared_half"), correlated=True),
    _binning(115, "binning with the priority heuristic", CMP, "pairwise comparisons", 1, percents=(0, 10, 20, 30, 40),
             refs=("n_ln_n",)),
    _binning(116, "priority heuristic near the 50 % threshold", CMP, "pairwise comparisons", 1,
             percents=tuple(range(40, 51)), refs=("n_ln_n",)),
    Figure(117, "extra run time of binning", ("s-dyn3", "s-dyn3-no-binning"),
           P(runtime_difference, label="binning on − off", trend=True)),
    Figure(119, "basis selection: landmark error", ("s-f8", "s-f8-first-three"),
           P(compare_runs, column="landmark_error", ylabel=LE,
             labels=("optimised basis (farthest points)", "first three points"))),
    _variants(120, "landmark error per group-constant setting", "s-f8-2l-const", ["landmark_error"], [LE]),
    _variants(121, "groups per group-constant setting", "s-f8-2l-const", GROUPS, GROUP_LABELS),
    _variants(122, "accuracy reduction 1: landmark error", "s-f8-2l-const", ["landmark_error"], [LE],
              emphasis=("ar1",)),
    _variants(123, "accuracy reduction 1: groups and their size", "s-f8-2l-const", ["groups", "mean_group_members"],
              ["groups created", "mean members per live group"], emphasis=("ar1",)),
    _variants(124, "look back / look ahead 90", "s-f8-2l-const", ["landmark_error"], [LE],
              emphasis=("lb90-ar10", "lb90-ar20"), only=("baseline", "lb90-ar10", "lb90-ar20")),
    _variants(125, "NextGroupMin 1", "s-f8-2l-const", ["landmark_error"], [LE],
              emphasis=("next1", "next1-lb90", "next1-prevmax50"),
              only=("baseline", "next1", "next1-lb90", "next1-prevmax50")),
    _variants(126, "seven loops, three settings", "s-f8-7l-const", ["landmark_error"], [LE]),
    *_axis_figures(),
    Figure(136, "run time from iteration 200, double-size figure eight", ("s-f8-2x",), runtime_trend),
    _density(137, "run time against point density", "runtime_ms", ("n", "nlogn", "poly")),
    _density(138, "initialisation time", "t_init_ms", ("n",)),
    _density(139, "point comparison (load) time", "t_load_ms", ("n", "nlogn", "poly")),
    _density(140, "RltGroup computation time", "t_compute_ms", ("n", "nlogn")),
    _density(141, "RltGroup creation time", "t_create_ms", ("n", "poly")),
    Figure(142, "run-time shares per density", ("s-dens-q",), density_shares),
    Figure(143, "time above linear: total vs load", ("s-dens-q",), density_excess),
    Figure(144, "small quads vs default quads", ("s-dens-q", "s-dens-qs"),
           P(density_pair, labels=("quads (default cell)", "small quads (cell 1.5)"), fits=("nlogn", "poly"))),
    Figure(145, "small quads, octree from density 400", ("s-dens-qs", "s-dens-o"),
           P(density_pair, labels=("small quads", "octree"), fits=("n", "nlogn"))),
    _compare(146, "figure-eight landmark error", "s-ekf-f8", "landmark_error", LE),
    _compare(147, "figure-eight position error", "s-ekf-f8", "position_error", POS),
    _compare(148, "figure-eight run time", "s-ekf-f8", "runtime_ms", MS, logy=True),
    Figure(149, "figure-eight point count", ("s-ekf-f8",), point_count),
    _compare(150, "straight-line landmark error", "s-line", "landmark_error", LE),
    _compare(151, "straight-line position error", "s-line", "position_error", POS),
    _compare(152, "stationary landmark error", "s-stat", "landmark_error", LE),
    Figure(163, "Victoria Park, scans 1181-1642", ("vp-1181",), vp_map),
    Figure(164, "Victoria Park 1181-1642 over the ekf2d map", ("vp-1181",), vp_overlay),
    Figure(165, "Victoria Park, scans 4220-4634", ("vp-4220",), vp_map),
    Figure(166, "Victoria Park 4220-4634 over the ekf2d map", ("vp-4220",), vp_overlay),
    Figure(167, "landmark error over 40 loops", ("s-40",), P(single_series, column="landmark_error", ylabel=LE,
                                                                stride=10)),
    Figure(168, "position error over 40 loops", ("s-40",), P(single_series, column="position_error", ylabel=POS,
                                                                stride=10)),
], key=lambda f: f.id) + [
    Figure("components", "run-time components, one figure-eight loop", ("s-f8",), components),
    Figure("vp-timing", "Victoria Park ms per scan by grouping levels", ("vp-timing.json",), vp_timing),
    Figure("vp-bridged", "Victoria Park whole log, bridged by dead reckoning", ("vp-bridged",), vp_map),
]
# ---- issue 13 experiments: Relative Plane part 2 (spec relative_plane_em.md §6.1 E02, E07-E10, E12,
# E15, E18, E32; thesis 4.3.3-4.3.7.1). Every helper reads one sweep's or run's CSVs; claims.py calls the
# same helpers for report/claims.md, so each number is computed in one place.

HEAL_ITERATIONS = 4  # thesis 4.3.4: a wrong key point "self corrected after the fourth iteration"
PAIR_NAMES = {(1, 1): "KP1–KP1", (1, 2): "KP1–KP2", (2, 1): "KP2–KP1", (2, 2): "KP2–KP2"}
UNDER_SIZED = 0.95  # a mapped plane shorter than this share of its wall is under-sized (E09) [R]


def plane_sweep(sweep, axes=("variant",)):
    """[(axis values tuple, [run folders over the seeds])] of a planar sweep, in sweep.csv order."""
    path = os.path.join(sweep, "sweep.csv")
    t = rp.read_table(path, [*axes, "folder", "algorithm"], text=(*axes, "folder", "algorithm"))
    out = {}
    for k in range(len(t["folder"])):
        if t["algorithm"][k] == PLANE:
            out.setdefault(tuple(t[a][k] for a in axes), []).append(os.path.join(sweep, t["folder"][k]))
    if not out:
        raise rp.DataError(f"{path}: column algorithm: no {PLANE} rows")
    return list(out.items())


def variant_folder_of(sweep, name):
    """The first seed's folder of variant `name` of a planar sweep."""
    for (value,), folders in plane_sweep(sweep):
        if value == name:
            return folders[0]
    raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {name!r}")


def seed_mean(folders, column):
    """{iteration, column}: the per-iteration mean over the seeds' runs (cut to the shortest)."""
    runs = [iterations(f, [column], PLANE) for f in folders]
    n = min(len(r["iteration"]) for r in runs)
    values = np.array([r[column][:n] for r in runs])
    seen = np.isfinite(values).sum(axis=0)  # before the first pose no seed has a value: NaN, silently
    return runs[0]["iteration"][:n], np.where(seen > 0, np.nansum(values, axis=0) / np.maximum(seen, 1), np.nan)


# E02 (Fig 68, paper Fig 4) ---------------------------------------------------------------------

def key_point_pair(run):
    """pairs.csv, pair_sigma.csv and the truth of the chosen key points: the share of the pair's
    iterations in which each chosen end is a real wall end (plane_observations.csv joined on the
    iteration and the observation's first end)."""
    cols = ["iteration", "plane1", "plane2", "a1_x", "a1_z", "a2_x", "a2_z"] + [
        f"off{a}{b}_{c}" for a in (1, 2) for b in (1, 2) for c in "xz"]
    series = plane_table(run, "pairs.csv", cols)
    sig = plane_table(run, "pair_sigma.csv", ["kp_a", "kp_b", "sigma", "mean_x", "mean_z", "chosen", "key_point1",
                                              "key_point2", "samples", "interval_start", "interval_end"])
    if len(series["iteration"]) == 0 or len(sig["sigma"]) != 4:
        raise rp.DataError(f"{os.path.join(run, PLANE, 'pairs.csv')}: no pair in which one plane grows while the "
                           f"other shrinks")
    obs = rp.read_table(os.path.join(run, "plane_observations.csv"),
                        ["iteration", "kp1_x", "kp1_z", "kp1_true_end", "kp2_true_end"])
    ends = {(i, x, z): (e1, e2) for i, x, z, e1, e2 in
            zip(obs["iteration"], obs["kp1_x"], obs["kp1_z"], obs["kp1_true_end"], obs["kp2_true_end"])}
    chosen = int(np.nonzero(sig["chosen"] == 1)[0][0])
    right = []
    for plane, key in ((1, "key_point1"), (2, "key_point2")):
        kp = int(sig[key][chosen])
        flags = [ends.get((i, x, z)) for i, x, z in zip(series["iteration"], series[f"a{plane}_x"],
                                                        series[f"a{plane}_z"])]
        right.append(float(np.mean([f[kp - 1] for f in flags if f is not None])) if kp in (1, 2) else float("nan"))
    return series, sig, chosen, right


def key_point_pairs_figure(fig, run):
    """Fig 68 / paper Fig 4 (E02): the four offset series of Rule 13 for one growing and one shrinking
    plane, and their standard deviations; the chosen pair is the lowest."""
    series, sig, chosen, right = key_point_pair(run)
    top, bottom = fig.subplots(1, 2, width_ratios=[2.2, 1])
    t = series["iteration"]
    for k, (a, b) in enumerate(zip(sig["kp_a"].astype(int), sig["kp_b"].astype(int))):
        name = PAIR_NAMES[(a, b)] + (" (chosen)" if k == chosen else "")
        colour = f"C{k}"
        for axis, style in (("x", "-"), ("z", "--")):
            top.plot(t, series[f"off{a}{b}_{axis}"], style, color=colour, lw=2.2 if k == chosen else 1,
                     label=f"{name}, {axis}")
    finish(top, "iteration", "offset in plane 1's frame turned to 0° (units)")
    top.legend(fontsize=7, ncol=2)
    labels = [PAIR_NAMES[(int(a), int(b))] for a, b in zip(sig["kp_a"], sig["kp_b"])]
    bars = bottom.bar(labels, sig["sigma"], color=["tab:green" if k == chosen else "tab:grey" for k in range(4)])
    bottom.bar_label(bars, fmt="%.2g", fontsize=7)
    bottom.set_yscale("log")
    finish(bottom, "assumed-midpoint pair", "σ over the piece (units)", legend=False)
    others = [s for k, s in enumerate(sig["sigma"]) if k != chosen]
    return (f"RltPlanes {series['plane1'][0]:.0f} and {series['plane2'][0]:.0f}, iterations "
            f"{sig['interval_start'][0]:.0f}-{sig['interval_end'][0]:.0f} ({sig['samples'][0]:.0f}): lowest σ "
            f"{sig['sigma'][chosen]:.3g} ({labels[chosen]}), the other three {min(others):.3g}-{max(others):.3g}; "
            f"its key points are real wall ends in {100 * right[0]:.0f} % / {100 * right[1]:.0f} % of the "
            f"iterations")


# E07 (Figs 74, 75) -----------------------------------------------------------------------------

E07_AXES = ("variant", "planar.noise.model")


def interval_mode_errors(sweep):
    """{(mode, noise model): (iterations, mean map error per iteration over the seeds, mean over the run,
    seeds)}."""
    out = {}
    for (mode, noise), folders in plane_sweep(sweep, E07_AXES):
        it, err = seed_mean(folders, "mean_map_error")
        out[(mode, noise)] = (it, err, float(np.nanmean(err)), len(folders))
    return out


def interval_mode_figure(fig, sweep, mode):
    """Figs 74 (group) and 75 (pair), E07: map error over the run under both noise models, and the
    run means of all four combinations as bars."""
    errors = interval_mode_errors(sweep)
    top, bottom = fig.subplots(2, 1, height_ratios=[1.6, 1])
    for (m, noise), (it, err, _, seeds) in errors.items():
        if m == mode:
            top.plot(it, err, lw=1, label=f"{mode} interval, {noise} rotation noise (mean of {seeds} seeds)")
    finish(top, "iteration", MAP_ERROR)
    names = [f"{m}\n{n}" for m, n in errors]
    bars = bottom.bar(names, [v[2] for v in errors.values()],
                      color=["tab:blue" if m == mode else "lightgrey" for m, _ in errors])
    bottom.bar_label(bars, fmt="%.3g", fontsize=7)
    finish(bottom, "", "run mean of the map error", legend=False)
    return "; ".join(f"{m}/{n}: run mean {v[2]:.3g}" for (m, n), v in errors.items())


# E08 (Figs 76-79) ------------------------------------------------------------------------------

def wrong_episodes(run):
    """Runs of consecutive iterations in which one (group, plane)'s key-point claim is wrong, from
    keypoints.csv: [(group, plane, first iteration, iterations)], longest first."""
    k = plane_table(run, "keypoints.csv", ["iteration", "group", "plane", "truth_correct"])
    episodes = []
    open_ = {}
    order = np.lexsort((k["iteration"], k["plane"], k["group"]))
    for i in order:
        key, it, ok = (int(k["group"][i]), int(k["plane"][i])), int(k["iteration"][i]), k["truth_correct"][i] == 1
        start, last = open_.get(key, (None, None))
        if start is not None and (ok or it != last + 1):
            episodes.append((*key, start, last - start + 1))
            start = None
        if not ok:
            open_[key] = (it if start is None else start, it)
        else:
            open_.pop(key, None)
    episodes += [(*key, s, last - s + 1) for key, (s, last) in open_.items() if s is not None]
    return sorted(episodes, key=lambda e: (-e[3], e[2]))


def healing(run):
    """Durations of the wrong key-point episodes: (count, median, share within HEAL_ITERATIONS, max)."""
    d = np.array([e[3] for e in wrong_episodes(run)])
    if len(d) == 0:
        return 0, float("nan"), float("nan"), 0
    return len(d), float(np.median(d)), float(np.mean(d <= HEAL_ITERATIONS)), int(d.max())


EVENT_JUMP = 0.3  # a map-error event: the summed e_ends rises by this much in one iteration, units [R]
EVENT_SETTLED = 0.25  # ... and it has healed once it is back within this share of the jump [R]
EVENT_FROM = 5  # the first iterations build the map from nothing: no events there


def map_error_events(run):
    """Iterations where a plane joins the map with a large error (thesis Figs 76-79: a plane just come
    into view, compared over a tiny interval): [(iteration, jump, iterations until healed or None)]."""
    d = iterations(run, ["map_error", "planes_in_map"], PLANE)
    e, n = d["map_error"], d["planes_in_map"]
    events = []
    for k in range(max(1, EVENT_FROM), len(e)):
        jump = e[k] - e[k - 1]
        if not jump >= EVENT_JUMP:
            continue
        healed = next((h for h in range(1, len(e) - k) if e[k + h] - e[k - 1] <= EVENT_SETTLED * jump), None)
        events.append((int(d["iteration"][k]), float(jump), healed, bool(n[k] > n[k - 1])))
    return events


def event_healing(run):
    """(events, healed within HEAL_ITERATIONS, never healed, median iterations to heal)."""
    ev = map_error_events(run)
    times = [h for _, _, h, _ in ev if h is not None]
    return (len(ev), sum(h <= HEAL_ITERATIONS for h in times), sum(h is None for _, _, h, _ in ev),
            float(np.median(times)) if times else float("nan"))


def largest_healed_event(run):
    """The largest event that healed within HEAL_ITERATIONS (else the largest), as its index in
    iterations.csv."""
    ev = sorted(map_error_events(run), key=lambda x: (x[2] is None or x[2] > HEAL_ITERATIONS, -x[1]))
    d = iterations(run, ["map_error", "mean_map_error", "planes_in_map", "kp_wrong"], PLANE)
    k = int(np.nonzero(d["iteration"] == ev[0][0])[0][0]) if ev else int(np.argmax(d["map_error"]))
    return d, k, (ev[0] if ev else None)


def bad_key_points_figure(fig, sweep, panel):
    """Figs 76-79 (E08): 76 the map error over the run with its events (a plane joining the map with a
    large error), 77 the largest event that healed, iteration by iteration, 78 the key-point claims around
    it, 79 how long events and wrong key points last, against the thesis's four iterations."""
    runs = [(name, folders[0]) for (name,), folders in plane_sweep(sweep)]
    if panel == 79:
        ax = fig.subplots()
        texts = []
        clip = 6 * HEAL_ITERATIONS  # longer (or never) is drawn as one last bin
        bins = np.arange(0, clip + 3) - 0.5
        for (name,), folders in plane_sweep(sweep):
            heal, wrong = [], []
            for run in folders:
                heal += [min(h, clip + 1) if h is not None else clip + 1 for _, _, h, _ in map_error_events(run)]
                wrong += [min(e[3], clip + 1) for e in wrong_episodes(run)]
            ax.hist([heal, wrong], bins=bins, histtype="step", lw=1.5,
                    label=[f"{name}: map-error events ({len(folders)} seeds)", f"{name}: wrong key-point episodes"])
            texts.append(f"{name}, {len(folders)} seed(s): {sum(h <= HEAL_ITERATIONS for h in heal)} of {len(heal)} "
                         f"map-error events healed within {HEAL_ITERATIONS} iterations; "
                         f"{sum(w <= HEAL_ITERATIONS for w in wrong)} of {len(wrong)} wrong key-point episodes "
                         f"over within {HEAL_ITERATIONS}")
        ax.axvline(HEAL_ITERATIONS + 0.5, color="black", ls="--", label=f"thesis: healed by the {HEAL_ITERATIONS}th")
        ticks = [*range(0, clip + 1, HEAL_ITERATIONS), clip + 1]
        ax.set_xticks(ticks, [*map(str, ticks[:-1]), f">{clip}"])
        finish(ax, "iterations until healed", "count")
        return "; ".join(texts)
    name, run = runs[0]
    d, k, event = largest_healed_event(run)
    lo, hi = (0, len(d["iteration"])) if panel == 76 else (max(0, k - 5), min(len(d["iteration"]), k + 15))
    it = d["iteration"][lo:hi]
    if panel == 78:
        claims = plane_table(run, "keypoints.csv", ["iteration", "group", "plane", "truth_correct"])
        sel = (claims["iteration"] >= it[0]) & (claims["iteration"] <= it[-1])
        rows = sorted({(int(g), int(p)) for g, p in zip(claims["group"][sel], claims["plane"][sel])})
        ax = fig.subplots()
        for ok, style in ((1, {"color": "tab:green", "marker": "s", "label": "claim right"}),
                          (0, {"color": "red", "marker": "x", "label": "claim wrong"})):
            m = sel & (claims["truth_correct"] == ok)
            y = [rows.index((int(g), int(p))) for g, p in zip(claims["group"][m], claims["plane"][m])]
            ax.plot(claims["iteration"][m], y, ls="none", ms=4, **style)
        ax.set_yticks(range(len(rows)), [f"X{g} plane {p}" for g, p in rows], fontsize=6)
        ax.axvline(d["iteration"][k], color="grey", ls=":")
        finish(ax, "iteration", "key-point claim (group, plane)")
        wrong = int((sel & (claims["truth_correct"] == 0)).sum())
        return f"{name}: {wrong} wrong key-point claims among {int(sel.sum())} in iterations {it[0]:.0f}-{it[-1]:.0f}"
    if panel == 77:
        ax = fig.subplots()
        ax.bar(it, d["map_error"][lo:hi], width=0.8, color=["red" if i >= d["iteration"][k] and
                                                              i < d["iteration"][k] + HEAL_ITERATIONS else "tab:blue"
                                                              for i in it])
        ax.axvline(d["iteration"][k] + HEAL_ITERATIONS - 0.5, color="black", ls="--",
                   label=f"thesis: corrected after the {HEAL_ITERATIONS}th iteration")
        finish(ax, "iteration", "map error, sum of e_ends (units)")
        healed = "never" if event is None or event[2] is None else f"after {event[2]} iterations"
        return (f"{name}: at iteration {d['iteration'][k]:.0f} a plane joins the map "
                f"({d['planes_in_map'][k - 1]:.0f} → {d['planes_in_map'][k]:.0f}) and the map error jumps {d['map_error'][k - 1]:.3g} → "
                f"{d['map_error'][k]:.3g}; healed (within {100 * EVENT_SETTLED:.0f} % of the jump) {healed}")
    ax = fig.subplots()
    for vname, vrun in runs:
        v = iterations(vrun, ["map_error"], PLANE)
        ax.plot(v["iteration"], v["map_error"], lw=0.8, label=f"{vname}: map error (sum of e_ends)")
    ev = map_error_events(run)
    ax.plot([e[0] for e in ev], [d["map_error"][int(np.nonzero(d["iteration"] == e[0])[0][0])] for e in ev], "rv",
            label=f"{name}: events (a jump of ≥ {EVENT_JUMP:g} in one iteration)")
    finish(ax, "iteration", "map error (units)")
    n, quick, never, median = event_healing(run)
    return (f"{name}: {n} events, {quick} healed within {HEAL_ITERATIONS} iterations, {never} never healed; final map "
            f"error {d['map_error'][-1]:.3g}")


# E09 (Figs 80, 81) and E15 (Figs 90-92): the map per wall ---------------------------------------

def wall_table(run):
    """planes.csv's mapped planes: {true_wall: [(len_ratio, e_ends), ...]} (a wall with two planes has two)."""
    p = plane_table(run, "planes.csv", ["true_wall", "len_ratio", "e_ends"])
    out = {}
    for w, r, e in zip(p["true_wall"], p["len_ratio"], p["e_ends"]):
        if np.isfinite(w):
            out.setdefault(int(w), []).append((r, e))
    return out


def under_sized(run):
    """Walls whose largest mapped plane is under UNDER_SIZED of their length: [(wall, len_ratio)]."""
    return [(w, max(r for r, _ in v)) for w, v in sorted(wall_table(run).items())
            if max(r for r, _ in v) < UNDER_SIZED]


def per_wall_bars(fig, sweep, column, ylabel, names=None):
    """One bar per true wall and variant (the largest plane of a wall when it has two)."""
    variants = [(n, f[0]) for (n,), f in plane_sweep(sweep) if names is None or n in names]
    ax = fig.subplots()
    width = 0.8 / len(variants)
    texts = []
    for i, (name, run) in enumerate(variants):
        table = wall_table(run)
        walls = sorted(table)
        values = [max(table[w])[0 if column == "len_ratio" else 1] for w in walls]
        ax.bar(np.array(walls) + (i - (len(variants) - 1) / 2) * width, values, width, label=name)
        s = count_summary(run)
        small = under_sized(run)
        texts.append(f"{name}: {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls, {s['duplicates']:.0f} "
                     f"duplicates, final mean map error {s['final_mean_map_error']:.3g}, under-sized "
                     + (", ".join(f"wall {w} ({r:.2f})" for w, r in small) or "none"))
    if column == "len_ratio":
        ax.axhline(1, color="black", lw=0.6)
    finish(ax, "true wall", ylabel)
    return "; ".join(texts)


def variant_overlays(fig, sweep, names, groups=False):
    """The final maps of some variants side by side (true walls yellow, planes blue; with `groups` each
    group's X label and member lines, and the start group's planes in the text)."""
    axes = np.atleast_1d(fig.subplots(1, len(names)))
    for ax, name in zip(axes, names):
        plane_overlay(ax, variant_folder_of(sweep, name), groups=groups, title=name)
    texts = []
    for name in names:
        run = variant_folder_of(sweep, name)
        s = count_summary(run)
        texts.append(f"{name}: {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls mapped, "
                     f"{s['duplicates']:.0f} duplicates, final mean map error {s['final_mean_map_error']:.3g}")
        if groups:
            layout = group_layout(run)[0]
            texts[-1] += (f", {len(layout)} groups on the map, X0 holds plane(s) "
                          + (", ".join(map(str, layout[0][2])) if 0 in layout else "none"))
    return "; ".join(texts)


# E10 (Fig 82) ---------------------------------------------------------------------------------

def group_counts(sweep):
    """{variant: groups at the end} of the E10 sweep."""
    return {name: int(iterations(folders[0], ["groups"], PLANE)["groups"][-1]) for (name,), folders in
            plane_sweep(sweep)}


REVISIT_AWAY, REVISIT_BACK = 5.0, 1.0  # units: the robot has been this far from its start, and is back this close


def revisit_time(run):
    """Summed step time (ms) over the revisit phase (thesis 4.3.5: "when the robot visits a previously
    viewed area"): from the first iteration at which the true robot is back within REVISIT_BACK of its
    start after having been REVISIT_AWAY from it, to the end. (total ms, first iteration), or None when
    the run ends before the robot returns (a shortened run)."""
    path = true_path(run)
    gone = np.hypot(path["x"] - path["x"][0], path["z"] - path["z"][0])
    away = np.nonzero(gone >= REVISIT_AWAY)[0]
    back = np.nonzero((gone <= REVISIT_BACK) & (np.arange(len(gone)) > (away[0] if len(away) else len(gone))))[0]
    if len(back) == 0:
        return None
    start = path["iteration"][back[0]]
    d = iterations(run, ["runtime_ms"], PLANE)
    return float(np.sum(d["runtime_ms"][d["iteration"] >= start])), int(start)


def too_many_groups(fig, sweep):
    """Fig 82 (E10): groups over the run per Rule 21/22 variant, the thesis's 21 and 30 marked."""
    ax = fig.subplots()
    for (name,), folders in plane_sweep(sweep):
        d = iterations(folders[0], ["groups"], PLANE)
        ax.plot(d["iteration"], d["groups"], drawstyle="steps-post", lw=1.2, label=f"{name}: {d['groups'][-1]:.0f}")
    for n, text in ((21, "thesis without Rule 21: 21"), (30, "thesis with it: 30")):
        ax.axhline(n, color="grey", ls=":", lw=0.8)
        ax.annotate(text, (0, n), fontsize=7, va="bottom")
    finish(ax, "iteration", "groups (RltXPoints)")
    return "; ".join(f"{k}: {v} groups" for k, v in group_counts(sweep).items())


# E12 (Fig 87) ---------------------------------------------------------------------------------

def size_mismatches(run):
    """edges.csv: the edges whose lengths differ from the planes' canonical sizes (Rule 28's L_e vs L*)."""
    e = plane_table(run, "edges.csv", ["valid", "length1", "length2", "canonical1", "canonical2"])
    gap = np.maximum(np.abs(e["length1"] - e["canonical1"]), np.abs(e["length2"] - e["canonical2"]))
    return int(np.sum((e["valid"] == 1) & (gap > 0.02))), len(gap), float(np.max(gap, initial=0.0))


OFF_LINE = 1e-6  # noise-free: a plane further than this from its wall's line is misplaced (spec §8's bound)


def misplaced(run):
    """Mapped planes off their wall's line (e_perp above OFF_LINE): [(wall, e_perp)]; the measure of a
    placement error that does not count walls never seen whole (e_ends does)."""
    p = plane_table(run, "planes.csv", ["true_wall", "e_perp"])
    return [(int(w), float(e)) for w, e in zip(p["true_wall"], p["e_perp"]) if np.isfinite(w) and e > OFF_LINE]


def rule28_figure(fig, sweep):
    """Fig 87 (E12): each mapped plane's distance from its wall's line, Rule 28 on and off, and the final
    position error; the edges that saw a plane off its canonical size are what Rule 28 corrects."""
    top, bottom = fig.subplots(2, 1, height_ratios=[1, 1.3])
    runs = plane_sweep(sweep)
    width = 0.8 / len(runs)
    texts = []
    for i, ((name,), folders) in enumerate(runs):
        p = plane_table(folders[0], "planes.csv", ["id", "e_perp"])
        top.bar(np.arange(len(p["id"])) + (i - (len(runs) - 1) / 2) * width, p["e_perp"], width, label=name)
        d = iterations(folders[0], ["position_error"], PLANE)
        bottom.plot(d["iteration"], d["position_error"], lw=1, label=name)
        n, total, gap = size_mismatches(folders[0])
        off = misplaced(folders[0])
        texts.append(f"{name}: " + (", ".join(f"wall {w} {e:.3g} off its line" for w, e in off) or
                                    f"every plane within {OFF_LINE:g} of its wall's line")
                     + f"; final position error {last_finite(d['position_error']):.3g}; {n} of {total} chain edges "
                       f"saw a plane more than 0.02 off its canonical size (largest {gap:.3g})")
    top.set_xticks(np.arange(len(p["id"])), [f"{i:.0f}" for i in p["id"]], fontsize=7)
    finish(top, "mapped plane (planes.csv id)", "e_perp (units)")
    finish(bottom, "iteration", POS)
    return "; ".join(texts)


# E18 (Fig 97) ---------------------------------------------------------------------------------

def collinear_run(run):
    """When the run's position error first passes 1e-6 (the pose exact until then; the map error also
    counts walls not yet seen whole), and the tied (Rule 15) key-point claims and chain edges."""
    d = iterations(run, ["map_error", "position_error", "pose_valid", "kp_wrong"], PLANE)
    bad = np.nonzero(d["position_error"] > 1e-6)[0]
    k = plane_table(run, "keypoints.csv", ["iteration", "ambiguous"])
    e = plane_table(run, "edges.csv", ["ambiguous"])
    return d, (int(d["iteration"][bad[0]]) if len(bad) else None), int(np.sum(k["ambiguous"] == 1)), \
        int(np.sum(e["ambiguous"] == 1))


def collinear_figure(fig, run):
    """Fig 97 (E18): Map D with the small frustum, the defaults (the distance test on, Rule 30 off): the
    collinear pieces tie both diagonals (Rule 15) and the distance test takes the real ends."""
    d, first_bad, ambiguous_claims, ambiguous_edges = collinear_run(run)
    axes = fig.subplots(2, 1, sharex=True)
    axes[0].plot(d["iteration"], d["map_error"], lw=1, label="map error (sum of e_ends)")
    axes[0].plot(d["iteration"], d["position_error"], lw=1, label="position error")
    axes[0].set_yscale("symlog", linthresh=1e-6)
    axes[1].plot(d["iteration"], d["pose_valid"], drawstyle="steps-post", lw=1, label="pose valid")
    axes[1].bar(d["iteration"], np.minimum(d["kp_wrong"], 1), width=1, color="red", label="a wrong key point")
    for ax in axes:
        if first_bad is not None:
            ax.axvline(first_bad, color="grey", ls=":")
    finish(axes[0], "", "units")
    finish(axes[1], "iteration", "flag")
    s = count_summary(run)
    until = "throughout" if first_bad is None else f"until iteration {first_bad}"
    valid = np.nonzero(d["pose_valid"] == 1)[0]
    return (f"pose exact (error ≤ 1e-6) {until}, last valid pose at iteration "
            f"{d['iteration'][valid[-1]] if len(valid) else float('nan'):.0f}; {ambiguous_claims} key-point claims and "
            f"{ambiguous_edges} chain edges tied both diagonals (Rule 15); {s['walls_mapped']:.0f} of "
            f"{s['walls_seen']:.0f} walls mapped, pose valid {100 * s['pose_valid_fraction']:.0f} %")


# E19 (Figs 98, 99) and E20 (Figs 101, 102) ----------------------------------------------------

E19 = ("p-e19-save-system",)
E20 = ("p-e20-pseudo-merge",)


def planes_on_map_figure(fig, sweep):
    """Fig 98 (E19): planes on the map per iteration for each save-system variant; without Rules 35 and
    36 planes vanish once the 1200-slot store wraps."""
    ax = fig.subplots()
    texts = []
    for (name,), folders in plane_sweep(sweep):
        d = iterations(folders[0], ["planes_in_map"], PLANE)
        ax.plot(d["iteration"], d["planes_in_map"], lw=1, label=name)
        s = count_summary(folders[0])
        texts.append(f"{name}: {int(d['planes_in_map'][-1])} planes at the end, {s['walls_mapped']:.0f} of "
                     f"{s['walls_seen']:.0f} walls mapped")
    finish(ax, "iteration", "planes on the map")
    return "; ".join(texts)


def shade_motion_model(ax, d, top):
    """Grey behind the iterations with an active motion model (iterations.csv mm_active), up to `top`."""
    ax.fill_between(d["iteration"], 0, top * d["mm_active"], step="post", color="grey", alpha=0.2,
                    label="motion model")


def current_group_figure(fig, sweep):
    """Fig 101 (E20): the current group per iteration with Rule 37 off and on (first seed), and where
    one-way links were added."""
    runs = dict(plane_sweep(sweep))
    axes = fig.subplots(2, 1, sharex=True)
    texts = []
    for ax, name in zip(axes, ("rule37_off", "rule37_on")):
        if (name,) not in runs:
            raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {name!r}")
        d = iterations(runs[(name,)][0], ["current_group", "oneway_links", "mm_active"], PLANE)
        ax.plot(d["iteration"], d["current_group"], drawstyle="steps-post", lw=1, label=f"current group, {name}")
        shade_motion_model(ax, d, np.nanmax(d["current_group"]))
        added = np.nonzero(d["oneway_links"] > 0)[0]
        if len(added):
            ax.plot(d["iteration"][added], d["current_group"][added], "rv", label="one-way links added")
        finish(ax, "iteration" if name == "rule37_on" else "", "group")
        texts.append(f"{name}: {int(np.nansum(d['oneway_links']))} one-way link(s)")
    off = iterations(runs[("rule37_off",)][0], ["current_group"], PLANE)["current_group"]
    on = iterations(runs[("rule37_on",)][0], ["current_group"], PLANE)["current_group"]
    n = min(len(on), len(off))
    differ = int(np.sum(~((on[:n] == off[:n]) | (np.isnan(on[:n]) & np.isnan(off[:n])))))
    return "; ".join(texts) + f"; the current group differs in {differ} iteration(s)"


# E32 ------------------------------------------------------------------------------------------

def runtime_by_size(sweep):
    """{loops: (median ms, median ms of the first and last tenth, RltPlanes at the end, iterations)}."""
    out = {}
    for (loops,), folders in plane_sweep(sweep, ("planar.loops",)):
        d = iterations(folders[0], ["runtime_ms", "rlt_planes"], PLANE)
        n = len(d["runtime_ms"])
        tenth = max(1, n // 10)
        out[int(float(loops))] = (float(np.median(d["runtime_ms"])), float(np.median(d["runtime_ms"][:tenth])),
                                  float(np.median(d["runtime_ms"][-tenth:])), int(d["rlt_planes"][-1]), n)
    return dict(sorted(out.items()))


def runtime_figure(fig, sweep):
    """E32: time per iteration over the run (moving median) for 1, 2 and 4 loops, and against the planes
    in view."""
    left, right = fig.subplots(1, 2)
    runs = plane_sweep(sweep, ("planar.loops",))
    for (loops,), folders in runs:
        d = iterations(folders[0], ["runtime_ms", "visible_planes"], PLANE)
        left.plot(d["iteration"], rp.moving_average(d["runtime_ms"], 50), lw=0.8, label=f"{loops} loop(s)")
    finish(left, "iteration", f"{MS} (50-iteration moving average)")
    (loops, folders) = runs[-1]
    d = iterations(folders[0], ["runtime_ms", "visible_planes"], PLANE)
    counts = sorted(set(d["visible_planes"].astype(int)))
    right.boxplot([d["runtime_ms"][d["visible_planes"] == c] for c in counts], labels=[str(c) for c in counts],
                  showfliers=False)
    finish(right, f"planes in view ({loops[0]} loops)", MS, legend=False)
    return "; ".join(f"{k} loop(s): median {v[0]:.3g} ms, first tenth {v[1]:.3g}, last tenth {v[2]:.3g}, "
                     f"{v[3]} RltPlanes, {v[4]} iterations" for k, v in runtime_by_size(sweep).items())


E09, E15 = ("p-e09-plane5",), ("p-e15-loop-closure-map-e",)
ISSUE13_FIGURES = [
    Figure(68, "Rule 13's four assumed-midpoint pairs of a growing and a shrinking plane, E02 (also paper Fig. 4)",
           ("p-e02-key-point-pairs",), key_point_pairs_figure),
    Figure(74, "group interval (minimum RltXPoint interval), E07", ("p-e07-interval-mode",),
           P(interval_mode_figure, mode="group")),
    Figure(75, "pair interval (minimum RltPlane interval), E07", ("p-e07-interval-mode",),
           P(interval_mode_figure, mode="pair")),
    *[Figure(n, title, ("p-e08-bad-key-points",), P(bad_key_points_figure, panel=n)) for n, title in [
        (76, "bad key points: the map error over the run and its events, E08"),
        (77, "bad key points: the largest event that heals, iteration by iteration, E08"),
        (78, "bad key points: the claims around it, right and wrong, E08"),
        (79, "bad key points: how soon map-error events and wrong key points heal, E08")]],
    Figure(80, "plane 5: length ratio per wall, Rule 21 on and off, E09", E09,
           P(per_wall_bars, column="len_ratio", ylabel="mapped length / true length")),
    Figure(81, "plane 5: the maps with Rule 21 off and on, E09", E09,
           P(variant_overlays, names=("rule21_off", "rule21_new_group"))),
    Figure(82, "too many RltXPoints: groups per Rule 21/22 variant, E10", ("p-e10-rule21-22",), too_many_groups),
    Figure(87, "size mismatch when chaining: Rule 28 on and off, E12", ("p-e12-rule28",), rule28_figure),
    Figure(90, "after the loop closes on Map E: all rules, and Rule 4's resize off, E15", E15,
           P(variant_overlays, names=("all_on", "rule4_resize_off"))),
    Figure(91, "length ratio per wall with and without Rule 19, E15", E15,
           P(per_wall_bars, column="len_ratio", ylabel="mapped length / true length")),
    Figure(92, "map error per wall with and without Rules 4 and 19, E15", E15,
           P(per_wall_bars, column="e_ends", ylabel="e_ends (units)")),
    Figure(94, "interval checks, hints and roll-back off and on (Rules 31-34), Map E, E17",
           ("p-e17-interval-check",),
           P(plane_variants, columns=("map_error", "planes_in_map", "rollbacks"),
             ylabels=("map error (units)", "planes on the map", "roll-backs"))),
    Figure(97, "collinear pieces on Map D, small frustum, Rule 15's tie decided by the distance test, E18",
           ("p-e18-collinear",),
           collinear_figure),
    Figure(98, "planes on the map per iteration, save system variants, E19", E19, planes_on_map_figure),
    Figure(99, "final maps without and with the save system (Rules 35, 36), E19", E19,
           P(variant_overlays, names=("save_off", "save_on"))),
    Figure(101, "current group per iteration, Rule 37 off and on, E20", E20, current_group_figure),
    Figure(102, "final maps with Rule 37 off and on, E20", E20, P(variant_overlays, names=("rule37_off", "rule37_on"))),
    Figure("e32-runtime", "E32: run time per iteration against the map size", ("p-e32-runtime",), runtime_figure),
]
FIGURES = sorted([f for f in FIGURES if isinstance(f.id, int)] + [f for f in ISSUE13_FIGURES if isinstance(f.id, int)],
                 key=lambda f: f.id) + [f for f in FIGURES if not isinstance(f.id, int)] + \
    [f for f in ISSUE13_FIGURES if not isinstance(f.id, int)]

# ---- issue 15 experiments: Relative Plane part 3 (spec relative_plane_em.md §6.1 E11, E13, E14, E16, E17,
# E19, E22; thesis 4.2.4, 4.3.6-4.3.7.3): the motion model (Rules 23-27, 29) and its artefacts. As above,
# claims.py calls the same helpers.

FRUSTUMS = {"small": (30.0, 7.0), "large": (35.0, 30.0)}  # spec §3.3 presets: half angle (degrees), far distance
VIEWED = {"color": "red", "lw": 3.5, "solid_capstyle": "butt", "zorder": 5}  # the part in view (Fig 69, paper Fig 5)


def first_seed(sweep):
    """The first run folder of a planar sweep (also of one without variants, over seeds only)."""
    return plane_sweep(sweep, ("seed",))[0][1][0]


def wrap_deg(angle):
    return (np.asarray(angle) + 180) % 360 - 180


def wall_lengths(run):
    w = rp.read_table(os.path.join(run, "ground_truth_walls.csv"), ["id", "length"])
    return {int(i): float(n) for i, n in zip(w["id"], w["length"])}


def mm_episodes(run):
    """Each motion model of a run (consecutive iterations with mm_active on one mm_plane), as a dict: first
    and last iteration, plane, its true wall and the wall's length, and the tracked length
    (mm_s_max − mm_s_min) at its first and last iteration."""
    d = iterations(run, ["mm_active", "mm_plane", "mm_s_min", "mm_s_max"], PLANE)
    p = plane_table(run, "planes.csv", ["id", "true_wall"])
    wall_of = {int(i): int(w) for i, w in zip(p["id"], p["true_wall"]) if np.isfinite(w)}
    lengths = wall_lengths(run)
    active = np.nonzero(d["mm_active"] == 1)[0]
    starts = [k for k in active if k == 0 or d["mm_active"][k - 1] != 1 or d["mm_plane"][k - 1] != d["mm_plane"][k]]
    out = []
    for first in starts:
        last = first
        while last + 1 < len(d["iteration"]) and d["mm_active"][last + 1] == 1 and \
                d["mm_plane"][last + 1] == d["mm_plane"][first]:
            last += 1
        plane = int(d["mm_plane"][first])
        wall = wall_of.get(plane, -1)
        out.append({"first": int(d["iteration"][first]), "last": int(d["iteration"][last]), "plane": plane,
                    "wall": wall, "true_length": lengths.get(wall, float("nan")),
                    "start_length": d["mm_s_max"][first] - d["mm_s_min"][first],
                    "length": d["mm_s_max"][last] - d["mm_s_min"][last]})
    return out


def no_motion_model(run):
    return rp.DataError(f"{os.path.join(run, PLANE, 'iterations.csv')}: column mm_active: no motion model")


def observed_wall(run, wall):
    """One wall's observations (plane_observations.csv, robot frame, the robot at the origin): {iteration,
    length in view, range of its farther end, heading (true, degrees)}."""
    o = rp.read_table(os.path.join(run, "plane_observations.csv"),
                      ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    sel = o["true_wall"] == wall
    it = o["iteration"][sel]
    path = true_path(run)
    heading = dict(zip(path["iteration"], path["psi_deg"]))
    return {"iteration": it,
            "length": np.hypot(o["kp2_x"][sel] - o["kp1_x"][sel], o["kp2_z"][sel] - o["kp1_z"][sel]),
            "range": np.maximum(np.hypot(o["kp1_x"][sel], o["kp1_z"][sel]), np.hypot(o["kp2_x"][sel], o["kp2_z"][sel])),
            "psi_deg": np.array([heading.get(i, np.nan) for i in it])}


def turn_iterations(run):
    """The iterations of the run's first turn in place: the true heading changes, the position does not."""
    path = true_path(run)
    turning = np.abs(wrap_deg(np.diff(path["psi_deg"]))) > 1e-6
    first = np.nonzero(turning)[0]
    if len(first) == 0:
        raise rp.DataError(f"{os.path.join(run, 'ground_truth_path.tum')}: the robot never turns")
    last = first[0]
    while last + 1 < len(turning) and turning[last + 1]:
        last += 1
    return path["iteration"][first[0]:last + 2]


def mapped_length(run, wall):
    """The longest mapped plane of a wall (planes.csv), NaN when none is mapped."""
    p = plane_table(run, "planes.csv", ["true_wall", "length"])
    lengths = p["length"][(p["true_wall"] == wall) & np.isfinite(p["length"])]
    return float(lengths.max()) if len(lengths) else float("nan")


def draw_view(ax, run, iteration, walls=None):
    """The robot at an iteration (true pose, a triangle looking along its heading) and what it saw then:
    each observed plane (of `walls`, else all) moved into the world by the true pose, red. Returns the
    pieces drawn as [(a, b, wall)] in the world."""
    t, psi = robot_pose(run, iteration)
    rot = planar_rotation(psi)
    pieces = [(rot @ a + t, rot @ b + t, w) for a, b, w in extracted_planes(run, iteration)
              if walls is None or w in walls]
    for i, (a, b, _) in enumerate(pieces):
        ax.plot([a[0], b[0]], [a[1], b[1]], label="in view at that iteration" if i == 0 else None, **VIEWED)
    ax.plot([t[0]], [t[1]], marker=(3, 0, np.degrees(psi) - 90), ms=12, color="black", ls="none", zorder=6,
            label=f"robot at iteration {iteration} (true pose)")
    ax.legend(fontsize=7)
    return pieces


# E11 (Figs 83-86) ------------------------------------------------------------------------------

E11 = ("p-e11-first-corner",)


def first_corner(run):
    """The first motion model of an E1 run against the truth: its episode, how far the robot was from the
    turn when it started (units of path), and the true heading when it ended."""
    episodes = mm_episodes(run)
    if not episodes:
        raise no_motion_model(run)
    e = episodes[0]
    path = true_path(run)
    turn = turn_iterations(run)
    at = {int(i): k for k, i in enumerate(path["iteration"])}
    k0, k1 = at[e["first"]], at[int(turn[0])]
    before = float(np.sum(np.hypot(np.diff(path["x"][k0:k1 + 1]), np.diff(path["z"][k0:k1 + 1]))))
    return e, before, float(path["psi_deg"][at[e["last"]]] - path["psi_deg"][k1])


def key_points_by_phase(run):
    """(wrong, checked) key-point claims inside and outside the motion models: {"in": (...), "out": (...)}."""
    d = iterations(run, ["kp_checked", "kp_wrong", "mm_active"], PLANE)
    mm = d["mm_active"] == 1
    return {"in": (int(np.sum(d["kp_wrong"][mm])), int(np.sum(d["kp_checked"][mm]))),
            "out": (int(np.sum(d["kp_wrong"][~mm])), int(np.sum(d["kp_checked"][~mm])))}


def first_corner_map(fig, sweep):
    """Fig 83 (E11): Map E1's final map, the true and estimated paths, the motion model's poses red."""
    run = first_seed(sweep)
    ax = fig.subplots()
    plane_overlay(ax, run)
    est = planar_track(os.path.join(run, PLANE, "trajectory.tum"))
    d = iterations(run, ["mm_active"], PLANE)
    mm = np.isin(est["iteration"], d["iteration"][d["mm_active"] == 1])
    ax.plot(est["x"][mm], est["z"][mm], ".", color="red", ms=3, zorder=4, label="estimated poses, motion model")
    ax.legend(fontsize=8)
    e, before, heading = first_corner(run)
    s = count_summary(run)
    return (f"seed 1: the motion model tracks plane {e['plane']} (wall {e['wall']}) from iteration {e['first']}, "
            f"{before:.2g} units before the turn, to {e['last']}, {heading:.0f}° into it; {s['walls_mapped']:.0f} of "
            f"{s['walls_seen']:.0f} seen walls mapped, final mean map error {s['final_mean_map_error']:.3g} per plane "
            f"(e_ends counts the parts of the long walls never seen)")


def mm_pose_track(fig, sweep):
    """Fig 84 (E11): the pose through the corner: position error, and the estimated against the true
    heading (the motion model's own heading in its frame as dots), the motion model shaded."""
    run = first_seed(sweep)
    d = iterations(run, ["position_error", "mm_active", "mm_heading_deg"], PLANE)
    truth, est = true_path(run), planar_track(os.path.join(run, PLANE, "trajectory.tum"))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(d["iteration"], d["position_error"], lw=1, label="position error")
    shade_motion_model(top, d, np.nanmax(d["position_error"]))
    finish(top, "", POS)
    bottom.plot(truth["iteration"], truth["psi_deg"], lw=2.5, color="orange", label="true heading")
    bottom.plot(est["iteration"], est["psi_deg"], lw=1, color="tab:blue", label="estimated heading")
    bottom.plot(d["iteration"], d["mm_heading_deg"], ".", ms=2, color="red", label="motion model frame heading")
    shade_motion_model(bottom, d, np.nanmax(truth["psi_deg"]))
    finish(bottom, "iteration", "heading ψ (degrees)")
    mm = d["mm_active"] == 1
    return (f"seed 1: position error inside the motion model mean {np.nanmean(d['position_error'][mm]):.3g}, max "
            f"{np.nanmax(d['position_error'][mm]):.3g}; outside mean {np.nanmean(d['position_error'][~mm]):.3g}, "
            f"max {np.nanmax(d['position_error'][~mm]):.3g}")


def mm_growth(fig, sweep):
    """Fig 85 (E11): the motion model's track: its distance to the wall, and the wall's tracked length
    (mm_s_max − mm_s_min) beside the length in view, against the iteration."""
    run = first_seed(sweep)
    e, _, _ = first_corner(run)
    d = iterations(run, ["mm_distance", "mm_s_min", "mm_s_max", "mm_active"], PLANE)
    seen = observed_wall(run, e["wall"])
    lo, hi = e["first"] - 30, e["last"] + 30
    window = (d["iteration"] >= lo) & (d["iteration"] <= hi)
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(d["iteration"][window], d["mm_distance"][window], lw=1.2, label="D: distance to the wall (mm_distance)")
    finish(top, "", "units")
    bottom.plot(d["iteration"][window], (d["mm_s_max"] - d["mm_s_min"])[window], lw=2, label="tracked length")
    w = (seen["iteration"] >= lo) & (seen["iteration"] <= hi)
    bottom.plot(seen["iteration"][w], seen["length"][w], lw=1, label=f"length in view of wall {e['wall']}")
    bottom.axhline(e["true_length"], color="black", ls="--", lw=0.8, label=f"true length {e['true_length']:.3g}")
    shade_motion_model(bottom, {k: v[window] for k, v in d.items()}, e["true_length"])
    finish(bottom, "iteration", "units")
    return (f"seed 1: wall {e['wall']} tracked from {e['start_length']:.3g} (its mapped length at the start) to "
            f"{e['length']:.3g} at the end, {e['length'] / e['true_length']:.3f} of its true {e['true_length']:.3g}; "
            f"longest in view {np.max(seen['length'][w]):.3g}")


def mm_key_points(fig, sweep):
    """Fig 86 (E11): key-point claims per iteration, right and wrong against the truth, and the map error
    with its events (a jump of at least EVENT_JUMP), the motion model shaded."""
    run = first_seed(sweep)
    d = iterations(run, ["map_error", "kp_checked", "kp_wrong", "mm_active"], PLANE)
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(d["iteration"], d["map_error"], lw=1, label="map error (sum of e_ends)")
    events = map_error_events(run)
    at = {int(i): k for k, i in enumerate(d["iteration"])}
    top.plot([e[0] for e in events], [d["map_error"][at[e[0]]] for e in events], "rv",
             label=f"events (a jump of ≥ {EVENT_JUMP:g})")
    shade_motion_model(top, d, np.nanmax(d["map_error"]))
    finish(top, "", "map error (units)")
    bottom.bar(d["iteration"], d["kp_checked"], width=1, color="lightgrey", label="key points claimed")
    bottom.bar(d["iteration"], d["kp_wrong"], width=1, color="red", label="wrong (not a real wall end)")
    shade_motion_model(bottom, d, np.nanmax(d["kp_checked"]))
    finish(bottom, "iteration", "claims")
    split = key_points_by_phase(run)
    n, quick, never, _ = event_healing(run)
    return (f"seed 1: wrong key-point claims {split['in'][0]} of {split['in'][1]} inside the motion model, "
            f"{split['out'][0]} of {split['out'][1]} outside; {n} map-error events ({quick} healed within "
            f"{HEAL_ITERATIONS} iterations, {never} never), {sum(e[3] for e in events)} of them a new plane joining "
            f"the map")


# E13 (Fig 88) ---------------------------------------------------------------------------------

def grown_lengths(sweep):
    """{variant: (tracked length / true length at each motion model's end, the grown planes' mapped
    len_ratio, seeds)} over every seed of a planar sweep."""
    out = {}
    for (name,), folders in plane_sweep(sweep):
        tracked, mapped = [], []
        for folder in folders:
            p = plane_table(folder, "planes.csv", ["id", "len_ratio"])
            ratio = {int(i): r for i, r in zip(p["id"], p["len_ratio"])}
            for e in mm_episodes(folder):
                tracked.append(e["length"] / e["true_length"])
                mapped.append(ratio.get(e["plane"], float("nan")))
        out[name] = (np.array(tracked), np.array(mapped), len(folders))
    return out


GROWN_TOP = 1.04  # Fig 88's y axis ends here ("a little past its true size"); ratios beyond are written


def grow_threshold_figure(fig, sweep):
    """Fig 88 (E13): per growth threshold, each motion model's tracked length at its end over the wall's
    true length, and the mapped length ratio of the planes it grew (every seed)."""
    stats = grown_lengths(sweep)
    axes = fig.subplots(1, 2, sharey=True)
    for ax, index, ylabel in zip(axes, (0, 1), ("tracked length at the motion model's end / true length",
                                                 "grown plane's mapped length / true length (planes.csv)")):
        for i, (name, values) in enumerate(stats.items()):
            v = values[index][np.isfinite(values[index])]
            x = i + np.linspace(-0.2, 0.2, len(v))
            ax.plot(x, np.minimum(v, GROWN_TOP), "o", ms=4, alpha=0.7, color=f"C{i}")
            ax.plot([i - 0.3, i + 0.3], [np.median(v)] * 2, color="black", lw=1.5)
            over = v[v > GROWN_TOP]  # far past the true size: drawn at the top, their values written
            if len(over):
                ax.annotate(", ".join(f"{r:.3g}" for r in over), (i, GROWN_TOP), xytext=(0, -12), ha="center",
                            textcoords="offset points", fontsize=7)
        ax.axhline(1, color="grey", lw=0.8, ls="--")
        ax.set_xticks(range(len(stats)), list(stats), fontsize=8)
        finish(ax, "relative_plane.motion_model.grow_threshold", ylabel, legend=False)
    return "; ".join(grown_text(name, v) for name, v in stats.items())


def grown_text(name, values):
    tracked, mapped, seeds = values
    over = tracked[tracked > 1.001]
    return (f"{name}: {len(tracked)} motion models over {seeds} seed(s), tracked length / true median "
            f"{np.nanmedian(tracked):.4f}, max {np.nanmax(tracked):.4f}, {len(over)} past the true size by over "
            f"0.1 %; grown planes' mapped len_ratio median {np.nanmedian(mapped):.4f}, max {np.nanmax(mapped):.4f}")


# E14 (Fig 89) ---------------------------------------------------------------------------------

def run_frustum(run):
    """(frustum preset, shape) of a planar run from its manifest's scenario."""
    path = os.path.join(run, "manifest.json")
    try:
        planar = read_json(path)["scenario"]["planar"]
        return planar["frustum"], planar["frustum_shape"]
    except (KeyError, TypeError):
        raise rp.DataError(f"{path}: no scenario.planar.frustum / frustum_shape") from None


def end_wall_turn(run):
    """The wall seen in most iterations of the first turn (the corner's end wall), its observations in
    the turn, and its mapped length."""
    turn = turn_iterations(run)
    o = rp.read_table(os.path.join(run, "plane_observations.csv"), ["iteration", "true_wall"])
    walls, counts = np.unique(o["true_wall"][np.isin(o["iteration"], turn)], return_counts=True)
    if len(walls) == 0:
        raise rp.DataError(f"{os.path.join(run, 'plane_observations.csv')}: no wall seen in the turn")
    wall = int(walls[np.argmax(counts)])
    seen = observed_wall(run, wall)
    sel = np.isin(seen["iteration"], turn)
    return wall, {k: v[sel] for k, v in seen.items()}, mapped_length(run, wall)


def frustum_turns(sweep):
    """{variant: (frustum, shape, wall, observations in the turn, mapped length, true length)}."""
    out = {}
    for (name,), folders in plane_sweep(sweep):
        wall, seen, mapped = end_wall_turn(folders[0])
        out[name] = (*run_frustum(folders[0]), wall, seen, mapped, wall_lengths(folders[0])[wall])
    return out


def frustum_figure(fig, sweep):
    """Fig 89 (E14): the end wall's length in view and the range of its farther end against the heading
    through the turn, per frustum shape and size; its mapped length dashed; the far distance f and the
    trapezoid's corner reach f / cos α dotted."""
    turns = frustum_turns(sweep)
    left, right = fig.subplots(1, 2)
    texts = []
    for i, (name, (frustum, shape, wall, seen, mapped, true)) in enumerate(turns.items()):
        style = {"color": f"C{i}", "ls": "-" if shape == "planar" else "--"}
        left.plot(seen["psi_deg"], seen["length"], lw=1.2, label=f"{name}: wall {wall} in view", **style)
        left.axhline(mapped, lw=0.8, alpha=0.7, color=f"C{i}", ls=":")
        right.plot(seen["psi_deg"], seen["range"], lw=1.2, label=name, **style)
        k = int(np.argmax(seen["length"]))
        texts.append(f"{name}: in view up to {seen['length'][k]:.3g} at ψ {seen['psi_deg'][k]:.0f}°, "
                     f"{seen['length'][-1]:.3g} at the turn's end; farthest end {np.max(seen['range']):.3g} away; "
                     f"mapped {mapped:.3g} of {true:.3g}")
    for frustum in sorted({v[0] for v in turns.values()} & set(FRUSTUMS)):
        alpha, far = FRUSTUMS[frustum]
        if far < np.nanmax([np.max(v[3]["range"]) for v in turns.values()]) * 1.5:
            right.axhline(far, color="black", lw=0.8, ls=":", label=f"{frustum}: f = {far:g}")
            right.axhline(far / np.cos(np.radians(alpha)), color="grey", lw=0.8, ls=":",
                          label=f"{frustum}: f / cos α = {far / np.cos(np.radians(alpha)):.3g}")
    finish(left, "true heading ψ (degrees)", "length in view (units; dotted: mapped length)")
    finish(right, "true heading ψ (degrees)", "range of the farther end (units)")
    return "; ".join(texts)


# E16 (Fig 93) ---------------------------------------------------------------------------------

def motion_model_exits(run):
    """(motion models, how many ended in a group created before they started, groups at the end)."""
    d = iterations(run, ["current_group"], PLANE)
    g = plane_table(run, "groups.csv", ["group_id", "created_iter"])
    created = dict(zip(g["group_id"].astype(int), g["created_iter"]))
    episodes = mm_episodes(run)
    back = 0
    for e in episodes:
        after = np.nonzero((d["iteration"] > e["last"]) & np.isfinite(d["current_group"]))[0]
        back += len(after) > 0 and created.get(int(d["current_group"][after[0]]), e["first"]) < e["first"]
    return len(episodes), back, len(g["group_id"])


# E22 (Fig 69, paper Fig 5) and E19 (Fig 100) ----------------------------------------------------

E22 = ("p-e22-one-partial-plane",)


def one_plane_iteration(run):
    """The middle iteration of the first stretch of the last loop in which the motion model is active
    and a single plane is in view."""
    loops, n = run_loops(run)
    d = iterations(run, ["mm_active", "visible_planes"], PLANE)
    sel = np.nonzero((d["iteration"] >= n * (loops - 1) / max(loops, 1)) & (d["mm_active"] == 1)
                     & (d["visible_planes"] == 1))[0]
    if len(sel) == 0:
        raise rp.DataError(f"{os.path.join(run, PLANE, 'iterations.csv')}: no motion model with one plane in view "
                           f"on the last loop")
    stretch = sel[:np.argmax(np.diff(np.append(sel, sel[-1] + 2)) > 1) + 1]
    return int(d["iteration"][stretch[len(stretch) // 2]]), int(d["iteration"][stretch[0]]), \
        int(d["iteration"][stretch[-1]])


def one_partial_plane(fig, run):
    """Fig 69 / paper Fig 5 (E22): the map, the robot at a corner of its last loop with the motion model
    active, and the part of the single wall in its view, red."""
    k, first, last = one_plane_iteration(run)
    ax = fig.subplots()
    plane_overlay(ax, run)
    pieces = draw_view(ax, run, k)
    d = iterations(run, ["position_error", "mm_active", "visible_planes"], PLANE)
    row = int(np.nonzero(d["iteration"] == k)[0][0])
    lengths = wall_lengths(run)
    return (f"iteration {k} (of the stretch {first}-{last} on the last loop): motion model "
            f"{'on' if d['mm_active'][row] == 1 else 'off'}, {d['visible_planes'][row]:.0f} plane in view: "
            + ", ".join(f"wall {w}, {np.linalg.norm(b - a):.3g} of its {lengths[w]:.3g} units" for a, b, w in pieces)
            + f"; position error {d['position_error'][row]:.3g}")


def first_seen_far(run):
    """The wall first seen from farthest away: (wall, iteration, distance of its nearer observed end)."""
    o = rp.read_table(os.path.join(run, "plane_observations.csv"),
                      ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    best = None
    for wall in sorted(set(o["true_wall"]) - {-1}):
        k = int(np.nonzero(o["true_wall"] == wall)[0][0])
        near = min(np.hypot(o["kp1_x"][k], o["kp1_z"][k]), np.hypot(o["kp2_x"][k], o["kp2_z"][k]))
        if best is None or near > best[2]:
            best = (int(wall), int(o["iteration"][k]), float(near))
    if best is None:
        raise rp.DataError(f"{os.path.join(run, 'plane_observations.csv')}: no wall seen")
    return best


def first_seen_figure(fig, sweep, name):
    """Fig 100 (E19): the wall first seen from farthest away, red, from where the robot first saw it (the
    large frustum, no occlusion), over variant `name`'s final map."""
    run = variant_folder_of(sweep, name)
    wall, k, near = first_seen_far(run)
    ax = fig.subplots()
    plane_overlay(ax, run, title=f"{name}: the final map; wall {wall} as first seen")
    draw_view(ax, run, k, walls={wall})
    on_map = np.isfinite(mapped_length(run, wall))
    return (f"{name}: wall {wall} is first seen at iteration {k}, its nearer end {near:.3g} units away; "
            f"{'on' if on_map else 'not on'} the final map")


E16, E17 = ("p-e16-rule29",), ("p-e17-interval-check",)
ISSUE15_FIGURES = [
    Figure(69, "only one partial plane in view on the second loop, E22 (also paper Fig. 5)", E22, one_partial_plane),
    Figure(83, "the first motion-model test: Map E1 FirstCorner, E11", E11, first_corner_map),
    Figure(84, "the pose through the corner, motion model shaded, E11", E11, mm_pose_track),
    Figure(85, "the motion model's track and the end wall's growth, E11", E11, mm_growth),
    Figure(86, "key-point claims and map-error events through the corner, E11", E11, mm_key_points),
    Figure(88, "growth threshold 0 (thesis), 0.02 and 0.05: the grown planes' lengths, E13",
           ("p-e13-grow-threshold",), grow_threshold_figure),
    Figure(89, "frustum failure: the end wall in view while turning, planar vs radial frustum, E14",
           ("p-e14-frustum-shape",), frustum_figure),
    Figure(93, "finished motion-model runs of Map E with Rule 29 on and off, E16", E16,
           P(variant_overlays, names=("rule29_on", "rule29_off"), groups=True)),
    Figure(95, "the start group with the interval checks off, E17", E17,
           P(variant_overlays, names=("interval_check_off",), groups=True)),
    Figure(96, "the start group with the interval checks, hints and roll-back on, E17", E17,
           P(variant_overlays, names=("interval_check_on",), groups=True)),
    Figure(100, "a wall first seen from far away (large frustum, no occlusion), E19", E19,
           P(first_seen_figure, name="save_off")),
]
FIGURES = sorted([f for f in FIGURES + ISSUE15_FIGURES if isinstance(f.id, int)], key=lambda f: f.id) + \
    [f for f in FIGURES + ISSUE15_FIGURES if not isinstance(f.id, int)]

# ---- issue 14 Chapter 5: points -> EM -> Relative Plane (spec relative_plane_em.md §6.1 E23-E30) --

EXTRACTED = {"color": "red", "lw": 1.8, "zorder": 4}  # the thesis draws current readings red
POINTS = {"s": 2, "color": "dimgrey", "alpha": 0.5, "linewidths": 0, "zorder": 2}
EXTRACTORS = ("em2", "em1", "ransac_open3d")
REAL_TIME_MS = 1000 / 30  # paper §III: 30 iterations a second including EM


def point_frame(run, iteration=None):
    """(iteration, points (n x 3, robot frame), true wall ids) of point_frames.csv (output.point_frames):
    the given iteration, else the last one written."""
    path = os.path.join(run, "point_frames.csv")
    t = rp.read_table(path, ["iteration", "x", "y", "z", "true_wall"])
    if len(t["iteration"]) == 0:
        raise rp.DataError(f"{path}: no rows")
    k = t["iteration"].max() if iteration is None else iteration
    sel = t["iteration"] == k
    if not sel.any():
        raise rp.DataError(f"{path}: column iteration: no iteration {k:.0f}")
    return int(k), np.column_stack([t["x"][sel], t["y"][sel], t["z"][sel]]), t["true_wall"][sel].astype(int)


def extracted_planes(run, iteration):
    """The extracted planes of one iteration (plane_observations.csv: the extractor's output, robot
    frame) as [(a, b, true wall)]."""
    o = rp.read_table(os.path.join(run, "plane_observations.csv"),
                      ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    sel = np.nonzero(o["iteration"] == iteration)[0]
    return [(np.array([o["kp1_x"][k], o["kp1_z"][k]]), np.array([o["kp2_x"][k], o["kp2_z"][k]]), int(o["true_wall"][k]))
            for k in sel]


def robot_pose(run, iteration):
    """(translation (x, z), heading rad) of the true pose at an iteration."""
    path = true_path(run)
    rows = np.nonzero(path["iteration"] == iteration)[0]
    if len(rows) == 0:
        raise rp.DataError(f"{os.path.join(run, 'ground_truth_path.tum')}: no iteration {iteration}")
    return np.array([path["x"][rows[0]], path["z"][rows[0]]]), np.radians(path["psi_deg"][rows[0]])


def visible_pieces(run, iteration, points, ids):
    """{wall id: (a, b)} in the robot frame: each true wall cut to the span of its points seen at the
    iteration (the "planes viewed by the robot at the time", thesis 5.2)."""
    t, psi = robot_pose(run, iteration)
    w = true_walls(run)
    rot = planar_rotation(-psi)
    out = {}
    for wid in sorted(set(ids) - {-1}):
        row = list(w["id"]).index(wid)
        a = rot @ (np.array([w["a_x"][row], w["a_z"][row]]) - t)
        b = rot @ (np.array([w["b_x"][row], w["b_z"][row]]) - t)
        u = (b - a) / np.linalg.norm(b - a)
        s = (points[ids == wid][:, [0, 2]] - a) @ u
        out[wid] = (a + s.min() * u, a + s.max() * u)
    return out


def em_frame_score(run, iteration):
    """em_frames.csv's row of an iteration as {column: value}."""
    names = ["iteration", "n_points", "n_planes", "n_true_visible", "recall", "precision"]
    t = rp.read_table(os.path.join(run, "em_frames.csv"), names)
    sel = np.nonzero(t["iteration"] == iteration)[0]
    if len(sel) == 0:
        raise rp.DataError(f"{os.path.join(run, 'em_frames.csv')}: column iteration: no iteration {iteration}")
    return {c: t[c][sel[0]] for c in names}


def draw_robot(ax):
    ax.plot([0], [0], marker=(3, 0, -90), ms=10, color="black", ls="none", label="robot (looking along +x)",
            zorder=5)


def frame_points(ax, points, title):
    ax.scatter(points[:, 0], points[:, 2], label=f"{len(points)} points (x, z)", **POINTS)
    draw_robot(ax)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x, robot frame (units)", "z, robot frame (units)")
    ax.set_title(title, fontsize=9)


def em_planes_vs_visible(ax, run, iteration, points, ids, title):
    """EM planes (red) over the visible wall pieces (yellow) and the points, robot frame."""
    for i, (a, b) in enumerate(visible_pieces(run, iteration, points, ids).values()):
        ax.plot([a[0], b[0]], [a[1], b[1]], label="visible wall pieces" if i == 0 else None, **WALL)
    planes = extracted_planes(run, iteration)
    for i, (a, b, _) in enumerate(planes):
        ax.plot([a[0], b[0]], [a[1], b[1]], label=f"extracted planes ({len(planes)})" if i == 0 else None, **EXTRACTED)
    ax.scatter(points[:, 0], points[:, 2], **{**POINTS, "alpha": 0.25})
    draw_robot(ax)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x, robot frame (units)", "z, robot frame (units)")
    ax.set_title(title, fontsize=9)


def number_planes(ax, run):
    p = plane_table(run, "planes.csv", ["id", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    for i, ax_, az, bx, bz in zip(p["id"], p["kp1_x"], p["kp1_z"], p["kp2_x"], p["kp2_z"]):
        if np.isfinite([ax_, az, bx, bz]).all():
            ax.annotate(f"{i:.0f}", ((ax_ + bx) / 2, (az + bz) / 2), fontsize=6, color="blue", zorder=5)


def em_views(fig, run):
    """Figs 105-108, paper Fig 6: the thesis's four windows (5.2) at the last written point frame:
    true walls vs the generated map; the points in view; the extracted planes vs the wall pieces in
    view; the Relative Plane map with its groups and plane numbers."""
    k, points, ids = point_frame(run)
    axes = fig.subplots(2, 2)
    plane_overlay(axes[0, 0], run, title="true walls (yellow) and the generated map (blue), end of run")
    frame_points(axes[0, 1], points, f"points in view at iteration {k}")
    score = em_frame_score(run, k)
    em_planes_vs_visible(axes[1, 0], run, k, points, ids,
                         f"extracted planes vs the walls in view, iteration {k}: recall {score['recall']:.3g}, "
                         f"precision {score['precision']:.3g}")
    plane_overlay(axes[1, 1], run, groups=True, title="the Relative Plane map: groups (X) and plane numbers")
    number_planes(axes[1, 1], run)
    for ax in axes.flat:
        if ax.get_legend():
            ax.get_legend().remove()
    axes[0, 0].legend(fontsize=6, loc="best")
    axes[1, 0].legend(fontsize=6, loc="best")
    s = count_summary(run)
    frames = rp.read_table(os.path.join(run, "em_frames.csv"), ["recall", "precision"])
    return (f"{s['walls_mapped']:.0f} of {s['walls_seen']:.0f} seen walls mapped, {s['duplicates']:.0f} duplicates, "
            f"final mean map error {s['final_mean_map_error']:.3g} per plane, pose valid in "
            f"{100 * s['pose_valid_fraction']:.0f} % of iterations; extraction over the run: recall "
            f"{np.mean(frames['recall']):.4f}, precision {np.mean(frames['precision']):.4f} (frame means); "
            f"iteration {k}: {len(points)} points, {score['n_planes']:.0f} planes for {score['n_true_visible']:.0f} "
            f"visible wall pieces")


def points_and_em(fig, run):
    """Fig 46: the simulated points of one frame and the planes EM made of them."""
    k, points, ids = point_frame(run)
    left, right = fig.subplots(1, 2)
    frame_points(left, points, f"the point sensor's points, iteration {k}")
    score = em_frame_score(run, k)
    em_planes_vs_visible(right, run, k, points, ids, f"EM's planes (red), iteration {k}")
    right.legend(fontsize=7)
    return (f"iteration {k}: {len(points)} points, {score['n_planes']:.0f} planes for {score['n_true_visible']:.0f} "
            f"visible wall pieces (recall {score['recall']:.3g}, precision {score['precision']:.3g})")


def bench_scores(run):
    return rp.read_table(os.path.join(run, "bench.csv"), ["scene", "variant", "extractor", "seed", "recall",
                                                           "precision", "n_planes", "noise", "ms"],
                         text=("scene", "variant", "extractor"))


def bench_picture(ax, run, scene, variant, seed, extractor, truth_only=False):
    """One bench case: points grey, true walls yellow, the extractor's planes red (robot at the origin)."""
    pts = rp.read_table(os.path.join(run, "bench_points.csv"), ["scene", "variant", "seed", "x", "z"],
                        text=("scene", "variant"))
    sel = (pts["scene"] == scene) & (pts["variant"] == variant) & (pts["seed"] == seed)
    ax.scatter(pts["x"][sel], pts["z"][sel], label=f"{sel.sum()} points", **POINTS)
    planes = rp.read_table(os.path.join(run, "bench_planes.csv"),
                           ["scene", "variant", "seed", "source", "a_x", "a_z", "b_x", "b_z"],
                           text=("scene", "variant", "source"))
    case = (planes["scene"] == scene) & (planes["variant"] == variant) & (planes["seed"] == seed)
    for source, style, label in [("truth", WALL, "true walls")] + ([] if truth_only else [(extractor, EXTRACTED,
                                                                                          f"{extractor} planes")]):
        rows = np.nonzero(case & (planes["source"] == source))[0]
        for i, k in enumerate(rows):
            ax.plot([planes["a_x"][k], planes["b_x"][k]], [planes["a_z"][k], planes["b_z"][k]],
                    label=f"{label} ({len(rows)})" if i == 0 else None, **style)
    draw_robot(ax)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (units)", "z (units)")
    ax.legend(fontsize=7)


def bench_case(fig, run, scene, variant, extractor, truth_only=False):
    """Figs 55-61 (E30): one test-bench case drawn for the seed where `extractor` did worst (recall +
    precision; the first such seed), beside every variant of the scene: mean recall and precision
    over the seeds per extractor."""
    t = bench_scores(run)
    rows = np.nonzero((t["scene"] == scene) & (t["variant"] == variant) & (t["extractor"] == extractor))[0]
    if len(rows) == 0:
        raise rp.DataError(f"{os.path.join(run, 'bench.csv')}: no rows for {scene} {variant} {extractor}")
    worst = rows[np.argmin(t["recall"][rows] + t["precision"][rows])]
    seed = t["seed"][worst]
    left, right = fig.subplots(1, 2, width_ratios=[1.2, 1])
    bench_picture(left, run, scene, variant, seed, extractor, truth_only)
    what = "true walls and points" if truth_only else (f"{extractor}: recall {t['recall'][worst]:.3g}, precision "
                                                       f"{t['precision'][worst]:.3g}")
    left.set_title(f"{scene}, {variant}, seed {seed:.0f} — {what}", fontsize=9)
    variants = list(dict.fromkeys(t["variant"][t["scene"] == scene]))
    x = np.arange(len(variants))
    shows = []
    for j, name in enumerate(e for e in EXTRACTORS if (t["extractor"] == e).any()):
        recall = [t["recall"][(t["scene"] == scene) & (t["variant"] == v) & (t["extractor"] == name)].mean()
                  for v in variants]
        precision = [t["precision"][(t["scene"] == scene) & (t["variant"] == v) & (t["extractor"] == name)].mean()
                     for v in variants]
        right.plot(x + 0.08 * (j - 1), recall, "o-", color=f"C{j}", label=f"{name} recall")
        right.plot(x + 0.08 * (j - 1), precision, "s--", color=f"C{j}", mfc="none", label=f"{name} precision")
        shows.append(f"{name} " + ", ".join(f"{v} {r:.2g}/{p:.2g}" for v, r, p in zip(variants, recall, precision)))
    right.set_xticks(x, variants, rotation=20, fontsize=7)
    right.set_ylim(-0.05, 1.05)
    seeds = len(set(t["seed"]))
    finish(right, "", f"mean over {seeds} seeds")
    right.set_title(f"{scene}: every variant", fontsize=9)
    return f"mean recall/precision over {seeds} seeds — " + "; ".join(shows)


def sweep_cell(sweep, variant):
    """The run folder of one variant of a planar sweep (its first seed)."""
    for value, folder in sweep_runs(sweep, "variant", PLANE):
        if value == variant:
            return folder
    raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {variant}")


def demo_views(fig, sweep, variant):
    """Paper Fig 6: the four windows of one E27 cell."""
    return em_views(fig, sweep_cell(sweep, variant))


def demo_maps(fig, sweep, variants):
    """Paper Figs 7, 8 (E27): the final maps of the demo's cells, side by side."""
    axes = np.atleast_1d(fig.subplots(1, len(variants)))
    shows = []
    for ax, variant in zip(axes, variants):
        run = sweep_cell(sweep, variant)
        plane_overlay(ax, run, title=variant)
        ax.legend(fontsize=6)
        s = count_summary(run)
        shows.append(f"{variant}: {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls mapped, "
                     f"{s['duplicates']:.0f} duplicates, final mean map error {s['final_mean_map_error']:.3g}, "
                     f"pose valid {100 * s['pose_valid_fraction']:.0f} %")
    return "; ".join(shows)


def demo_times(sweep):
    """{variant: (EM ms per iteration, Relative Plane ms per iteration)} of the E27 sweep."""
    out = {}
    for variant, folder in sweep_runs(sweep, "variant", PLANE):
        d = iterations(folder, ["t_extract_ms", "runtime_ms"], PLANE)
        out[variant] = (d["t_extract_ms"], d["runtime_ms"])
    return out


def demo_timing(fig, sweep):
    """Extra (E27): ms per iteration of EM and of Relative Plane, median and 95th percentile per cell,
    against the paper's 30 iterations a second."""
    times = demo_times(sweep)
    ax = fig.subplots()
    x = np.arange(len(times))
    shows = []
    for j, (name, index) in enumerate([("EM (t_extract_ms)", 0), ("Relative Plane (runtime_ms)", 1),
                                       ("EM + Relative Plane", None)]):
        values = [v[index] if index is not None else v[0] + v[1] for v in times.values()]
        med = [np.median(v) for v in values]
        p95 = [np.percentile(v, 95) for v in values]
        bars = ax.bar(x + (j - 1) * 0.27, med, 0.27, color=f"C{j}", label=f"{name}: median")
        ax.bar_label(bars, fmt="%.3g", fontsize=7)
        ax.plot(x + (j - 1) * 0.27, p95, "v", color="black", ms=5, label="95th percentile" if j == 0 else None)
        if index is None:
            shows = [f"{v}: EM + RP median {m:.3g} ms, p95 {p:.3g} ms, max {np.max(w):.3g} ms ({1000 / m:.0f} it/s)"
                     for v, m, p, w in zip(times, med, p95, values)]
    ax.axhline(REAL_TIME_MS, color="red", ls="--", lw=1, label="paper: 30 iterations/s (33.3 ms) on an AMD 64 3400+")
    ax.set_xticks(x, list(times))
    ax.set_yscale("log")
    finish(ax, "E27 cell", "ms per iteration (simulator excluded)")
    return "; ".join(shows)


def compare_frames(run):
    """em_compare.csv's ms and scores per extractor present: {extractor: {column: values}}."""
    path = os.path.join(run, "em_compare.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    present = [e for e in EXTRACTORS if f"ms_{e}" in header]
    if not present:
        raise rp.DataError(f"{path}: no ms_<extractor> column")
    names = [f"{c}_{e}" for e in present for c in ("ms", "recall", "precision", "n_planes", "mean_normal_err_deg")]
    t = rp.read_table(path, ["iteration", *names])
    return t["iteration"], {e: {c: t[f"{c}_{e}"] for c in ("ms", "recall", "precision", "n_planes",
                                                            "mean_normal_err_deg")} for e in present}


def em_compare(fig, *runs, labels):
    """Extra (E29): ms per frame of each extractor on identical frames, one panel per map."""
    axes = np.atleast_1d(fig.subplots(1, len(runs), sharey=True))
    shows = []
    for ax, run, label in zip(axes, runs, labels):
        it, by = compare_frames(run)
        for j, (e, d) in enumerate(by.items()):
            ax.plot(it, rp.moving_average(d["ms"], SMOOTH), color=f"C{j}", lw=1,
                    label=f"{e}: median {np.median(d['ms']):.3g} ms, recall {np.mean(d['recall']):.4f}, "
                          f"precision {np.mean(d['precision']):.4f}")
        ax.set_yscale("log")
        finish(ax, "iteration", f"ms per frame ({SMOOTH}-frame moving average)")
        ax.set_title(f"{label}, {len(it)} frames", fontsize=9)
        ratio = np.median(by["em1"]["ms"]) / np.median(by["em2"]["ms"]) if {"em1", "em2"} <= set(by) else float("nan")
        shows.append(f"{label}: " + ", ".join(f"{e} median {np.median(d['ms']):.3g} ms" for e, d in by.items())
                     + f" (EM1/EM2 {ratio:.2f})")
    return "; ".join(shows)


def w_ma_figure(fig, *sweeps, labels):
    """Extra (E23 w_ma): the map error per iteration of each moving-average window, one panel per sweep
    (Map D without and with point noise)."""
    axes = np.atleast_1d(fig.subplots(len(sweeps), 1, sharex=True))
    shows = []
    for ax, sweep, label in zip(axes, sweeps, labels):
        series = sweep_series(sweep, ["mean_map_error"], algorithm=PLANE)
        cells = []
        for name, d in series.items():
            s = count_summary(variant_folder_of(sweep, name))
            ax.plot(d["iteration"], d["mean_map_error"], lw=1, label=f"{name}: final {s['final_mean_map_error']:.3g}, "
                    f"{s['walls_mapped']:.0f}/{s['walls_seen']:.0f} walls, pose valid "
                    f"{100 * s['pose_valid_fraction']:.0f} %")
            cells.append(f"{name} final mean map error {s['final_mean_map_error']:.3g}, {s['walls_mapped']:.0f} of "
                         f"{s['walls_seen']:.0f} walls, pose valid {100 * s['pose_valid_fraction']:.0f} %")
        ax.set_yscale("log")
        finish(ax, "iteration" if ax is axes[-1] else "", MAP_ERROR)
        ax.set_title(label, fontsize=9)
        shows.append(f"{label}: " + ", ".join(cells))
    return "; ".join(shows)


def noise_sweep_figure(fig, sweep):
    """Extra (E28): extraction and map against the point noise σ_pt, from the sweep's noise_sweep.csv
    (scripts/plot/noise_sweep.py): recall, precision and normal error of EM; map error, walls mapped
    and the pose-valid share of the Relative Plane map."""
    t = noise_sweep.read(sweep)
    sigma = t["point_sigma"]
    (em, normal), (err, share) = fig.subplots(2, 2, sharex=True)
    em.plot(sigma, t["em_recall"], "o-", label="EM recall (frame mean)")
    em.plot(sigma, t["em_precision"], "s--", label="EM precision (frame mean)")
    finish(em, "", "SegComp score at 0.8")
    normal.plot(sigma, t["mean_normal_err_deg"], "o-", color="C2", label="normal error of correct planes")
    finish(normal, "", "mean normal error (°)")
    err.errorbar(sigma, t["final_mean_map_error"], yerr=np.nan_to_num(t["final_mean_map_error_std"]), fmt="o-",
                 color="C3", capsize=3, label="final mean map error (± std over seeds)")
    finish(err, "point noise σ_pt (units)", MAP_ERROR)
    share.plot(sigma, t["walls_mapped"] / t["walls_seen"], "o-", color="C4", label="walls mapped / seen")
    share.plot(sigma, t["pose_valid_fraction"], "s--", color="C5", label="iterations with a valid pose")
    share.set_ylim(-0.05, 1.05)
    finish(share, "point noise σ_pt (units)", "share")
    seeds = int(t["seeds"].min())
    return f"{seeds} seed(s) per σ_pt — " + "; ".join(
        f"σ_pt {s:g}: recall {r:.3g}, precision {p:.3g}, normal error {n:.3g}°, map error {e:.3g}, "
        f"{w:.1f} of {ws:.0f} walls, pose valid {100 * v:.0f} %"
        for s, r, p, n, e, w, ws, v in zip(sigma, t["em_recall"], t["em_precision"], t["mean_normal_err_deg"],
                                           t["final_mean_map_error"], t["walls_mapped"], t["walls_seen"],
                                           t["pose_valid_fraction"]))


E23_W_MA = ("p-em-office-w-ma", "p-em-office-noise-w-ma")
E27 = ("p-em-demo",)
E29 = ("e29-office", "e29-room")
CHAPTER5 = [
    Figure(46, "points of one frame and EM's planes (E24's last frame)", ("p-em-office-noise",), points_and_em),
    Figure(55, "EM test bench: random walls (E30)", ("em-bench",), P(bench_case, scene="random_walls",
                                                                   variant="default", extractor="em2")),
    Figure(56, "actual planes: two close parallel walls (E30)", ("em-bench",),
           P(bench_case, scene="close_parallel", variant="gap=0.1", extractor="em2", truth_only=True)),
    Figure(57, "plane stealing points: EM2 on the close walls (E30)", ("em-bench",),
           P(bench_case, scene="close_parallel", variant="gap=0.1", extractor="em2")),
    Figure(58, "other plane stealing points: EM1 on the close walls (E30)", ("em-bench",),
           P(bench_case, scene="close_parallel", variant="gap=0.2", extractor="em1")),
    Figure(59, "extra plane: the corner without the exclusivity cull (E30)", ("em-bench",),
           P(bench_case, scene="corner", variant="exclusivity=off", extractor="em1")),
    Figure(60, "misaligned plane: the attached wall at a large inlier distance (E30)", ("em-bench",),
           P(bench_case, scene="attached_smaller", variant="inlier_distance=0.6", extractor="em2")),
    Figure(61, "unattached plane: EM1 with nearest assignment (E30)", ("em-bench",),
           P(bench_case, scene="corner", variant="assign_mode=nearest", extractor="em1")),
    Figure(105, "Map D, points, EM2, small frustum, no noise (E23)", ("p-em-office",), em_views),
    Figure(106, "Map D, points, EM2, small frustum, point noise (E24)", ("p-em-office-noise",), em_views),
    Figure(107, "Map E, points, EM2, large frustum, no noise (E25)", ("p-em-room",), em_views),
    Figure(108, "Map E, points, EM2, large frustum, point noise (E26)", ("p-em-room-noise",), em_views),
    Figure("paper6", "the simulation: points, EM and the Relative Plane map (E27, Map E with noise)", E27,
           P(demo_views, variant="room_noise")),
    Figure("paper7", "results without noise (E27)", E27, P(demo_maps, variants=("office_no_noise", "room_no_noise"))),
    Figure("paper8", "results with noise (E27)", E27, P(demo_maps, variants=("office_noise", "room_noise"))),
    Figure("e27-timing", "ms per iteration, EM and Relative Plane (E27)", E27, demo_timing),
    Figure("e29-em-compare", "EM1 vs EM2 (and the baseline) on identical frames (E29)", E29,
           P(em_compare, labels=("Map D, small frustum", "Map E, large frustum"))),
    Figure("e23-w-ma", "the moving-average window w_ma of Rule 18 without and with point noise (E23, E24)",
           E23_W_MA, P(w_ma_figure, labels=("Map D, points, no noise (E23)", "Map D, points, σ_pt 0.05 (E24)"))),
    Figure("e28-noise-sweep", "extraction and map against the point noise, Map E, EM2 (E28)", ("p-em-noise-sweep",),
           noise_sweep_figure),
]


# issue 14 Chapter 5: numbered figures in order, then the paper's and the extras
FIGURES = sorted([f for f in FIGURES + CHAPTER5 if isinstance(f.id, int)], key=lambda f: f.id) + \
    [f for f in FIGURES + CHAPTER5 if not isinstance(f.id, int)]
BY_ID = {str(f.id): f for f in FIGURES}


# ---- rendering -------------------------------------------------------------------------------

@dataclasses.dataclass
class Result:
    figure: Figure
    status: str  # "ok", "missing" or "error"
    detail: str  # the PNG path, the missing runs, or the error message
    shows: str = ""  # what our run shows, measured from its files (Chapter 4 figures)


def render(figure, runs, out):
    """Draws one figure into OUT/<name>.png, or says why not."""
    missing = [r for r in figure.runs if not os.path.exists(os.path.join(runs, r))]
    if missing:
        return Result(figure, "missing", ", ".join(missing))
    fig = plt.figure(figsize=FIGSIZE, layout="constrained")
    try:
        shows = figure.draw(fig, *[os.path.join(runs, r) for r in figure.runs])
    except rp.DataError as e:
        plt.close(fig)
        return Result(figure, "error", str(e))
    prefix = (f"Fig. {figure.id} — " if isinstance(figure.id, int)
              else f"Paper Fig. {figure.id[5:]} — " if str(figure.id).startswith("paper") else "Extra — ")
    fig.suptitle(prefix + figure.title)
    shows = shows if isinstance(shows, str) else ""  # helpers such as compare_algorithms return their axes
    return Result(figure, "ok", rp.save_png(fig, os.path.join(out, figure.name + ".png"), DPI), shows)


def render_all(runs, out, ids=None, log=print):
    results = []
    for figure in FIGURES if not ids else [BY_ID[i] for i in ids]:
        r = render(figure, runs, out)
        log({"ok": f"{figure.name}: wrote {r.detail}",
             "missing": f"{figure.name}: skipped, missing {r.detail} in {runs}",
             "error": f"{figure.name}: error: {r.detail}"}[r.status])
        results.append(r)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", help="folder holding the run folders (scripts/reproduce.sh's layout)")
    parser.add_argument("--out", help="folder for the PNGs")
    parser.add_argument("--fig", nargs="+", metavar="ID", help="only these figures (numbers or extra names)")
    parser.add_argument("--list", action="store_true", help="list the figures and the runs each needs")
    args = parser.parse_args()
    if args.list:
        for f in FIGURES:
            print(f"{f.name}\t{' '.join(f.runs)}\t{f.caption}")
        return 0
    if not args.runs or not args.out:
        parser.error("--runs and --out are required")
    unknown = [i for i in args.fig or [] if i not in BY_ID]
    if unknown:
        parser.error(f"unknown figure(s) {', '.join(unknown)}; --list shows them")
    results = render_all(args.runs, args.out, args.fig)
    return 1 if any(r.status == "error" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
