"""Chapter 5 (EM plane extraction) measures: the numbers its figures show and claims.py checks."""
import os

import numpy as np

from measures.common import PLANE, iterations, sweep_runs
from measures.planes import planar_rotation, true_path, true_walls
import relslam_plot as rp


EXTRACTORS = ("em2", "em1", "ransac_open3d")


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


def bench_scores(run):
    return rp.read_table(os.path.join(run, "bench.csv"), ["scene", "variant", "extractor", "seed", "recall",
                                                           "precision", "n_planes", "noise", "ms"],
                         text=("scene", "variant", "extractor"))


def sweep_cell(sweep, variant):
    """The run folder of one variant of a planar sweep (its first seed)."""
    for value, folder in sweep_runs(sweep, "variant", PLANE):
        if value == variant:
            return folder
    raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {variant}")


def demo_times(sweep):
    """{variant: (EM ms per iteration, Relative Plane ms per iteration)} of the E27 sweep."""
    out = {}
    for variant, folder in sweep_runs(sweep, "variant", PLANE):
        d = iterations(folder, ["t_extract_ms", "runtime_ms"], PLANE)
        out[variant] = (d["t_extract_ms"], d["runtime_ms"])
    return out


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
