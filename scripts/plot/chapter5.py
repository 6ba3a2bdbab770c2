"""Chapter 5's figures (EM plane extraction, Figs 46, 55-61, 105-108, the paper's Figs 6-8): drawing
only; the numbers come from measures.em."""
import os

import numpy as np

from chapter4 import MAP_ERROR, WALL, plane_overlay
from draw import Figure, P, SMOOTH, finish
from measures.common import PLANE
from load import sweep_series
from measures.em import (EXTRACTORS, compare_frames, demo_times, em_frame_score, extracted_planes, point_frame,
    visible_pieces)
import load
from load import bench_scores, plane_table, sweep_cell, variant_folder_of
from measures.planes import count_summary
import noise_sweep
import relslam_plot as rp


EXTRACTED = {"color": "red", "lw": 1.8, "zorder": 4}  # the thesis draws current readings red


POINTS = {"s": 2, "color": "dimgrey", "alpha": 0.5, "linewidths": 0, "zorder": 2}


REAL_TIME_MS = 1000 / 30  # paper §III: 30 iterations a second including EM


def draw_robot(ax):
    ax.plot([0], [0], marker=(3, 0, -90), ms=10, color="black", ls="none", label="robot (looking along +x)",
            zorder=5)


def frame_points(ax, points, title):
    ax.scatter(points[:, 0], points[:, 2], label=f"{len(points)} points (x, z)", **POINTS)
    draw_robot(ax)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x, robot frame (units)", "z, robot frame (units)", legend="beside")
    ax.set_title(title, fontsize=9)


def em_planes_vs_visible(ax, run, iteration, points, ids, title):
    """EM planes (red) over the visible wall pieces (yellow) and the points, robot frame."""
    pieces = visible_pieces(load.truth_path(run), load.truth_walls(run), iteration, points, ids)
    for i, (a, b) in enumerate(pieces.values()):
        ax.plot([a[0], b[0]], [a[1], b[1]], label="visible wall pieces" if i == 0 else None, **WALL)
    planes = extracted_planes(load.observations(run), iteration)
    for i, (a, b, _) in enumerate(planes):
        ax.plot([a[0], b[0]], [a[1], b[1]], label=f"extracted planes ({len(planes)})" if i == 0 else None, **EXTRACTED)
    ax.scatter(points[:, 0], points[:, 2], **{**POINTS, "alpha": 0.25})
    draw_robot(ax)
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x, robot frame (units)", "z, robot frame (units)", legend="beside")
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
    k, points, ids = point_frame(load.table(run, "point_frames.csv"))
    axes = fig.subplots(2, 2)
    plane_overlay(axes[0, 0], run, title="true walls (yellow) and the generated map (blue), end of run")
    frame_points(axes[0, 1], points, f"points in view at iteration {k}")
    score = em_frame_score(load.table(run, "em_frames.csv"), k)
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
    s = count_summary(load.summary(run))
    frames = rp.read_table(os.path.join(run, "em_frames.csv"), ["recall", "precision"])
    return (f"{s['walls_mapped']:.0f} of {s['walls_seen']:.0f} seen walls mapped, {s['duplicates']:.0f} duplicates, "
            f"final mean map error {s['final_mean_map_error']:.3g} per plane, pose valid in "
            f"{100 * s['pose_valid_fraction']:.0f} % of iterations; extraction over the run: recall "
            f"{np.mean(frames['recall']):.4f}, precision {np.mean(frames['precision']):.4f} (frame means); "
            f"iteration {k}: {len(points)} points, {score['n_planes']:.0f} planes for {score['n_true_visible']:.0f} "
            f"visible wall pieces")


def points_and_em(fig, run):
    """Fig 46: the simulated points of one frame and the planes EM made of them."""
    k, points, ids = point_frame(load.table(run, "point_frames.csv"))
    left, right = fig.subplots(1, 2)
    frame_points(left, points, f"the point sensor's points, iteration {k}")
    score = em_frame_score(load.table(run, "em_frames.csv"), k)
    em_planes_vs_visible(right, run, k, points, ids, f"EM's planes (red), iteration {k}")
    right.legend(fontsize=7)
    return (f"iteration {k}: {len(points)} points, {score['n_planes']:.0f} planes for {score['n_true_visible']:.0f} "
            f"visible wall pieces (recall {score['recall']:.3g}, precision {score['precision']:.3g})")


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
    finish(ax, "x (units)", "z (units)", legend="beside")
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
        s = count_summary(load.summary(run))
        shows.append(f"{variant}: {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls mapped, "
                     f"{s['duplicates']:.0f} duplicates, final mean map error {s['final_mean_map_error']:.3g}, "
                     f"pose valid {100 * s['pose_valid_fraction']:.0f} %")
    return "; ".join(shows)


def demo_timing(fig, sweep):
    """Extra (E27): ms per iteration of EM and of Relative Plane, median and 95th percentile per cell,
    against the paper's 30 iterations a second."""
    times = demo_times(load.variant_iterations(sweep))
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


def em_compare(fig, *runs, labels):
    """Extra (E29): ms per frame of each extractor on identical frames, one panel per map."""
    axes = np.atleast_1d(fig.subplots(1, len(runs), sharey=True))
    shows = []
    for ax, run, label in zip(axes, runs, labels):
        it, by = compare_frames(load.table(run, "em_compare.csv"))
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
            s = count_summary(load.summary(variant_folder_of(sweep, name)))
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


# ---- Chapter 5's figures, in any order: figures.py sorts the one registry ---------------

FIGURES = [
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
