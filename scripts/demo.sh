#!/usr/bin/env bash
# The main job for a new user: install what is missing, build, run the default experiment,
# plot it, and say where everything is.
#   scripts/demo.sh [--out DIR]        (default runs/demo)
# Default experiment: S-EKF-F8 (scenarios/s-ekf-f8.json), one loop of the figure eight at
# density 25 with the Relative Point algorithm and MRPT's 6D EKF on the same observations,
# scored against the simulator's truth (on an idle two-core machine the run takes under a minute and the first
# build about six minutes: it compiles the library, simulator and harness). Builds only the relslam program;
# scripts/test.sh builds everything.
set -euo pipefail
cd "$(dirname "$0")/.."
out=runs/demo
scenario=scenarios/s-ekf-f8.json
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "demo: unknown argument $1" >&2; exit 2 ;;
  esac
done

scripts/setup.sh --demo
cmake -S . -B build -DCMAKE_BUILD_TYPE="${RELSLAM_BUILD_TYPE:-Release}" >/dev/null
cmake --build build -j "$(nproc)" --target relslam
echo
./build/relslam run "$scenario" --out "$out" --force
/usr/bin/python3 scripts/plot/simulation.py --run "$out"
/usr/bin/python3 scripts/plot/run.py --run "$out"
echo
echo "Results in $out/:"
echo "  summary.csv                      one row per algorithm (errors, ATE, RPE, run time, memory) and their ratios"
echo "  <algorithm>/iterations.csv       errors, timings and counts per iteration (relative_point, ekf6d)"
echo "  <algorithm>/landmarks.csv        the map: position, true landmark, error"
echo "  <algorithm>/trajectory.tum       estimated path (evo: evo_ape tum $out/ground_truth_path.tum $out/ekf6d/trajectory.tum)"
echo "  ground_truth_*, observations.*   the simulated truth and what the robot saw (CSV and MRPT rawlog)"
echo "  plots/*.png                      errors, run time, map size, top view, visible points"
echo "  manifest.json                    scenario, seed, git revision, library versions"
