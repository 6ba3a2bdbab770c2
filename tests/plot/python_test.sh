#!/usr/bin/env bash
# The Python side of bring-your-own-data: the relslam_data package (python/) and the two plot commands
# (scripts/plot_run.py, scripts/plot_sweep.py; and scripts/plot/run.py, simulation.py, which read
# through it) on a tiny simulated run, a tiny planar run and a
# tiny sweep made by the relslam binary: every promised PNG is written and non-trivial, the
# package's unit tests pass (the real-folder ones with this binary), the package imports through
# PYTHONPATH without installing, and a damaged folder fails with exit 2 naming the file, without a
# traceback. Takes about half a minute on two cores.
#
# Usage: tests/plot/python_test.sh <relslam binary> <source dir> <work dir>
set -uo pipefail
[ $# -eq 3 ] || { echo "usage: $0 <relslam binary> <source dir> <work dir>" >&2; exit 2; }
relslam=$(realpath "$1")
src=$(realpath "$2")
work=$(realpath -m "$3")
python=/usr/bin/python3  # Debian's, with pandas and matplotlib
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in the source tree

source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"

rm -rf "$work"
mkdir -p "$work" || die "cannot create $work"
cd "$src" || die "no source dir $src"

# ---- fixture: tiny real folders --------------------------------------------------------------
"$relslam" run scenarios/s-ekf-f8.json --out "$work/run" --set sim.iterations=60 -q || die "relslam run failed"
"$relslam" run scenarios/p-room.json --out "$work/planar" --set planar.iterations=150 -q || die "planar run failed"
"$relslam" sweep scenarios/s-ekf-f8.json --out "$work/sweep" --param sim.noise_sigma=0.05,0.1 \
  --param relative_point.basis=first_three,farthest --seeds 2 --set sim.iterations=30 --jobs 1 -q ||
  die "relslam sweep failed"

check_png() {  # check_png FILE: a PNG of at least 300x200 pixels and 10 kB (a drawn figure, not a blank)
  local size
  [ -s "$1" ] || { fail "$1 missing or empty"; return; }
  size=$("$python" "$src/tests/plot/png_size.py" "$1") || { fail "$1 is not a PNG"; return; }
  read -r width height <<<"$size"
  if [ "$width" -ge 300 ] && [ "$height" -ge 200 ] && [ "$(stat -c %s "$1")" -ge 10000 ]; then ok
  else fail "$1: $size pixels, $(stat -c %s "$1") bytes: too small for a figure"; fi
}

# ---- plot_run.py and plot_sweep.py -----------------------------------------------------------
"$python" scripts/plot_run.py "$work/run" --out "$work/plots-run" >"$work/plot-run.log" 2>&1
expect "plot_run.py exits 0 (see $work/plot-run.log)" [ $? -eq 0 ]
"$python" scripts/plot_run.py "$work/planar" >"$work/plot-planar.log" 2>&1  # no --out: into RUN/plots
expect "plot_run.py on the planar run exits 0 (see $work/plot-planar.log)" [ $? -eq 0 ]
for plots in "$work/plots-run" "$work/planar/plots"; do
  for name in errors runtime map_size top_view; do
    check_png "$plots/$name.png"
  done
done
metrics=(final_mean_landmark_error ate_rmse runtime_median_ms)
"$python" scripts/plot_sweep.py "$work/sweep" --out "$work/plots-sweep" --metric "${metrics[@]}" --ratios \
  >"$work/plot-sweep.log" 2>&1
expect "plot_sweep.py exits 0 (see $work/plot-sweep.log)" [ $? -eq 0 ]
for metric in "${metrics[@]}"; do
  check_png "$work/plots-sweep/$metric.png"
  check_png "$work/plots-sweep/${metric}_ratio.png"
done
expect "plot_sweep.py writes only the metrics asked for" [ "$(find "$work/plots-sweep" -name '*.png' | wc -l)" -eq 6 ]

# scripts/demo.sh's two scripts, which read through the package too.
"$python" scripts/plot/run.py --run "$work/run" --out "$work/plots-demo" >"$work/plot-demo.log" 2>&1
expect "scripts/plot/run.py exits 0 (see $work/plot-demo.log)" [ $? -eq 0 ]
"$python" scripts/plot/simulation.py --run "$work/run" --out "$work/plots-demo" >>"$work/plot-demo.log" 2>&1
expect "scripts/plot/simulation.py exits 0 (see $work/plot-demo.log)" [ $? -eq 0 ]
for name in landmark_error position_error runtime map_size sim_top_view sim_height sim_visible; do
  check_png "$work/plots-demo/$name.png"
done

# ---- the package: unit tests, import without installing ---------------------------------------
RELSLAM_BINARY=$relslam "$python" -m unittest discover -s "$src/python/tests" >"$work/unittest.log" 2>&1
expect "python unit tests pass (see $work/unittest.log)" [ $? -eq 0 ]
expect "no unit test skipped (the real-folder tests ran)" not grep -q "skipped" "$work/unittest.log"
out=$(cd "$work" && PYTHONPATH=$src/python "$python" -c \
  'import relslam_data as r; print(r.load_run("run").summary["algorithm"].tolist(), r.load_sweep("sweep").axes)')
expect "import through PYTHONPATH: load_run and load_sweep ($out)" \
  [ "$out" = "['relative_point', 'ekf6d', 'relative_point/ekf6d'] ['sim.noise_sigma', 'relative_point.basis']" ]

# ---- damaged folders -------------------------------------------------------------------------
cp -r "$work/run" "$work/cut-run"
truncate -s -7 "$work/cut-run/ekf6d/iterations.csv"
out=$("$python" scripts/plot_run.py "$work/cut-run" --out "$work/cut-plots" 2>&1)
expect "cut iterations.csv: exit 2" [ $? -eq 2 ]
expect "cut iterations.csv: named ($out)" grep -q "cut-run/ekf6d/iterations.csv: cut short" <<<"$out"
expect "cut iterations.csv: no traceback" not grep -q "Traceback" <<<"$out"
out=$("$python" scripts/plot/run.py --run "$work/cut-run" --out "$work/cut-plots" 2>&1)
status=$?
expect "scripts/plot/run.py on the cut file: exit 1" [ $status -eq 1 ]
expect "scripts/plot/run.py names the cut file ($out)" grep -q "cut-run/ekf6d/iterations.csv: cut short" <<<"$out"
cp -r "$work/sweep" "$work/bad-sweep"
rm "$work/bad-sweep/aggregate.csv"
out=$("$python" scripts/plot_sweep.py "$work/bad-sweep" --out "$work/bad-plots" 2>&1)
expect "sweep without aggregate.csv: exit 2" [ $? -eq 2 ]
expect "sweep without aggregate.csv: named ($out)" grep -q "bad-sweep/aggregate.csv: file not found" <<<"$out"
expect "sweep without aggregate.csv: no traceback" not grep -q "Traceback" <<<"$out"
out=$("$python" scripts/plot_sweep.py "$work/run" 2>&1)
status=$?
expect "a run folder given as a sweep: exit 2" [ $status -eq 2 ]
expect "a run folder given as a sweep: names sweep.csv ($out)" grep -q "run/sweep.csv: file not found" <<<"$out"

summary
[ "$failed" -eq 0 ]
