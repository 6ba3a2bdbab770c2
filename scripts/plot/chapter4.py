"""Chapter 4's figures (Relative Plane, Figs 64-102, the paper's Figs 1-5): drawing only; the numbers
come from measures.planes."""
import os

import numpy as np

from draw import Figure, MS, P, POS, finish
from measures.common import PLANE
from measures.em import extracted_planes, robot_pose
from measures.planes import (E07_AXES, EVENT_JUMP, EVENT_SETTLED, GROWN_TOP, HEAL_ITERATIONS, OFF_LINE, PAIR_NAMES,
    collinear_run, count_summary, event_healing, first_corner, first_seen_far, frustum_turns, group_counts,
    group_layout, grown_lengths, grown_text, interval_mode_errors, invariance, key_point_pair, key_points_by_phase,
    largest_healed_event, last_finite, loop_means, map_error_events, mapped_length, misplaced, observed_wall,
    one_plane_iteration, planar_rotation, planar_track, rltplane_rows, runtime_by_size, size_mismatches, under_sized,
    wall_lengths, wall_table, wrong_episodes)
import load
from load import (PlanarRun, first_seed, iteration_frame, iterations, plane_sweep, plane_table, sweep_series,
    true_path, true_walls, variant_folder_of)
import relslam_plot as rp


MAP_ERROR = "map error per plane (units)"  # mean e_ends


WALL = {"color": "gold", "lw": 5, "solid_capstyle": "butt", "zorder": 1}  # the thesis draws true walls yellow


MAPPED = {"color": "blue", "lw": 1.6, "zorder": 3}  # and mapped planes blue (Fig 70's text)


def groups_of(run):
    """measures.planes.group_layout of a planar run folder."""
    return group_layout(load.plane_file(run, "groups.csv"), load.plane_file(run, "planes.csv"))


def plane_overlay(ax, run, groups=False, title=None):
    """Top-down map (as thesis Fig. 67): true walls yellow, mapped planes blue, true path orange, estimated
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
        layout, mid = groups_of(run)
        for gid, (gx, gz, members) in layout.items():
            for m in members:
                ax.plot([gx, mid[m][0]], [gz, mid[m][1]], color="grey", lw=0.5, zorder=2)
            ax.annotate(f"X{gid}", (gx, gz), ha="center", va="center", fontsize=8, zorder=4,
                        bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "grey", "lw": 0.5})
    ax.set_aspect("equal", adjustable="datalim")
    finish(ax, "x (units)", "z (units)", legend="beside")
    if title:
        ax.set_title(title, fontsize=9)


def map_overlay(fig, run, groups=False):
    """Figs 64, 67: the final map over the true walls."""
    ax = fig.subplots()
    plane_overlay(ax, run, groups)
    s = count_summary(load.summary(run))
    shows = (f"{s['walls_mapped']:.0f} of {s['walls_seen']:.0f} seen walls mapped, {s['duplicates']:.0f} duplicates, "
             f"final mean map error {s['final_mean_map_error']:.3g} units per plane, pose valid in "
             f"{100 * s['pose_valid_fraction']:.0f} % of the iterations")
    if groups:
        shows += f"; {len(groups_of(run)[0])} groups"
    return shows


def four_planes_errors(fig, run):
    """Fig 70 (E03): map and pose error over the loops of Map A; each loop's mean drawn as a step, since
    "no drift" (thesis 4.3.1) means the last loop's mean is no higher than the first's."""
    d = iterations(run, ["mean_map_error", "position_error"], PLANE)
    axes = fig.subplots(2, 1, sharex=True)
    texts = []
    for ax, column, ylabel in zip(axes, ["mean_map_error", "position_error"], [MAP_ERROR, POS]):
        ax.plot(d["iteration"], d[column], lw=0.4, color="lightsteelblue", label="per iteration")
        loops = loop_means(PlanarRun(run), column)
        for k, (lo, hi, mean) in enumerate(loops):
            ax.plot([lo, hi], [mean, mean], color="darkblue", lw=2, label="mean per loop" if k == 0 else None)
        finish(ax, "iteration" if ax is axes[-1] else "", ylabel)
        texts.append(f"{column}: loop 1 mean {loops[0][2]:.3g}, loop {len(loops)} mean {loops[-1][2]:.3g}, "
                     f"max {np.nanmax(d[column]):.3g}")
    return "; ".join(texts)


def rltplane_table(fig, run, wall=0):
    """Fig 65 / paper Fig 1: the RltPlane structure as a table of one plane's untransformed observations."""
    rows, total = rltplane_rows(load.observations(run), wall)
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


def invariance_scatter(fig, run):
    """Fig 66 / paper Fig 3 (E01): raw midpoint difference and Rule 3 offset against the heading."""
    psi, raw, rel, expected = invariance(PlanarRun(run))
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
    links = plane_table(run, "links.csv", ["from", "linking_planes"], strings=("linking_planes",))
    per_link = [len([s for s in p.split(";") if s]) for f, p in zip(links["from"], links["linking_planes"])
                if np.isfinite(f)]
    s = count_summary(load.summary(run))
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


E05 = ("p-e05-edge-on",)


E06 = ("p-e06-rule12",)


def key_point_pairs_figure(fig, run):
    """Fig 68 / paper Fig 4 (E02): the four offset series of Rule 13 for one growing and one shrinking
    plane, and their standard deviations; the chosen pair is the lowest."""
    series, sig, chosen, right = key_point_pair(PlanarRun(run))
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


def interval_mode_figure(fig, sweep, mode):
    """Figs 74 (group) and 75 (pair), E07: map error over the run under both noise models, and the
    run means of all four combinations as bars."""
    errors = interval_mode_errors(load.plane_frames(sweep, E07_AXES))
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
                events = map_error_events(iteration_frame(run, PLANE))
                heal += [min(h, clip + 1) if h is not None else clip + 1 for _, _, h, _ in events]
                wrong += [min(e[3], clip + 1) for e in wrong_episodes(load.plane_file(run, "keypoints.csv"))]
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
    d, k, event = largest_healed_event(iteration_frame(run, PLANE))
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
    ev = map_error_events(iteration_frame(run, PLANE))
    ax.plot([e[0] for e in ev], [d["map_error"][int(np.nonzero(d["iteration"] == e[0])[0][0])] for e in ev], "rv",
            label=f"{name}: events (a jump of ≥ {EVENT_JUMP:g} in one iteration)")
    finish(ax, "iteration", "map error (units)")
    n, quick, never, median = event_healing(iteration_frame(run, PLANE))
    return (f"{name}: {n} events, {quick} healed within {HEAL_ITERATIONS} iterations, {never} never healed; final map "
            f"error {d['map_error'][-1]:.3g}")


def per_wall_bars(fig, sweep, column, ylabel, names=None):
    """One bar per true wall and variant (the largest plane of a wall when it has two)."""
    variants = [(n, f[0]) for (n,), f in plane_sweep(sweep) if names is None or n in names]
    ax = fig.subplots()
    width = 0.8 / len(variants)
    texts = []
    for i, (name, run) in enumerate(variants):
        table = wall_table(load.plane_file(run, "planes.csv"))
        walls = sorted(table)
        values = [max(table[w])[0 if column == "len_ratio" else 1] for w in walls]
        ax.bar(np.array(walls) + (i - (len(variants) - 1) / 2) * width, values, width, label=name)
        s = count_summary(load.summary(run))
        small = under_sized(load.plane_file(run, "planes.csv"))
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
        s = count_summary(load.summary(run))
        texts.append(f"{name}: {s['walls_mapped']:.0f} of {s['walls_seen']:.0f} walls mapped, "
                     f"{s['duplicates']:.0f} duplicates, final mean map error {s['final_mean_map_error']:.3g}")
        if groups:
            layout = groups_of(run)[0]
            texts[-1] += (f", {len(layout)} groups on the map, X0 holds plane(s) "
                          + (", ".join(map(str, layout[0][2])) if 0 in layout else "none"))
    return "; ".join(texts)


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
    return "; ".join(f"{k}: {v} groups" for k, v in group_counts(load.first_seed_iterations(sweep)).items())


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
        n, total, gap = size_mismatches(load.plane_file(folders[0], "edges.csv"))
        off = misplaced(load.plane_file(folders[0], "planes.csv"))
        texts.append(f"{name}: " + (", ".join(f"wall {w} {e:.3g} off its line" for w, e in off) or
                                    f"every plane within {OFF_LINE:g} of its wall's line")
                     + f"; final position error {last_finite(d['position_error']):.3g}; {n} of {total} chain edges "
                       f"saw a plane more than 0.02 off its canonical size (largest {gap:.3g})")
    top.set_xticks(np.arange(len(p["id"])), [f"{i:.0f}" for i in p["id"]], fontsize=7)
    finish(top, "mapped plane (planes.csv id)", "e_perp (units)")
    finish(bottom, "iteration", POS)
    return "; ".join(texts)


def collinear_figure(fig, run):
    """Fig 97 (E18): Map D with the small frustum, the defaults (the distance test on, Rule 30 off): the
    collinear pieces tie both diagonals (Rule 15) and the distance test takes the real ends."""
    d, first_bad, ambiguous_claims, ambiguous_edges = collinear_run(PlanarRun(run))
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
    s = count_summary(load.summary(run))
    until = "throughout" if first_bad is None else f"until iteration {first_bad}"
    valid = np.nonzero(d["pose_valid"] == 1)[0]
    return (f"pose exact (error ≤ 1e-6) {until}, last valid pose at iteration "
            f"{d['iteration'][valid[-1]] if len(valid) else float('nan'):.0f}; {ambiguous_claims} key-point claims and "
            f"{ambiguous_edges} chain edges tied both diagonals (Rule 15); {s['walls_mapped']:.0f} of "
            f"{s['walls_seen']:.0f} walls mapped, pose valid {100 * s['pose_valid_fraction']:.0f} %")


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
        s = count_summary(load.summary(folders[0]))
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
    sizes = runtime_by_size(load.first_seed_iterations(sweep, "planar.loops"))
    return "; ".join(f"{k} loop(s): median {v[0]:.3g} ms, first tenth {v[1]:.3g}, last tenth {v[2]:.3g}, "
                     f"{v[3]} RltPlanes, {v[4]} iterations" for k, v in sizes.items())


E09, E15 = ("p-e09-plane5",), ("p-e15-loop-closure-map-e",)


FRUSTUMS = {"small": (30.0, 7.0), "large": (35.0, 30.0)}  # thesis 6.3.2 presets: half angle (degrees), far distance


VIEWED = {"color": "red", "lw": 3.5, "solid_capstyle": "butt", "zorder": 5}  # the part in view (Fig 69, paper Fig 5)


def draw_view(ax, run, iteration, walls=None):
    """The robot at an iteration (true pose, a triangle looking along its heading) and what it saw then:
    each observed plane (of `walls`, else all) moved into the world by the true pose, red. Returns the
    pieces drawn as [(a, b, wall)] in the world."""
    t, psi = robot_pose(load.truth_path(run), iteration)
    rot = planar_rotation(psi)
    pieces = [(rot @ a + t, rot @ b + t, w) for a, b, w in extracted_planes(load.observations(run), iteration)
              if walls is None or w in walls]
    for i, (a, b, _) in enumerate(pieces):
        ax.plot([a[0], b[0]], [a[1], b[1]], label="in view at that iteration" if i == 0 else None, **VIEWED)
    ax.plot([t[0]], [t[1]], marker=(3, 0, np.degrees(psi) - 90), ms=12, color="black", ls="none", zorder=6,
            label=f"robot at iteration {iteration} (true pose)")
    ax.legend(fontsize=7)
    return pieces


E11 = ("p-e11-first-corner",)


def first_corner_map(fig, sweep):
    """Fig 83 (E11): Map E1's final map, the true and estimated paths, the motion model's poses red."""
    run = first_seed(sweep)
    ax = fig.subplots()
    plane_overlay(ax, run)
    est = planar_track(load.tum(run, PLANE, "trajectory.tum"))
    d = iterations(run, ["mm_active"], PLANE)
    mm = np.isin(est["iteration"], d["iteration"][d["mm_active"] == 1])
    ax.plot(est["x"][mm], est["z"][mm], ".", color="red", ms=3, zorder=4, label="estimated poses, motion model")
    ax.legend(fontsize=8)
    e, before, heading = first_corner(PlanarRun(run))
    s = count_summary(load.summary(run))
    return (f"seed 1: the motion model tracks plane {e['plane']} (wall {e['wall']}) from iteration {e['first']}, "
            f"{before:.2g} units before the turn, to {e['last']}, {heading:.0f}° into it; {s['walls_mapped']:.0f} of "
            f"{s['walls_seen']:.0f} seen walls mapped, final mean map error {s['final_mean_map_error']:.3g} per plane "
            f"(e_ends counts the parts of the long walls never seen)")


def mm_pose_track(fig, sweep):
    """Fig 84 (E11): the pose through the corner: position error, and the estimated against the true
    heading (the motion model's own heading in its frame as dots), the motion model shaded."""
    run = first_seed(sweep)
    d = iterations(run, ["position_error", "mm_active", "mm_heading_deg"], PLANE)
    truth, est = true_path(run), planar_track(load.tum(run, PLANE, "trajectory.tum"))
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
    e, _, _ = first_corner(PlanarRun(run))
    d = iterations(run, ["mm_distance", "mm_s_min", "mm_s_max", "mm_active"], PLANE)
    seen = observed_wall(PlanarRun(run), e["wall"])
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
    events = map_error_events(iteration_frame(run, PLANE))
    at = {int(i): k for k, i in enumerate(d["iteration"])}
    top.plot([e[0] for e in events], [d["map_error"][at[e[0]]] for e in events], "rv",
             label=f"events (a jump of ≥ {EVENT_JUMP:g})")
    shade_motion_model(top, d, np.nanmax(d["map_error"]))
    finish(top, "", "map error (units)")
    bottom.bar(d["iteration"], d["kp_checked"], width=1, color="lightgrey", label="key points claimed")
    bottom.bar(d["iteration"], d["kp_wrong"], width=1, color="red", label="wrong (not a real wall end)")
    shade_motion_model(bottom, d, np.nanmax(d["kp_checked"]))
    finish(bottom, "iteration", "claims")
    split = key_points_by_phase(iteration_frame(run, PLANE))
    n, quick, never, _ = event_healing(iteration_frame(run, PLANE))
    return (f"seed 1: wrong key-point claims {split['in'][0]} of {split['in'][1]} inside the motion model, "
            f"{split['out'][0]} of {split['out'][1]} outside; {n} map-error events ({quick} healed within "
            f"{HEAL_ITERATIONS} iterations, {never} never), {sum(e[3] for e in events)} of them a new plane joining "
            f"the map")


def grow_threshold_figure(fig, sweep):
    """Fig 88 (E13): per growth threshold, each motion model's tracked length at its end over the wall's
    true length, and the mapped length ratio of the planes it grew (every seed)."""
    stats = grown_lengths(load.planar_variants(sweep))
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


def frustum_figure(fig, sweep):
    """Fig 89 (E14): the end wall's length in view and the range of its farther end against the heading
    through the turn, per frustum shape and size; its mapped length dashed; the far distance f and the
    trapezoid's corner reach f / cos α dotted."""
    turns = frustum_turns(load.first_seeds(sweep))
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


E22 = ("p-e22-one-partial-plane",)


def one_partial_plane(fig, run):
    """Fig 69 / paper Fig 5 (E22): the map, the robot at a corner of its last loop with the motion model
    active, and the part of the single wall in its view, red."""
    k, first, last = one_plane_iteration(PlanarRun(run))
    ax = fig.subplots()
    plane_overlay(ax, run)
    pieces = draw_view(ax, run, k)
    d = iterations(run, ["position_error", "mm_active", "visible_planes"], PLANE)
    row = int(np.nonzero(d["iteration"] == k)[0][0])
    lengths = wall_lengths(load.truth_walls(run))
    return (f"iteration {k} (of the stretch {first}-{last} on the last loop): motion model "
            f"{'on' if d['mm_active'][row] == 1 else 'off'}, {d['visible_planes'][row]:.0f} plane in view: "
            + ", ".join(f"wall {w}, {np.linalg.norm(b - a):.3g} of its {lengths[w]:.3g} units" for a, b, w in pieces)
            + f"; position error {d['position_error'][row]:.3g}")


def first_seen_figure(fig, sweep, name):
    """Fig 100 (E19): the wall first seen from farthest away, red, from where the robot first saw it (the
    large frustum, no occlusion), over variant `name`'s final map."""
    run = variant_folder_of(sweep, name)
    wall, k, near = first_seen_far(load.observations(run))
    ax = fig.subplots()
    plane_overlay(ax, run, title=f"{name}: the final map; wall {wall} as first seen")
    draw_view(ax, run, k, walls={wall})
    on_map = np.isfinite(mapped_length(load.plane_file(run, "planes.csv"), wall))
    return (f"{name}: wall {wall} is first seen at iteration {k}, its nearer end {near:.3g} units away; "
            f"{'on' if on_map else 'not on'} the final map")


E16, E17 = ("p-e16-rule29",), ("p-e17-interval-check",)


# ---- Chapter 4's figures, in any order: figures.py sorts the one registry ---------------

FIGURES = [
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
