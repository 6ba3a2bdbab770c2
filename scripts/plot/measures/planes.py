"""Chapter 4 (Relative Plane) measures: the numbers its figures show and claims.py checks.

Pure functions on the tables of a planar run that load.py reads. A measure that needs one file takes
its table (planes.csv, keypoints.csv, edges.csv, summary.csv, ...); one that needs several takes `r`, the
run's tables as attributes: r.iterations (relative_plane/iterations.csv), r.planes, r.groups,
r.keypoints, r.edges, r.pairs, r.pair_sigma (relative_plane/*.csv), r.observations
(plane_observations.csv), r.truth_path (ground_truth_path.tum), r.walls (ground_truth_walls.csv),
r.manifest (manifest.json as a dict). load.PlanarRun reads them when first used; a test passes a
types.SimpleNamespace of hand-made frames.
"""
import numpy as np

from measures.common import PLANE, arrays, source
import relslam_plot as rp

OBSERVED = ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"]


def planar_track(tum):
    """{iteration, x, z, psi_deg} of a planar run's TUM trajectory (t, x, y, z, qx, qy, qz, qw; TUM time =
    iteration). The planar turn by ψ is a rotation about −y (core/planar_pose.hpp), so
    q = (0, −sin ψ/2, 0, cos ψ/2)."""
    t = arrays(tum, ["t", "x", "z", "qy", "qw"])
    psi = np.degrees(2 * np.arctan2(-np.asarray(t["qy"]), np.asarray(t["qw"])))
    return {"iteration": np.asarray(t["t"]), "x": np.asarray(t["x"]), "z": np.asarray(t["z"]),
            "psi_deg": (psi + 180) % 360 - 180}


def run_loops(manifest, where="manifest.json"):
    """(loops, iterations) of a planar run from its manifest (0 loops: the map's own path)."""
    try:
        return int(manifest["scenario"]["planar"]["loops"]), int(manifest["planar_simulation"]["iterations"])
    except (KeyError, TypeError, ValueError):
        raise rp.DataError(f"{where}: no scenario.planar.loops or planar_simulation.iterations") from None


def loop_means(r, column):
    """[(first iteration, last iteration, mean of column)] per loop: the run cut into its loops of equal
    length (the last iteration closes the final loop). Invalid poses (empty fields) are left out."""
    where = manifest_path(r)
    loops, n = run_loops(r.manifest, where)
    if loops < 1:
        raise rp.DataError(f"{where}: scenario.planar.loops is {loops}: no loops")
    return means_per_loop(arrays(r.iterations, ["iteration", column]), column, loops, n)


def manifest_path(r):
    """Where r's manifest came from, for messages."""
    return getattr(r, "manifest_path", "manifest.json")


def means_per_loop(d, column, loops, n):
    """loop_means on a table (a DataFrame or {column: array}) of `iteration` and `column`: n iterations
    cut into `loops` equal parts, the mean of each part's finite values (NaN where it has none)."""
    it, values = np.asarray(d["iteration"], dtype=float), np.asarray(d[column], dtype=float)
    edges = np.linspace(0, n, loops + 1).round().astype(int)
    out = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        part = values[(it >= lo) & (it < hi)]
        out.append((int(lo), int(hi - 1), float(np.nanmean(part)) if np.isfinite(part).any() else float("nan")))
    return out


def group_layout(groups, planes):
    """{group id: (x, z, [member plane ids])}: a label at the mean of the member planes' mapped midpoints,
    as the paper draws its X labels ("for display purposes the centroid of the group", paper §II.D).
    groups, planes: groups.csv and planes.csv."""
    g = arrays(groups, ["group_id", "planes"], strings=("planes",))
    p = arrays(planes, ["id", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    mid = {int(i): ((ax + bx) / 2, (az + bz) / 2)
           for i, ax, az, bx, bz in zip(p["id"], p["kp1_x"], p["kp1_z"], p["kp2_x"], p["kp2_z"])
           if np.isfinite([ax, az, bx, bz]).all()}
    out = {}
    for gid, planes in zip(g["group_id"], g["planes"]):
        members = [int(s) for s in planes.split(";") if s and int(s) in mid]
        if members:
            out[int(gid)] = (np.mean([mid[m][0] for m in members]), np.mean([mid[m][1] for m in members]), members)
    return out, mid


def count_summary(summary):
    """summary.csv's relative_plane row: final mean map error, walls mapped and seen, duplicates, share of
    valid poses."""
    s = arrays(summary, ["algorithm", "final_mean_map_error", "walls_mapped", "walls_seen", "duplicates",
                         "pose_valid_fraction"], strings=("algorithm",))
    rows = [i for i, a in enumerate(s["algorithm"]) if a == PLANE]
    if not rows:
        raise rp.DataError(f"{source(summary)}: column algorithm: no {PLANE} row")
    return {c: s[c][rows[0]] for c in s if c != "algorithm"}


def rltplane_rows(observations, wall=0, first=6):
    """Rows of one plane's untransformed observations (thesis Fig 65: iteration, location, orientation;
    paper Fig 1 adds the plane equation's d): midpoint m, normal n = tangent turned +90° (thesis 4.2.1)
    as (nx, ny, nz) with ny = 0 (2½D), d = −n·m, robot frame. observations: plane_observations.csv."""
    o = arrays(observations, OBSERVED)
    sel = np.nonzero(o["true_wall"] == wall)[0]
    if len(sel) == 0:
        raise rp.DataError(f"{source(observations)}: column true_wall: no wall {wall}")
    rows = []
    for k in [*sel[:first], sel[-1]]:
        a = np.array([o["kp1_x"][k], o["kp1_z"][k]])
        b = np.array([o["kp2_x"][k], o["kp2_z"][k]])
        u = (b - a) / np.linalg.norm(b - a)
        n, m = np.array([-u[1], u[0]]), (a + b) / 2
        rows.append([f"{o['iteration'][k]:.0f}", f"({m[0]:.3f}, {m[1]:.3f})", f"({n[0]:.3f}, 0, {n[1]:.3f})",
                     f"{-n @ m:.3f}", f"({a[0]:.2f}, {a[1]:.2f}) – ({b[0]:.2f}, {b[1]:.2f})"])
    return rows, len(sel)


def invariance(r):
    """E01: per iteration with both walls, the raw midpoint difference m2 − m1 and the Rule 3 offset
    Rot(−θ1)(m2 − m1), θ1 = plane 1's direction a→b (thesis 4.3.1), with the robot's true heading; plus
    the offset the true walls give. Uses r.observations, r.truth_path, r.walls."""
    o = arrays(r.observations, OBSERVED)
    walls = sorted(set(o["true_wall"]))[:2]
    if len(walls) < 2:
        raise rp.DataError(f"{source(r.observations)}: column true_wall: fewer than two walls")
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
    path = planar_track(r.truth_path)
    heading = dict(zip(path["iteration"], path["psi_deg"]))
    w = arrays(r.walls, ["id", "a_x", "a_z", "b_x", "b_z"])
    ends = {int(i): (np.array([ax_, az]), np.array([bx, bz]))
            for i, ax_, az, bx, bz in zip(w["id"], w["a_x"], w["a_z"], w["b_x"], w["b_z"])}
    (a1, b1), (a2, b2) = ends[int(walls[0])], ends[int(walls[1])]
    expected = planar_rotation(-np.arctan2(*(b1 - a1)[::-1])) @ ((a2 + b2) / 2 - (a1 + b1) / 2)
    return np.array([heading.get(i, np.nan) for i in both]), raw, rel, expected


def planar_rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def last_finite(values):
    """The last value that is not NaN (an iteration without a valid pose leaves its error empty)."""
    finite = np.asarray(values)[np.isfinite(values)]
    return finite[-1] if len(finite) else float("nan")


HEAL_ITERATIONS = 4  # thesis 4.3.4: a wrong key point "self corrected after the fourth iteration"


PAIR_NAMES = {(1, 1): "KP1–KP1", (1, 2): "KP1–KP2", (2, 1): "KP2–KP1", (2, 2): "KP2–KP2"}


UNDER_SIZED = 0.95  # a mapped plane shorter than this share of its wall is under-sized (E09) [R]


def seed_mean(frames, column):
    """(iterations, per-iteration mean of column over the seeds' iterations tables, cut to the shortest)."""
    runs = [arrays(f, ["iteration", column]) for f in frames]
    n = min(len(r["iteration"]) for r in runs)
    values = np.array([r[column][:n] for r in runs])
    seen = np.isfinite(values).sum(axis=0)  # before the first pose no seed has a value: NaN, silently
    return runs[0]["iteration"][:n], np.where(seen > 0, np.nansum(values, axis=0) / np.maximum(seen, 1), np.nan)


def key_point_pair(r):
    """pairs.csv, pair_sigma.csv and the truth of the chosen key points: the share of the pair's
    iterations in which each chosen end is a real wall end (plane_observations.csv joined on the
    iteration and the observation's first end). Uses r.pairs, r.pair_sigma, r.observations."""
    cols = ["iteration", "plane1", "plane2", "a1_x", "a1_z", "a2_x", "a2_z"] + [
        f"off{a}{b}_{c}" for a in (1, 2) for b in (1, 2) for c in "xz"]
    series = arrays(r.pairs, cols)
    sig = arrays(r.pair_sigma, ["kp_a", "kp_b", "sigma", "mean_x", "mean_z", "chosen", "key_point1", "key_point2",
                                "samples", "interval_start", "interval_end"])
    if len(series["iteration"]) == 0 or len(sig["sigma"]) != 4:
        raise rp.DataError(f"{source(r.pairs)}: no pair in which one plane grows while the other shrinks")
    obs = arrays(r.observations, ["iteration", "kp1_x", "kp1_z", "kp1_true_end", "kp2_true_end"])
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


E07_AXES = ("variant", "planar.noise.model")


def interval_mode_errors(cells):
    """{(mode, noise model): (iterations, mean map error per iteration over the seeds, mean over the run,
    seeds)}; cells: [((mode, noise model), [iterations table per seed])] (the E07 sweep, E07_AXES)."""
    out = {}
    for (mode, noise), frames in cells:
        it, err = seed_mean(frames, "mean_map_error")
        out[(mode, noise)] = (it, err, float(np.nanmean(err)), len(frames))
    return out


def wrong_episodes(keypoints):
    """Runs of consecutive iterations in which one (group, plane)'s key-point claim is wrong, from
    keypoints.csv: [(group, plane, first iteration, iterations)], longest first."""
    k = arrays(keypoints, ["iteration", "group", "plane", "truth_correct"])
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


def healing(keypoints):
    """Durations of the wrong key-point episodes (keypoints.csv): (count, median, share within
    HEAL_ITERATIONS, max)."""
    d = np.array([e[3] for e in wrong_episodes(keypoints)])
    if len(d) == 0:
        return 0, float("nan"), float("nan"), 0
    return len(d), float(np.median(d)), float(np.mean(d <= HEAL_ITERATIONS)), int(d.max())


EVENT_JUMP = 0.3  # a map-error event: the summed e_ends rises by this much in one iteration, units [R]


EVENT_SETTLED = 0.25  # ... and it has healed once it is back within this share of the jump [R]


EVENT_FROM = 5  # the first iterations build the map from nothing: no events there


def map_error_events(iterations):
    """Iterations where a plane joins the map with a large error (thesis Figs 76-79: a plane just come
    into view, compared over a tiny interval), from relative_plane/iterations.csv's iteration, map_error
    and planes_in_map: [(iteration, jump, iterations until healed or None, a plane joined the map)]."""
    d = arrays(iterations, ["iteration", "map_error", "planes_in_map"])
    e, n = d["map_error"], d["planes_in_map"]
    it = d["iteration"]
    events = []
    for k in range(max(1, EVENT_FROM), len(e)):
        jump = e[k] - e[k - 1]
        if not jump >= EVENT_JUMP:
            continue
        healed = next((h for h in range(1, len(e) - k) if e[k + h] - e[k - 1] <= EVENT_SETTLED * jump), None)
        events.append((int(it[k]), float(jump), healed, bool(n[k] > n[k - 1])))
    return events


def event_healing(iterations):
    """(events, healed within HEAL_ITERATIONS, never healed, median iterations to heal)."""
    ev = map_error_events(iterations)
    times = [h for _, _, h, _ in ev if h is not None]
    return (len(ev), sum(h <= HEAL_ITERATIONS for h in times), sum(h is None for _, _, h, _ in ev),
            float(np.median(times)) if times else float("nan"))


def largest_healed_event(iterations):
    """The largest event that healed within HEAL_ITERATIONS (else the largest), as its index in
    iterations.csv: (the table's columns, index, event or None)."""
    ev = sorted(map_error_events(iterations), key=lambda x: (x[2] is None or x[2] > HEAL_ITERATIONS, -x[1]))
    d = arrays(iterations, ["iteration", "map_error", "mean_map_error", "planes_in_map", "kp_wrong"])
    k = int(np.nonzero(d["iteration"] == ev[0][0])[0][0]) if ev else int(np.argmax(d["map_error"]))
    return d, k, (ev[0] if ev else None)


def wall_table(planes):
    """planes.csv's mapped planes: {true_wall: [(len_ratio, e_ends), ...]} (a wall with two planes has two)."""
    p = arrays(planes, ["true_wall", "len_ratio", "e_ends"])
    out = {}
    for w, r, e in zip(p["true_wall"], p["len_ratio"], p["e_ends"]):
        if np.isfinite(w):
            out.setdefault(int(w), []).append((r, e))
    return out


def under_sized(planes):
    """Walls whose largest mapped plane (planes.csv) is under UNDER_SIZED of their length: [(wall, len_ratio)]."""
    return [(w, max(r for r, _ in v)) for w, v in sorted(wall_table(planes).items())
            if max(r for r, _ in v) < UNDER_SIZED]


def plane_map_errors(planes):
    """How a planes.csv map lies on the true walls: (largest distance of a plane off its wall's line, largest
    angle off it in degrees, mean distance of the ends over the walls). The ends count only each wall's
    plane with the most observations: a wall first seen in part is kept apart as a second plane on purpose
    (thesis Fig 90), and that piece's ends would count a deliberate duplicate as an error."""
    p = arrays(planes, ["true_wall", "e_ends", "e_ang_deg", "e_perp", "n_obs"])
    if len(p["true_wall"]) == 0:
        return float("nan"), float("nan"), float("nan")
    best = {}
    for wall, ends, n in zip(p["true_wall"], p["e_ends"], p["n_obs"]):
        if wall not in best or n > best[wall][1]:
            best[wall] = (ends, n)
    return (float(np.max(np.abs(p["e_perp"]))), float(np.max(np.abs(p["e_ang_deg"]))),
            float(np.mean([e for e, _ in best.values()])))


def group_counts(runs):
    """{variant: groups at the end} of the E10 sweep; runs: [(variant, iterations table of its first seed)]."""
    return {name: int(arrays(frame, ["groups"])["groups"][-1]) for name, frame in runs}


REVISIT_AWAY, REVISIT_BACK = 5.0, 1.0  # units: the robot has been this far from its start, and is back this close


def revisit_time(r):
    """Summed step time (ms) over the revisit phase (thesis 4.3.5: "when the robot visits a previously
    viewed area"): from the first iteration at which the true robot is back within REVISIT_BACK of its
    start after having been REVISIT_AWAY from it, to the end. (total ms, first iteration), or None when
    the run ends before the robot returns (a shortened run). Uses r.truth_path and r.iterations."""
    path = planar_track(r.truth_path)
    gone = np.hypot(path["x"] - path["x"][0], path["z"] - path["z"][0])
    away = np.nonzero(gone >= REVISIT_AWAY)[0]
    back = np.nonzero((gone <= REVISIT_BACK) & (np.arange(len(gone)) > (away[0] if len(away) else len(gone))))[0]
    if len(back) == 0:
        return None
    start = path["iteration"][back[0]]
    d = arrays(r.iterations, ["iteration", "runtime_ms"])
    return float(np.sum(d["runtime_ms"][d["iteration"] >= start])), int(start)


def size_mismatches(edges):
    """edges.csv: the edges whose lengths differ from the planes' canonical sizes (Rule 28's L_e vs L*)."""
    e = arrays(edges, ["valid", "length1", "length2", "canonical1", "canonical2"])
    gap = np.maximum(np.abs(e["length1"] - e["canonical1"]), np.abs(e["length2"] - e["canonical2"]))
    return int(np.sum((e["valid"] == 1) & (gap > 0.02))), len(gap), float(np.max(gap, initial=0.0))


OFF_LINE = 1e-6  # noise-free: a plane further than this from its wall's line is misplaced ('s bound)


def misplaced(planes):
    """Mapped planes (planes.csv) off their wall's line (e_perp above OFF_LINE): [(wall, e_perp)]; the
    measure of a placement error that does not count walls never seen whole (e_ends does)."""
    p = arrays(planes, ["true_wall", "e_perp"])
    return [(int(w), float(e)) for w, e in zip(p["true_wall"], p["e_perp"]) if np.isfinite(w) and e > OFF_LINE]


def collinear_run(r):
    """When the run's position error first passes 1e-6 (the pose exact until then; the map error also
    counts walls not yet seen whole), and the tied (Rule 15) key-point claims and chain edges. Uses
    r.iterations, r.keypoints, r.edges."""
    d = arrays(r.iterations, ["iteration", "map_error", "position_error", "pose_valid", "kp_wrong"])
    bad = np.nonzero(d["position_error"] > 1e-6)[0]
    k = arrays(r.keypoints, ["iteration", "ambiguous"])
    e = arrays(r.edges, ["ambiguous"])
    return d, (int(d["iteration"][bad[0]]) if len(bad) else None), int(np.sum(k["ambiguous"] == 1)), \
        int(np.sum(e["ambiguous"] == 1))


def runtime_by_size(runs):
    """{loops: (median ms, median ms of the first and last tenth, RltPlanes at the end, iterations)};
    runs: [(loops, iterations table of its first seed)]."""
    out = {}
    for loops, frame in runs:
        d = arrays(frame, ["runtime_ms", "rlt_planes"])
        n = len(d["runtime_ms"])
        tenth = max(1, n // 10)
        out[int(float(loops))] = (float(np.median(d["runtime_ms"])), float(np.median(d["runtime_ms"][:tenth])),
                                  float(np.median(d["runtime_ms"][-tenth:])), int(d["rlt_planes"][-1]), n)
    return dict(sorted(out.items()))


def wrap_deg(angle):
    return (np.asarray(angle) + 180) % 360 - 180


def wall_lengths(walls):
    """{wall id: length} of ground_truth_walls.csv."""
    w = arrays(walls, ["id", "length"])
    return {int(i): float(n) for i, n in zip(w["id"], w["length"])}


def mm_episodes(r):
    """Each motion model of a run (consecutive iterations with mm_active on one mm_plane), as a dict: first
    and last iteration, plane, its true wall and the wall's length, and the tracked length
    (mm_s_max − mm_s_min) at its first and last iteration. Uses r.iterations, r.planes, r.walls."""
    d = arrays(r.iterations, ["iteration", "mm_active", "mm_plane", "mm_s_min", "mm_s_max"])
    p = arrays(r.planes, ["id", "true_wall"])
    wall_of = {int(i): int(w) for i, w in zip(p["id"], p["true_wall"]) if np.isfinite(w)}
    lengths = wall_lengths(r.walls)
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


def no_motion_model(iterations):
    return rp.DataError(f"{source(iterations)}: column mm_active: no motion model")


def observed_wall(r, wall):
    """One wall's observations (r.observations, robot frame, the robot at the origin): {iteration,
    length in view, range of its farther end, heading (true, degrees; r.truth_path)}."""
    o = arrays(r.observations, OBSERVED)
    sel = o["true_wall"] == wall
    it = o["iteration"][sel]
    path = planar_track(r.truth_path)
    heading = dict(zip(path["iteration"], path["psi_deg"]))
    return {"iteration": it,
            "length": np.hypot(o["kp2_x"][sel] - o["kp1_x"][sel], o["kp2_z"][sel] - o["kp1_z"][sel]),
            "range": np.maximum(np.hypot(o["kp1_x"][sel], o["kp1_z"][sel]), np.hypot(o["kp2_x"][sel], o["kp2_z"][sel])),
            "psi_deg": np.array([heading.get(i, np.nan) for i in it])}


def turn_iterations(truth_path):
    """The iterations of the run's first turn in place (ground_truth_path.tum): the true heading changes,
    the position does not."""
    path = planar_track(truth_path)
    turning = np.abs(wrap_deg(np.diff(path["psi_deg"]))) > 1e-6
    first = np.nonzero(turning)[0]
    if len(first) == 0:
        raise rp.DataError(f"{source(truth_path)}: the robot never turns")
    last = first[0]
    while last + 1 < len(turning) and turning[last + 1]:
        last += 1
    return path["iteration"][first[0]:last + 2]


def mapped_length(planes, wall):
    """The longest mapped plane of a wall (planes.csv), NaN when none is mapped."""
    p = arrays(planes, ["true_wall", "length"])
    lengths = p["length"][(p["true_wall"] == wall) & np.isfinite(p["length"])]
    return float(lengths.max()) if len(lengths) else float("nan")


def first_corner(r):
    """The first motion model of an E1 run against the truth: its episode, how far the robot was from the
    turn when it started (units of path), and the true heading when it ended."""
    episodes = mm_episodes(r)
    if not episodes:
        raise no_motion_model(r.iterations)
    e = episodes[0]
    path = planar_track(r.truth_path)
    turn = turn_iterations(r.truth_path)
    at = {int(i): k for k, i in enumerate(path["iteration"])}
    k0, k1 = at[e["first"]], at[int(turn[0])]
    before = float(np.sum(np.hypot(np.diff(path["x"][k0:k1 + 1]), np.diff(path["z"][k0:k1 + 1]))))
    return e, before, float(path["psi_deg"][at[e["last"]]] - path["psi_deg"][k1])


def key_points_by_phase(iterations):
    """(wrong, checked) key-point claims inside and outside the motion models: {"in": (...), "out": (...)},
    from relative_plane/iterations.csv."""
    d = arrays(iterations, ["kp_checked", "kp_wrong", "mm_active"])
    mm = d["mm_active"] == 1
    return {"in": (int(np.sum(d["kp_wrong"][mm])), int(np.sum(d["kp_checked"][mm]))),
            "out": (int(np.sum(d["kp_wrong"][~mm])), int(np.sum(d["kp_checked"][~mm])))}


def grown_lengths(variants):
    """{variant: (tracked length / true length at each motion model's end, the grown planes' mapped
    len_ratio, seeds)} over every seed of a planar sweep; variants: [(variant, [r per seed])]."""
    out = {}
    for name, seeds in variants:
        tracked, mapped = [], []
        for r in seeds:
            p = arrays(r.planes, ["id", "len_ratio"])
            ratio = {int(i): x for i, x in zip(p["id"], p["len_ratio"])}
            for e in mm_episodes(r):
                tracked.append(e["length"] / e["true_length"])
                mapped.append(ratio.get(e["plane"], float("nan")))
        out[name] = (np.array(tracked), np.array(mapped), len(seeds))
    return out


GROWN_TOP = 1.04  # Fig 88's y axis ends here ("a little past its true size"); ratios beyond are written


def grown_text(name, values):
    tracked, mapped, seeds = values
    over = tracked[tracked > 1.001]
    return (f"{name}: {len(tracked)} motion models over {seeds} seed(s), tracked length / true median "
            f"{np.nanmedian(tracked):.4f}, max {np.nanmax(tracked):.4f}, {len(over)} past the true size by over "
            f"0.1 %; grown planes' mapped len_ratio median {np.nanmedian(mapped):.4f}, max {np.nanmax(mapped):.4f}")


def run_frustum(manifest, where="manifest.json"):
    """(frustum preset, shape) of a planar run from its manifest's scenario."""
    try:
        planar = manifest["scenario"]["planar"]
        return planar["frustum"], planar["frustum_shape"]
    except (KeyError, TypeError):
        raise rp.DataError(f"{where}: no scenario.planar.frustum / frustum_shape") from None


def end_wall_turn(r):
    """The wall seen in most iterations of the first turn (the corner's end wall), its observations in
    the turn, and its mapped length."""
    turn = turn_iterations(r.truth_path)
    o = arrays(r.observations, ["iteration", "true_wall"])
    walls, counts = np.unique(o["true_wall"][np.isin(o["iteration"], turn)], return_counts=True)
    if len(walls) == 0:
        raise rp.DataError(f"{source(r.observations)}: no wall seen in the turn")
    wall = int(walls[np.argmax(counts)])
    seen = observed_wall(r, wall)
    sel = np.isin(seen["iteration"], turn)
    return wall, {k: v[sel] for k, v in seen.items()}, mapped_length(r.planes, wall)


def frustum_turns(variants):
    """{variant: (frustum, shape, wall, observations in the turn, mapped length, true length)};
    variants: [(variant, r of its first seed)]."""
    out = {}
    for name, r in variants:
        wall, seen, mapped = end_wall_turn(r)
        out[name] = (*run_frustum(r.manifest, manifest_path(r)), wall, seen, mapped, wall_lengths(r.walls)[wall])
    return out


def motion_model_exits(r):
    """(motion models, how many ended in a group created before they started, groups at the end). Uses
    r.iterations, r.groups and what mm_episodes does."""
    d = arrays(r.iterations, ["iteration", "current_group"])
    g = arrays(r.groups, ["group_id", "created_iter"])
    created = dict(zip(g["group_id"].astype(int), g["created_iter"]))
    episodes = mm_episodes(r)
    back = 0
    for e in episodes:
        after = np.nonzero((d["iteration"] > e["last"]) & np.isfinite(d["current_group"]))[0]
        back += len(after) > 0 and created.get(int(d["current_group"][after[0]]), e["first"]) < e["first"]
    return len(episodes), back, len(g["group_id"])


def one_plane_iteration(r):
    """The middle iteration of the first stretch of the last loop in which the motion model is active
    and a single plane is in view. Uses r.manifest and r.iterations."""
    loops, n = run_loops(r.manifest, manifest_path(r))
    d = arrays(r.iterations, ["iteration", "mm_active", "visible_planes"])
    sel = np.nonzero((d["iteration"] >= n * (loops - 1) / max(loops, 1)) & (d["mm_active"] == 1)
                     & (d["visible_planes"] == 1))[0]
    if len(sel) == 0:
        raise rp.DataError(f"{source(r.iterations)}: no motion model with one plane in view on the last loop")
    stretch = sel[:np.argmax(np.diff(np.append(sel, sel[-1] + 2)) > 1) + 1]
    return int(d["iteration"][stretch[len(stretch) // 2]]), int(d["iteration"][stretch[0]]), \
        int(d["iteration"][stretch[-1]])


def first_seen_far(observations):
    """The wall first seen from farthest away (plane_observations.csv): (wall, iteration, distance of its
    nearer observed end)."""
    o = arrays(observations, OBSERVED)
    best = None
    for wall in sorted(set(o["true_wall"]) - {-1}):
        k = int(np.nonzero(o["true_wall"] == wall)[0][0])
        near = min(np.hypot(o["kp1_x"][k], o["kp1_z"][k]), np.hypot(o["kp2_x"][k], o["kp2_z"][k]))
        if best is None or near > best[2]:
            best = (int(wall), int(o["iteration"][k]), float(near))
    if best is None:
        raise rp.DataError(f"{source(observations)}: no wall seen")
    return best
