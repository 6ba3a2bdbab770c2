#!/usr/bin/env bash
# The main job for a new user: install what is missing, build, run the default experiment,
# plot it, and say where everything is.
#   scripts/demo.sh [--out DIR]        (default runs/demo)
# Default experiment: the Relative Point algorithm on one loop of the figure eight, S-F8
# (scenarios/s-f8.json), scored against the simulator's truth.
set -euo pipefail
cd "$(dirname "$0")/.."
out=runs/demo
scenario=scenarios/s-f8.json
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "demo: unknown argument $1" >&2; exit 2 ;;
  esac
done

scripts/setup.sh
scripts/build.sh build
echo
./build/relslam run "$scenario" --out "$out" --force
/usr/bin/python3 scripts/plot/simulation.py --run "$out"
/usr/bin/python3 scripts/plot/run.py --run "$out"
echo
echo "Results in $out/:"
echo "  summary.csv                      one row per algorithm: errors, ATE, run time, memory"
echo "  relative_point/iterations.csv    errors, timings and counts per iteration"
echo "  relative_point/landmarks.csv     the map: position, true landmark, error, group level"
echo "  relative_point/trajectory.tum    estimated path (evo: evo_ape tum $out/ground_truth_path.tum $out/relative_point/trajectory.tum)"
echo "  ground_truth_*, observations.*   the simulated truth and what the robot saw (CSV and MRPT rawlog)"
echo "  plots/*.png                      errors, run time, top view, visible points"
echo "  manifest.json                    scenario, seed, git revision, library versions"
