"""Chapter 6's figures (Relative Point, Figs 110-171): drawing only; the numbers come from measures.points."""
import os

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from draw import Figure, LE, MS, P, POS, SMOOTH, draw_fits, finish, label_densities, readable
from measures.common import ALG, line_fit, steady
from measures.compare import side_by_side
from measures.points import COMPONENTS, density_table, vp_benchmarks
import load
from load import algorithms, iterations, sweep_series, vp_landmarks
import relslam_plot as rp


COMPONENT_NAMES = {"t_init_ms": "init", "t_load_ms": "load", "t_compute_ms": "compute", "t_create_ms": "create",
                   "t_pose_ms": "pose", "t_other_ms": "other"}


VISIBLE = "mean visible points per iteration n (labels: density)"


BASELINE = {"color": "deeppink", "lw": 2.8, "zorder": 5}  # the thesis draws its baseline pink and thick


PAIRING = "every_bin"  # the thesis's pairing rule: it shows Fig 113's polynomial growth (README, RltBinning)


REFERENCES = {"n_minus_1": "n − 1", "n_ln_n": "n·ln n", "three_n_ln_n": "3n·ln n", "n_squared_half": "n²/2"}


TENS = tuple(range(0, 100, 10))


THESIS_VP_MS = {1: 0.296, 2: 0.40, 3: 0.57}  # thesis 6.8, seconds per iteration x 1000


VP_FITTED = "landmarks_similarity_fit.csv"  # x,y in the GPS frame after map_comparison's fit


def single_series(fig, run, column, ylabel, stride=1, zero=False):
    """One relative_point column against the iteration (Figs 130, 132, 134, 167-171)."""
    d = iterations(run, [column])
    ax = fig.subplots()
    label = readable(ALG) if stride == 1 else f"{readable(ALG)} (every {stride}th iteration)"
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
    ax.plot(d["iteration"][:n], truth[axis][:n] + d["e" + axis][:n], lw=0.8,
            label=f"estimated {axis} ({readable(ALG)})")
    finish(ax, "iteration", f"{axis} location (units)")


def compare_runs(fig, *runs, column, ylabel, labels):
    """The same relative_point column of several runs (Fig 119)."""
    ax = fig.subplots()
    for run, label in zip(runs, labels):
        d = iterations(run, [column])
        ax.plot(d["iteration"], d[column], lw=1, label=label)
    finish(ax, "iteration", ylabel)


def draw_algorithms(ax, run, column):
    """Every algorithm of one run on the same stream; returns {algorithm: DataFrame of iteration, column}."""
    frames = {}
    for algorithm in algorithms(run):
        d = iterations(run, [column], algorithm)
        ax.plot(d["iteration"], d[column], lw=0.9, label=readable(algorithm))
        frames[algorithm] = pd.DataFrame({"iteration": d["iteration"], column: d[column]})
    return frames


def side_by_side_text(frames, column, statistic="mean"):
    """One line on what a comparison figure shows (compare.side_by_side), with each algorithm's name."""
    rows, shared = side_by_side(frames, column, statistic)
    cells = [f"{readable(a)} {statistic} {v:.3g}, last {last:.3g} ({n} iterations)" for a, n, v, last in rows]
    ratio = f"; ratio {rows[0][2] / rows[1][2]:.3g}" if len(rows) == 2 and rows[1][2] else ""
    return f"over the {shared} iterations all ran: " + "; ".join(cells) + ratio


def compare_algorithms(fig, run, column, ylabel, logy=False):
    """Every algorithm of one run on the same stream (Figs 146-152), and what it shows."""
    ax = fig.subplots()
    frames = draw_algorithms(ax, run, column)
    if logy:
        ax.set_yscale("log")  # the EKF is orders of magnitude slower (thesis Fig 148)
    finish(ax, "iteration", ylabel)
    return side_by_side_text(frames, column, "median" if column == "runtime_ms" else "mean")


def point_count(fig, run):
    """Fig 149: map sizes, plus the true landmarks seen so far when observations.csv was written."""
    ax = fig.subplots()
    frames = draw_algorithms(ax, run, "landmarks_in_map")
    shows = side_by_side_text(frames, "landmarks_in_map")
    path = os.path.join(run, "observations.csv")
    if os.path.exists(path):
        obs = rp.read_table(path, ["iteration", "true_id"])
        _, first = np.unique(obs["true_id"], return_index=True)
        first_seen = np.sort(obs["iteration"][first])
        it = np.unique(obs["iteration"])
        ax.plot(it, np.searchsorted(first_seen, it, side="right"), "k:", lw=1, label="true points seen so far")
        shows += f"; {len(first_seen)} true points seen by the last iteration"
    finish(ax, "iteration", "landmarks on the map")
    return shows


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
    ax.plot(it, rp.moving_average(t, SMOOTH), lw=0.8,
            label=f"{readable(ALG)}, {SMOOTH}-iteration moving average")
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
    t = density_table(load.density_runs(sweep))
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
    t = density_table(load.density_runs(sweep))
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
    t = density_table(load.density_runs(sweep))
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
    return "mean ms per iteration: " + ", ".join(f"{COMPONENT_NAMES[c]} {np.mean(d[c]):.3g}" for c in names)


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
        ax.plot(path["x"], path["y"], color=colour, lw=1, label=f"{readable(algorithm)} trajectory")
        lm = vp_landmarks(run, algorithm)
        ax.plot(lm["x"], lm["y"], marker, color=colour, mfc="none", ls="none",
                label=f"{readable(algorithm)} landmarks")
    vp_gps(ax, run, color="black", ms=3)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (m, GPS frame)", "y (m, GPS frame)", legend="beside")


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
    ax.plot(ref["x"], ref["y"], "o", ms=11, mfc="gold", mec="black", ls="none",
            label=f"{readable('ekf2d')} reference map")
    ax.plot(rel["x"], rel["y"], "s", ms=5, color="blue", ls="none",
            label=f"{readable(ALG)} ({'after the similarity fit' if fitted else 'rigid GPS fit of its trajectory'}): "
                  f"{fit['matched'][row]:.0f} of {fit['landmarks'][row]:.0f} matched, similarity-fit RMS "
                  f"{fit['rms'][row]:.3g} m, scale {fit['scale'][row]:.4g}")
    vp_gps(ax, run, color="lightgrey", ms=2)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (m, GPS frame)", "y (m, GPS frame)", legend="beside")


def vp_timing(fig, path):
    """Extra: Victoria Park ms per scan per grouping level (Google Benchmark JSON) vs the thesis."""
    measured = vp_benchmarks(load.read_json(path), path)
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


def _axis_figures():
    out = []
    for axis, error_fig, location_fig, forty_fig in [("x", 130, 131, 169), ("y", 132, 133, 170), ("z", 134, 135, 171)]:
        ylabel = f"{axis} error, estimate − truth (units)"
        out += [Figure(error_fig, f"{axis} error", ("s-f8",), P(single_series, column="e" + axis, ylabel=ylabel,
                                                                 zero=True)),
                Figure(location_fig, f"{axis} location", ("s-f8",), P(location, axis=axis)),
                Figure(forty_fig, f"{axis} error over 40 loops", ("s-40",),
                       P(single_series, column="e" + axis, ylabel=ylabel, stride=10, zero=True),
                       quick_title=f"{axis} error over {{loops}} loops (quick; the thesis ran 40)")]
    return out


def _binning(number, title, column, ylabel, heuristic, **kw):
    return Figure(number, title, ("s-bin",), P(binning_lines, column=column, ylabel=ylabel, heuristic=heuristic, **kw))


def _variants(number, title, sweep, columns, ylabels, quick_title="", **kw):
    return Figure(number, title, (sweep,), P(variant_lines, columns=columns, ylabels=ylabels, **kw), quick_title)


def _compare(number, title, run, column, ylabel, quick_title="", **kw):
    return Figure(number, title, (run,), P(compare_algorithms, column=column, ylabel=ylabel, **kw), quick_title)


def _density(number, title, column, fits):
    return Figure(number, title, ("s-dens-q",), P(density_component, column=column, fits=fits))


CMP = "comparisons"


GROUPS = ["groups", "final_groups"]


GROUP_LABELS = ["groups created", "final groups"]


ALL_REFS = ("n_minus_1", "n_ln_n", "n_squared_half")


# ---- Chapter 6's figures, in any order: figures.py sorts the one registry ---------------

FIGURES = [
    Figure("components", "run-time components, one figure-eight loop", ("s-f8",), components),
    Figure("vp-timing", "Victoria Park ms per scan by grouping levels", ("vp-timing.json",), vp_timing),
    Figure("vp-bridged", "Victoria Park whole log, bridged by dead reckoning", ("vp-bridged",), vp_map),
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
    _variants(126, "seven loops, three settings", "s-f8-7l-const", ["landmark_error"], [LE],
              quick_title="{loops} loops, three settings (quick; the thesis ran 7)"),
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
    _compare(146, "figure-eight landmark error", "s-ekf-f8", "landmark_error", LE,
             quick_title="figure-eight landmark error, first {iterations} iterations (quick)"),
    _compare(147, "figure-eight position error", "s-ekf-f8", "position_error", POS,
             quick_title="figure-eight position error, first {iterations} iterations (quick)"),
    _compare(148, "figure-eight run time", "s-ekf-f8", "runtime_ms", MS, logy=True,
             quick_title="figure-eight run time, first {iterations} iterations (quick)"),
    Figure(149, "figure-eight point count", ("s-ekf-f8",), point_count,
           quick_title="figure-eight point count, first {iterations} iterations (quick)"),
    _compare(150, "straight-line landmark error", "s-line", "landmark_error", LE,
             quick_title="straight-line landmark error, first {iterations} iterations (quick)"),
    _compare(151, "straight-line position error", "s-line", "position_error", POS,
             quick_title="straight-line position error, first {iterations} iterations (quick)"),
    _compare(152, "stationary landmark error", "s-stat", "landmark_error", LE,
             quick_title="stationary landmark error, first {iterations} iterations (quick)"),
    Figure(163, "Victoria Park, scans 1181-1642", ("vp-1181",), vp_map),
    Figure(164, "Victoria Park 1181-1642 over the ekf2d map", ("vp-1181",), vp_overlay),
    Figure(165, "Victoria Park, scans 4220-4634", ("vp-4220",), vp_map),
    Figure(166, "Victoria Park 4220-4634 over the ekf2d map", ("vp-4220",), vp_overlay),
    Figure(167, "landmark error over 40 loops", ("s-40",), P(single_series, column="landmark_error", ylabel=LE,
                                                                stride=10),
           quick_title="landmark error over {loops} loops (quick; the thesis ran 40)"),
    Figure(168, "position error over 40 loops", ("s-40",), P(single_series, column="position_error", ylabel=POS,
                                                                stride=10),
           quick_title="position error over {loops} loops (quick; the thesis ran 40)"),
]
