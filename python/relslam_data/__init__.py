"""relslam_data: the folders relslam writes, as pandas data frames.

So that figures and comparisons need no CSV parsing of their own: one loader per folder kind,
checked on the way in (a missing or cut file raises DataError naming it).

    from relslam_data import load_run, load_sweep

    run = load_run("runs/demo")                  # relslam run ... --out runs/demo
    print(run.summary[["algorithm", "status", "final_mean_landmark_error", "runtime_median_ms"]])
    rp = run.algorithms["relative_point"]
    rp.iterations.plot(x="iteration", y="mean_landmark_error")   # pandas' own plot
    print(run.truth_landmarks.head())            # simulated runs carry the truth

    sweep = load_sweep("runs/noise")             # relslam sweep ... --out runs/noise
    print(sweep.axes, sweep.metrics)
    print(sweep.aggregate[sweep.axes + ["algorithm", "final_mean_landmark_error_mean"]])
    cell = sweep.run(sweep.runs.iloc[0])         # one cell's run folder, as load_run reads it

Figures: scripts/plot_run.py RUN --out DIR and scripts/plot_sweep.py SWEEP --out DIR.
"""
from .files import DataError, read_csv, read_json, read_tum
from .run import AlgorithmRun, Run, load_run
from .sweep import Sweep, load_sweep

__all__ = ["DataError", "load_run", "load_sweep", "Run", "AlgorithmRun", "Sweep", "read_csv", "read_tum",
           "read_json"]
__version__ = "0.1.0"
