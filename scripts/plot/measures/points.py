"""Chapter 6 (Relative Point) measures: the numbers its figures show and claims.py checks."""
import numpy as np

from measures.common import arrays, steady
import relslam_plot as rp


COMPONENTS = ["t_init_ms", "t_load_ms", "t_compute_ms", "t_create_ms"]  # thesis 6.6.3's buckets


DENSITY_COLUMNS = ["runtime_ms", "visible_points", *COMPONENTS]


def density_table(runs):
    """Per density, ascending: steady-state means of run time, visible points and components, averaged
    over the seeds (the thesis's density.csv). runs: [(density, iterations table)], one per seed."""
    columns = DENSITY_COLUMNS
    per_density = {}
    for value, frame in runs:
        d = arrays(frame, columns)
        per_density.setdefault(float(value), []).append([steady(d[c]).mean() for c in columns])
    densities = sorted(per_density)
    means = np.array([np.mean(per_density[d], axis=0) for d in densities])
    table = {"density": np.array(densities), **{c: means[:, i] for i, c in enumerate(columns)}}
    table["t_other_ms"] = table["runtime_ms"] - sum(table[c] for c in COMPONENTS)
    return table


def vp_benchmarks(doc, path="benchmark JSON"):
    """{window: {levels: ms per scan}} from relslam_bench_victoria_park's JSON document (labels "levels
    L, window W"); with --benchmark_repetitions only the mean aggregate counts. `path` names the file in
    messages."""
    measured = {}
    for b in doc.get("benchmarks", []):
        levels, _, window = b.get("label", "").partition(", window ")
        repeated = b.get("run_type") == "aggregate" or b.get("repetitions", 1) > 1
        if levels.startswith("levels ") and "ms_per_scan" in b and (not repeated or b.get("aggregate_name") == "mean"):
            measured.setdefault(window, {})[int(levels.split()[1])] = b["ms_per_scan"]
    if not measured:
        raise rp.DataError(f"{path}: no benchmark with label 'levels L, window W' and counter ms_per_scan")
    return measured
