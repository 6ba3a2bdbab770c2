"""load_sweep: one `relslam sweep` folder as pandas data frames.

A sweep folder holds sweep.csv (one row per run and algorithm: the axis values, seed, folder,
status and final scores), aggregate.csv (per combination of axis values and algorithm: runs, ok,
not_ok_seeds and for each score its _mean, _std and _ci95 over the seeds), plan.json (the axes
and cells) and manifest.json, plus one run folder per cell, read on demand by `Sweep.run`.
"""
from dataclasses import dataclass
from pathlib import Path

from .files import DataError, read_csv, read_json, scenario_name
from .run import load_run

STATISTICS = ("_mean", "_std", "_ci95")


@dataclass
class Sweep:
    """A sweep folder. `axes` are the swept keys in the order of aggregate.csv's columns (the
    columns before `algorithm`), e.g. ['sim.noise_sigma'] or ['variant', 'planar.noise.model']."""

    folder: Path
    manifest: dict
    plan: object  # plan.json as Python objects, or None for a sweep written before plan.json existed
    runs: object  # DataFrame of sweep.csv
    aggregate: object  # DataFrame of aggregate.csv
    axes: list

    @property
    def metrics(self):
        """The scores aggregate.csv gives a mean and a 95 % interval of, in column order."""
        columns = set(self.aggregate.columns)
        return [c[:-len("_mean")] for c in self.aggregate.columns
                if c.endswith("_mean") and c[:-len("_mean")] + "_ci95" in columns]

    @property
    def name(self):
        """The scenario's name (manifest.json), else the folder's name."""
        return scenario_name(self.manifest, self.folder)

    def run(self, cell):
        """The run folder of one cell, by its `folder` value in sweep.csv
        (e.g. 'sim.noise_sigma=0.1/seed-2') or by a row of `runs`."""
        relative = cell["folder"] if hasattr(cell, "__getitem__") and not isinstance(cell, str) else cell
        return load_run(self.folder / relative)


def _axes(aggregate, path):
    """aggregate.csv's axis columns: those before `algorithm`, which the table writer puts first."""
    columns = list(aggregate.columns)
    if "algorithm" not in columns:
        raise DataError(path, "missing column(s) algorithm")
    return columns[:columns.index("algorithm")]


def load_sweep(folder):
    """Reads a sweep folder written by `relslam sweep` (or `sweep --aggregate`).

    Raises DataError ("PATH: PROBLEM") when sweep.csv, aggregate.csv or manifest.json is missing
    or damaged, when aggregate.csv's axes are not sweep.csv's, or plan.json is not valid JSON."""
    folder = Path(folder)
    if not folder.is_dir():
        raise DataError(folder, "not a folder (expected a sweep folder written by relslam sweep)")
    if (folder / "summary.csv").is_file() and not (folder / "sweep.csv").is_file():
        raise DataError(folder / "sweep.csv", "file not found: this is a run folder (load_run reads it)")
    manifest = read_json(folder / "manifest.json")
    plan_path = folder / "plan.json"
    plan = read_json(plan_path) if plan_path.is_file() else None
    runs = read_csv(folder / "sweep.csv", required=("seed", "folder", "algorithm", "status"), numeric=("seed",))
    aggregate_path = folder / "aggregate.csv"
    # The statistics must be numbers; read_csv names the first row that is not.
    aggregate = read_csv(aggregate_path, required=("algorithm", "runs", "ok"),
                         numeric=lambda c: c in ("runs", "ok") or c.endswith(STATISTICS))
    axes = _axes(aggregate, aggregate_path)
    missing = [a for a in axes if a not in runs.columns]
    if missing:
        raise DataError(aggregate_path, f"axis column(s) {', '.join(missing)} not in sweep.csv")
    return Sweep(folder=folder, manifest=manifest, plan=plan, runs=runs, aggregate=aggregate, axes=axes)
