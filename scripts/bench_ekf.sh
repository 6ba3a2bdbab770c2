#!/usr/bin/env bash
# Benchmark: the MRPT 6D EKF and the Relative Point algorithm timed in the same run at
# density 25 as the map grows; prints their times and ratio per map size and the map size
# where the EKF passes 100 ms per iteration on this machine.
#   scripts/bench_ekf.sh [--out DIR] [--density RHO] [--iterations N]  (runs/bench-ekf, 25, 7600)
# The straight line keeps adding landmarks (a figure eight stops at ~290 at density 25): 7600
# iterations at density 25 would give ~570. The EKF stops once it needs more than 300 ms per
# iteration for 20 iterations in a row (a few minutes on two cores).
set -euo pipefail
cd "$(dirname "$0")/.."
out=runs/bench-ekf
density=25
iterations=7600
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    --density) density=$2; shift 2 ;;
    --iterations) iterations=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "bench_ekf: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -x build/relslam ] || scripts/build.sh build
./build/relslam run scenarios/s-line.json --out "$out" --force \
  --set sim.density="$density" --set sim.iterations="$iterations" --set relative_point.final_group.prev_min=8 \
  --set ekf6d.time_budget_ms=300 --set output.observations_csv=false --set output.rawlog=false
/usr/bin/python3 scripts/plot/ekf_timing.py --run "$out"
