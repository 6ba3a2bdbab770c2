"""The report's loader: every file of a run or sweep folder that a figure or a measure needs, read by
relslam_data's checked readers (python/relslam_data, the loader plot_run.py and your own scripts use).

Loading stops here: the measures (measures/) are pure functions on the data frames these return, and
the figures (chapter4.py ... chapter6.py) draw what the measures compute. A missing or damaged file
raises relslam_plot.DataError naming it; each frame remembers its file in frame.attrs["path"], so a
measure that finds a column or row missing names the file too (measures.common.arrays).
"""
import os

import relslam_plot as rp  # first: it puts python/ (relslam_data) on the path
import relslam_data  # noqa: E402
from measures.common import ALG, PLANE, arrays, seed_means
from measures.planes import planar_track

# Columns that hold text even where it looks like a number (a list of plane ids "3", a sweep axis's
# "0.10"): read as written, so labels and lists stay as relslam wrote them.
STRINGS = {"summary.csv": ("algorithm", "status"), "groups.csv": ("planes",), "links.csv": ("linking_planes",),
           "bench.csv": ("scene", "variant", "extractor")}


def _checked(read, path, *args, **kwargs):
    try:
        frame = read(path, *args, **kwargs)
    except relslam_data.DataError as e:
        raise rp.DataError(str(e)) from None
    frame.attrs["path"] = str(path)
    return frame


def table(*parts, strings=None):
    """The CSV file os.path.join(*parts) as a DataFrame (its text columns by file name: STRINGS)."""
    path = os.path.join(*parts)
    return _checked(relslam_data.read_csv, path,
                    strings=STRINGS.get(os.path.basename(path), ()) if strings is None else strings)


def tum(*parts):
    """A TUM trajectory (t, x, y, z, qx, qy, qz, qw) as a DataFrame."""
    return _checked(relslam_data.read_tum, os.path.join(*parts))


def read_json(path):
    try:
        return relslam_data.read_json(path)
    except relslam_data.DataError as e:
        raise rp.DataError(str(e)) from None


def manifest(run):
    return read_json(os.path.join(run, "manifest.json"))


def plane_file(run, name):
    """One of Relative Plane's files of a planar run (planes.csv, groups.csv, keypoints.csv, ...)."""
    return table(run, PLANE, name)


def iteration_frame(run, algorithm=ALG):
    """One algorithm's iterations.csv; an empty file is an error."""
    frame = table(run, algorithm, "iterations.csv")
    if len(frame) == 0:
        raise rp.DataError(f"{frame.attrs['path']}: no rows")
    return frame


def iterations(run, columns, algorithm=ALG):
    """One algorithm's iterations.csv columns (plus `iteration`) as {column: numpy array}, for drawing."""
    return arrays(iteration_frame(run, algorithm), ["iteration", *columns])


def truth_walls(run):
    return table(run, "ground_truth_walls.csv")


def truth_path(run):
    return tum(run, "ground_truth_path.tum")


def observations(run):
    """plane_observations.csv: each extracted plane of each iteration, robot frame, with its true wall."""
    return table(run, "plane_observations.csv")


def summary(run):
    return table(run, "summary.csv")


def algorithms(run):
    """Algorithms of a run, in summary.csv order (the relative_point/ekf6d row holds ratios)."""
    t = arrays(summary(run), ["algorithm", "status"], strings=("algorithm", "status"))
    return [a for a, s in zip(t["algorithm"], t["status"]) if s != "ratio"]


def sweep_table(sweep, axes):
    """sweep.csv with its axes, folder and algorithm as text."""
    return table(sweep, "sweep.csv", strings=(*axes, "folder", "algorithm"))


def sweep_runs(sweep, axis, algorithm=ALG):
    """[(axis value, run folder)] of a `relslam sweep` folder, one algorithm's rows, sweep order."""
    t = arrays(sweep_table(sweep, (axis,)), [axis, "folder", "algorithm"], strings=(axis, "folder", "algorithm"))
    runs = [(v, os.path.join(sweep, f)) for v, f, a in zip(t[axis], t["folder"], t["algorithm"]) if a == algorithm]
    if not runs:
        raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column algorithm: no {algorithm} rows")
    return runs


def sweep_series(sweep, columns, axis="variant", algorithm=ALG):
    """{axis value: {column: per-iteration mean over the seeds}} (seeds cut to the shortest run)."""
    grouped = {}
    for value, folder in sweep_runs(sweep, axis, algorithm):
        grouped.setdefault(value, []).append(iterations(folder, columns, algorithm))
    return {value: seed_means(runs, ["iteration", *columns]) for value, runs in grouped.items()}


def plane_sweep(sweep, axes=("variant",)):
    """[(axis values tuple, [run folders over the seeds])] of a planar sweep, in sweep.csv order."""
    t = arrays(sweep_table(sweep, axes), [*axes, "folder", "algorithm"], strings=(*axes, "folder", "algorithm"))
    out = {}
    for k in range(len(t["folder"])):
        if t["algorithm"][k] == PLANE:
            out.setdefault(tuple(t[a][k] for a in axes), []).append(os.path.join(sweep, t["folder"][k]))
    if not out:
        raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column algorithm: no {PLANE} rows")
    return list(out.items())


def variant_folder_of(sweep, name):
    """The first seed's folder of variant `name` of a planar sweep."""
    for (value,), folders in plane_sweep(sweep):
        if value == name:
            return folders[0]
    raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {name!r}")


def first_seed(sweep):
    """The first run folder of a planar sweep (also of one without variants, over seeds only)."""
    return plane_sweep(sweep, ("seed",))[0][1][0]


def sweep_cell(sweep, variant):
    """The run folder of one variant of a planar sweep (its first seed)."""
    for value, folder in sweep_runs(sweep, "variant", PLANE):
        if value == variant:
            return folder
    raise rp.DataError(f"{os.path.join(sweep, 'sweep.csv')}: column variant: no {variant}")


def density_runs(sweep):
    """[(density, iterations table)] of a density sweep, one per seed (measures.points.density_table)."""
    return [(float(value), iteration_frame(folder)) for value, folder in sweep_runs(sweep, "sim.density")]


def vp_landmarks(run, algorithm, name="landmarks_gps_frame.csv"):
    """A Victoria Park run's landmarks in the GPS frame as {x, y}, for drawing."""
    return arrays(table(run, algorithm, name), ["x", "y"])


def bench_scores(run):
    """bench.csv of an extractor benchmark as {column: array}."""
    return arrays(table(run, "bench.csv"), ["scene", "variant", "extractor", "seed", "recall", "precision",
                                            "n_planes", "noise", "ms"], strings=("scene", "variant", "extractor"))


def variant_iterations(sweep, algorithm=PLANE):
    """{variant: iterations table of its first seed} of a sweep."""
    return {variant: iteration_frame(folder, algorithm) for variant, folder in sweep_runs(sweep, "variant", algorithm)}


class PlanarRun:
    """The tables of a planar run folder that measures.planes takes as `r`, each read on first use and
    kept: iterations (relative_plane/iterations.csv), planes, groups, keypoints, edges, pairs,
    pair_sigma (relative_plane/*.csv), observations (plane_observations.csv), truth_path
    (ground_truth_path.tum), walls (ground_truth_walls.csv), summary, manifest (a dict)."""

    FILES = {"iterations": (PLANE, "iterations.csv"), "planes": (PLANE, "planes.csv"),
             "groups": (PLANE, "groups.csv"), "keypoints": (PLANE, "keypoints.csv"), "edges": (PLANE, "edges.csv"),
             "pairs": (PLANE, "pairs.csv"), "pair_sigma": (PLANE, "pair_sigma.csv"),
             "observations": ("plane_observations.csv",), "walls": ("ground_truth_walls.csv",),
             "summary": ("summary.csv",)}

    def __init__(self, folder):
        self.folder = folder
        self.manifest_path = os.path.join(folder, "manifest.json")

    def __getattr__(self, name):  # only called for attributes not yet set: read the file once
        if name == "truth_path":
            value = truth_path(self.folder)
        elif name == "manifest":
            value = read_json(self.manifest_path)
        elif name in PlanarRun.FILES:
            value = table(self.folder, *PlanarRun.FILES[name])
        else:
            raise AttributeError(name)
        setattr(self, name, value)
        return value


def plane_table(run, name, columns, strings=()):
    """Columns of one of Relative Plane's files as {column: array}, for drawing."""
    return arrays(plane_file(run, name), columns, strings=strings)


def true_walls(run):
    """ground_truth_walls.csv's ends as {column: array}, for drawing."""
    return arrays(truth_walls(run), ["id", "a_x", "a_z", "b_x", "b_z"])


def true_path(run):
    """{iteration, x, z, psi_deg} of the true path, for drawing."""
    return planar_track(truth_path(run))


def plane_frames(sweep, axes=("variant",)):
    """[(axis values, [iterations table per seed])] of a planar sweep (measures.planes.interval_mode_errors)."""
    return [(key, [iteration_frame(f, PLANE) for f in folders]) for key, folders in plane_sweep(sweep, axes)]


def planar_variants(sweep, axes=("variant",)):
    """[(variant, [PlanarRun per seed])] of a planar sweep."""
    return [(key[0] if len(key) == 1 else key, [PlanarRun(f) for f in folders])
            for key, folders in plane_sweep(sweep, axes)]


def first_seed_iterations(sweep, axis="variant"):
    """[(axis value, relative_plane iterations table of its first seed)] of a planar sweep."""
    return [(value, iteration_frame(folders[0], PLANE)) for (value,), folders in plane_sweep(sweep, (axis,))]


def first_seeds(sweep):
    """[(variant, PlanarRun of its first seed)] of a planar sweep."""
    return [(name, seeds[0]) for name, seeds in planar_variants(sweep)]
