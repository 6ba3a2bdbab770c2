"""load_run: one `relslam run` folder (also `victoria-park` runs and each cell of a sweep) as pandas
data frames.

A run folder holds manifest.json, summary.csv (one row per algorithm, plus ratio rows when both
relative_point and ekf6d ran) and one sub-folder per algorithm with iterations.csv,
trajectory.tum and its map: landmarks.csv (point algorithms) or planes.csv (relative_plane). A
simulated run adds the truth: ground_truth_path.tum with ground_truth_landmarks.csv (points) or
ground_truth_walls.csv (planar). Every other CSV in the folder is read on demand by `table`.
"""
from dataclasses import dataclass, field
from pathlib import Path

from .files import DataError, read_csv, read_json, read_tum, scenario_name

# Columns the plots rely on; checked to be present (required) or numbers (numeric, when present),
# so a damaged file fails here, naming itself, instead of in the middle of a figure.
ITERATION_NUMBERS = ("iteration", "runtime_ms", "landmark_error", "mean_landmark_error", "map_error",
                     "mean_map_error", "position_error", "heading_error_deg", "landmarks_in_map", "planes_in_map")
SUMMARY_REQUIRED = ("algorithm", "status")
RATIO_STATUS = "ratio"  # summary.csv's relative_point/ekf6d row: quotients, not a run of its own


def _optional(path, reader, **kwargs):
    """The file read by `reader`, or None when it does not exist (a damaged one still raises)."""
    return reader(path, **kwargs) if path.is_file() else None


@dataclass
class AlgorithmRun:
    """One algorithm's sub-folder: per-iteration scores, estimated trajectory and map."""

    name: str
    folder: Path
    iterations: object  # DataFrame of iterations.csv, one row per iteration
    trajectory: object = None  # DataFrame t, x, y, z, qx, qy, qz, qw of trajectory.tum
    landmarks: object = None  # DataFrame of landmarks.csv (point algorithms)
    planes: object = None  # DataFrame of planes.csv (relative_plane)

    def table(self, name):
        """Any other CSV of the sub-folder (e.g. 'groups.csv', 'edges.csv'), checked."""
        return read_csv(self.folder / name)


@dataclass
class Run:
    """A run folder. `algorithms` is keyed by algorithm name in summary.csv's order."""

    folder: Path
    manifest: dict
    summary: object  # DataFrame of summary.csv, ratio rows included
    algorithms: dict = field(default_factory=dict)
    truth_path: object = None  # DataFrame of ground_truth_path.tum
    truth_landmarks: object = None  # DataFrame of ground_truth_landmarks.csv (id, x, y, z, dynamic)
    truth_walls: object = None  # DataFrame of ground_truth_walls.csv (planar runs)

    @property
    def name(self):
        """The scenario's name (manifest.json), else the folder's name."""
        return scenario_name(self.manifest, self.folder)

    @property
    def ratios(self):
        """summary.csv's ratio rows (relative_point/ekf6d), empty when only one algorithm ran."""
        return self.summary[self.summary["status"] == RATIO_STATUS]

    def table(self, name):
        """Any other CSV of the run folder (e.g. 'sim_iterations.csv', 'gps_comparison.csv')."""
        return read_csv(self.folder / name)

    def tum(self, name):
        """Any other TUM trajectory of the run folder (e.g. 'gps.tum' of a Victoria Park run)."""
        return read_tum(self.folder / name)


def _load_algorithm(folder, name, finished):
    """The sub-folder of one algorithm. A run that finished must have its iterations.csv; one
    that failed may stop before writing it, and then only what exists is read."""
    sub = folder / name
    iterations_path = sub / "iterations.csv"
    if not finished and not iterations_path.is_file():
        return None
    return AlgorithmRun(
        name=name, folder=sub,
        iterations=read_csv(iterations_path, required=("iteration",), numeric=ITERATION_NUMBERS),
        trajectory=_optional(sub / "trajectory.tum", read_tum),
        landmarks=_optional(sub / "landmarks.csv", read_csv, required=("x", "y", "z"), numeric=("x", "y", "z")),
        planes=_optional(sub / "planes.csv", read_csv, numeric=("kp1_x", "kp1_z", "kp2_x", "kp2_z")))


def load_run(folder):
    """Reads a run folder written by `relslam run` (or `victoria-park`, or a sweep's seed-N cell).

    Raises DataError ("PATH: PROBLEM") when a file it needs is missing or damaged: no folder, no
    manifest.json or summary.csv, a finished algorithm without iterations.csv, a cut or
    malformed CSV or TUM file."""
    folder = Path(folder)
    if not folder.is_dir():
        raise DataError(folder, "not a folder (expected a run folder written by relslam run)")
    if (folder / "sweep.csv").is_file() and not (folder / "summary.csv").is_file():
        raise DataError(folder / "summary.csv", "file not found: this is a sweep folder (load_sweep reads it)")
    manifest = read_json(folder / "manifest.json")
    summary = read_csv(folder / "summary.csv", required=SUMMARY_REQUIRED)
    run = Run(folder=folder, manifest=manifest, summary=summary)
    for row in summary.itertuples(index=False):
        if row.status == RATIO_STATUS:
            continue
        algorithm = _load_algorithm(folder, str(row.algorithm), finished=row.status == "ok")
        if algorithm is not None:
            run.algorithms[algorithm.name] = algorithm
    run.truth_path = _optional(folder / "ground_truth_path.tum", read_tum)
    run.truth_landmarks = _optional(folder / "ground_truth_landmarks.csv", read_csv, required=("x", "y", "z"),
                                    numeric=("x", "y", "z"))
    run.truth_walls = _optional(folder / "ground_truth_walls.csv", read_csv, required=("a_x", "a_z", "b_x", "b_z"),
                                numeric=("a_x", "a_z", "b_x", "b_z"))
    return run
