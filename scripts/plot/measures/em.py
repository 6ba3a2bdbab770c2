"""Chapter 5 (EM plane extraction) measures: the numbers its figures show and claims.py checks.
Pure functions on the tables load.py reads (point_frames.csv, plane_observations.csv, em_frames.csv,
em_compare.csv, the true path and walls)."""
import numpy as np

from measures.common import arrays, source
from measures.planes import planar_rotation, planar_track
import relslam_plot as rp


EXTRACTORS = ("em2", "em1", "ransac_open3d")


def point_frame(frames, iteration=None):
    """(iteration, points (n x 3, robot frame), true wall ids) of point_frames.csv (output.point_frames):
    the given iteration, else the last one written."""
    t = arrays(frames, ["iteration", "x", "y", "z", "true_wall"])
    if len(t["iteration"]) == 0:
        raise rp.DataError(f"{source(frames)}: no rows")
    k = t["iteration"].max() if iteration is None else iteration
    sel = t["iteration"] == k
    if not sel.any():
        raise rp.DataError(f"{source(frames)}: column iteration: no iteration {k:.0f}")
    return int(k), np.column_stack([t["x"][sel], t["y"][sel], t["z"][sel]]), t["true_wall"][sel].astype(int)


def extracted_planes(observations, iteration):
    """The extracted planes of one iteration (plane_observations.csv: the extractor's output, robot
    frame) as [(a, b, true wall)]."""
    o = arrays(observations, ["iteration", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z"])
    sel = np.nonzero(o["iteration"] == iteration)[0]
    return [(np.array([o["kp1_x"][k], o["kp1_z"][k]]), np.array([o["kp2_x"][k], o["kp2_z"][k]]), int(o["true_wall"][k]))
            for k in sel]


def robot_pose(truth_path, iteration):
    """(translation (x, z), heading rad) of the true pose (ground_truth_path.tum) at an iteration."""
    path = planar_track(truth_path)
    rows = np.nonzero(path["iteration"] == iteration)[0]
    if len(rows) == 0:
        raise rp.DataError(f"{source(truth_path)}: no iteration {iteration}")
    return np.array([path["x"][rows[0]], path["z"][rows[0]]]), np.radians(path["psi_deg"][rows[0]])


def visible_pieces(truth_path, walls, iteration, points, ids):
    """{wall id: (a, b)} in the robot frame: each true wall (ground_truth_walls.csv) cut to the span of its
    points seen at the iteration (the "planes viewed by the robot at the time", thesis 5.2)."""
    t, psi = robot_pose(truth_path, iteration)
    w = arrays(walls, ["id", "a_x", "a_z", "b_x", "b_z"])
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


def em_frame_score(em_frames, iteration):
    """em_frames.csv's row of an iteration as {column: value}."""
    names = ["iteration", "n_points", "n_planes", "n_true_visible", "recall", "precision"]
    t = arrays(em_frames, names)
    sel = np.nonzero(t["iteration"] == iteration)[0]
    if len(sel) == 0:
        raise rp.DataError(f"{source(em_frames)}: column iteration: no iteration {iteration}")
    return {c: t[c][sel[0]] for c in names}


def demo_times(runs):
    """{variant: (EM ms per iteration, Relative Plane ms per iteration)} of the E27 sweep; runs: {variant:
    relative_plane iterations table}."""
    out = {}
    for variant, frame in runs.items():
        d = arrays(frame, ["t_extract_ms", "runtime_ms"])
        out[variant] = (d["t_extract_ms"], d["runtime_ms"])
    return out


def compare_frames(em_compare):
    """em_compare.csv's ms and scores per extractor present: (iterations, {extractor: {column: values}})."""
    present = [e for e in EXTRACTORS if f"ms_{e}" in em_compare]
    if not present:
        raise rp.DataError(f"{source(em_compare)}: no ms_<extractor> column")
    names = [f"{c}_{e}" for e in present for c in ("ms", "recall", "precision", "n_planes", "mean_normal_err_deg")]
    t = arrays(em_compare, ["iteration", *names])
    return t["iteration"], {e: {c: t[f"{c}_{e}"] for c in ("ms", "recall", "precision", "n_planes",
                                                            "mean_normal_err_deg")} for e in present}
