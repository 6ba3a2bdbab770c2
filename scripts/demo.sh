#!/usr/bin/env bash
# The main job for a new user: install what is missing, build, run the default experiment,
# plot it, and say where everything is.
#   scripts/demo.sh [--out DIR]        (default runs/demo)
# Default experiment: the one-loop figure eight, S-F8 (scenarios/s-f8.json).
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
./build/relslam simulate "$scenario" --out "$out" --force
/usr/bin/python3 scripts/plot/simulation.py --run "$out"
echo
echo "Results in $out/:"
echo "  ground_truth_path.tum       robot path (TUM; try: evo_traj tum $out/ground_truth_path.tum)"
echo "  observations.csv, .rawlog   what the robot saw, per iteration (CSV and MRPT rawlog)"
echo "  sim_iterations.csv          pose and visible-point count per iteration"
echo "  plots/*.png                 top view, side view, visible points"
echo "  manifest.json               scenario, seed, git revision, library versions"
