#!/usr/bin/env bash
# Runs the thesis's Chapter 4 (Relative Plane), Chapter 5 (EM plane extraction) and Chapter 6
# (Relative Point) experiments and
# writes the report: a summary page (report/index.html: Relative Point against the EKF and the other
# baselines, every thesis claim with its verdict), one page per chapter with each figure next to its
# thesis number and caption, and the thesis's numbers next to ours (report/claims.md).
#   scripts/reproduce.sh [--quick] [--out DIR] [--report DIR] [--binary PATH] [--jobs N]
#     --quick    shortened runs (fewer iterations and loops; minutes rather than hours: docs/figures.md)
#     --out      run folders (default runs/reproduce, or runs/reproduce-quick with --quick)
#     --report   report folder (default report)
#     --binary   use this relslam and skip installing and building (as the long CTest does)
#     --jobs     sweep runs at a time (default: the number of cores)
# Steps that fail are listed at the end (exit 1); the others still run and are reported.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$(pwd)

quick=0
out=""
report=report
binary=""
jobs=$(nproc)
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; shift ;;
    --out) out=$2; shift 2 ;;
    --report) report=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "reproduce: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -n "$out" ] || out=$([ $quick -eq 1 ] && echo runs/reproduce-quick || echo runs/reproduce)

if [ -z "$binary" ]; then
  scripts/setup.sh
  scripts/build.sh build
  binary=build/relslam
  bench_vp=build/bench/relslam_bench_victoria_park
else
  bench_vp=$(dirname "$binary")/bench/relslam_bench_victoria_park
fi
relslam() { "$binary" "$@"; }
vp_data=${RELSLAM_VICTORIA_PARK:-$source_dir/../shared/datasets/victoria_park}
mkdir -p "$out/renders"
log="$out/reproduce.log"
: > "$log"
failed=()
start_all=$SECONDS

# step NAME COMMAND...: runs one experiment, logs its output and time, and goes on if it fails.
step() {
  local name=$1; shift
  local start=$SECONDS
  printf '%-28s ' "$name"
  if "$@" >> "$log" 2>&1; then
    printf 'done in %4d s\n' $((SECONDS - start))
  else
    printf 'FAILED after %d s (see %s)\n' $((SECONDS - start)) "$log"
    failed+=("$name")
  fi
}
# Quick mode's shorter runs: each experiment keeps its shape, with fewer iterations or loops.
short() { [ $quick -eq 1 ] && echo "$@" || true; }
run() { local name=$1 scenario=$2; shift 2; relslam run "scenarios/$scenario.json" --out "$out/$name" --force -q "$@"; }
sweep() { local name=$1; shift; relslam sweep "scenarios/$name.json" --out "$out/$name" --force -q --jobs "$jobs" "$@"; }
set_each() { local a=(); for kv in "$@"; do a+=(--set "$kv"); done; echo "${a[@]}"; }

echo "reproduce: thesis Chapters 4 and 6 into $out ($([ $quick -eq 1 ] && echo quick || echo full) mode); log in $log"

# 4.2 - 4.3: the Relative Plane experiments (E01-E22, E31, E32).
# Seconds each, so quick mode runs them in full; the variant files go through sweep.
step p-e01-invariance    run p-e01-invariance p-e01-invariance
step p-four-planes       run p-four-planes p-four-planes
step p-hallway           run p-hallway p-hallway
step p-hallway-back      run p-hallway-back p-hallway-back
step p-e05-edge-on       sweep p-e05-edge-on
step p-e06-rule12        sweep p-e06-rule12
step p-e31-chain-order   sweep p-e31-chain-order
step p-office            run p-office p-office
step p-e21-completed-map run p-e21-completed-map p-e21-completed-map
step p-e10-rule21-22     sweep p-e10-rule21-22
# experiments (Relative Plane part 2: E02, E07-E09, E12, E15, E18, E32). Seconds each too;
# quick mode runs fewer noise seeds, and E32 (whose times are the result: one run at a time) 1 and 2 loops.
seeds() { if [ $quick -eq 1 ]; then echo "--seeds 2"; else echo "--seeds 5"; fi; }
step p-e02-key-point-pairs run p-e02-key-point-pairs p-e02-key-point-pairs
step p-e07-interval-mode sweep p-e07-interval-mode $(seeds)
step p-e08-bad-key-points sweep p-e08-bad-key-points $(seeds)
step p-e09-plane5        sweep p-e09-plane5
step p-e12-rule28        sweep p-e12-rule28
step p-e15-loop-closure-map-e sweep p-e15-loop-closure-map-e $(seeds)
step p-e18-collinear     run p-e18-collinear p-e18-collinear
# (part 3): E19's save system needs the 1200-slot store to wrap (Map D at a quarter speed,
# about a minute on two cores, so quick mode runs it whole); E20: Rule 37 on Map E, two loops.
step p-e19-save-system   sweep p-e19-save-system
step p-e20-pseudo-merge  sweep p-e20-pseudo-merge $(seeds)
step p-e32-runtime       relslam sweep scenarios/p-e32-runtime.json --out "$out/p-e32-runtime" --force -q --jobs 1 \
                           $([ $quick -eq 1 ] && echo "--param planar.loops=1,2")
step p-room              run p-room p-room
# experiments (Relative Plane part 3): E16 (Rule 29), E17 (Rules 31-34: interval checks,
# hints and roll-back); the motion model's E11 (Map E1's first corner), E13 (Rule 23's growth
# threshold), E14 (frustum shape) and E22 (one partial plane in view). Seconds each.
step p-e16-rule29        sweep p-e16-rule29
step p-e17-interval-check sweep p-e17-interval-check
step p-e11-first-corner  sweep p-e11-first-corner $(seeds)
step p-e13-grow-threshold sweep p-e13-grow-threshold $(seeds)
step p-e14-frustum-shape sweep p-e14-frustum-shape
step p-e22-one-partial-plane run p-e22-one-partial-plane p-e22-one-partial-plane

# Chapter 5 and the companion paper (E23-E30): points -> EM ->
# Relative Plane (Figs 46, 105-108, paper Figs 6-8; E23's w_ma variants, the E28 noise sweep), the EM
# test bench (Figs 55-61) and EM1 vs EM2 on identical frames (E29). E27 times EM and the algorithm per
# iteration: one run at a time.
step p-em-office         run p-em-office p-em-office $(set_each $(short planar.iterations=1000))
step p-em-office-noise   run p-em-office-noise p-em-office-noise $(set_each $(short planar.iterations=1000))
# E23's moving-average variants (Rule 18's w_ma 5, 3, 8) without and with point noise (E24).
step p-em-office-w-ma    relslam sweep scenarios/p-em-office.json --out "$out/p-em-office-w-ma" --force -q \
                           --jobs "$jobs" $(set_each $(short planar.iterations=1000))
step p-em-office-noise-w-ma relslam sweep scenarios/p-em-office-noise.json --out "$out/p-em-office-noise-w-ma" \
                           --force -q --jobs "$jobs" $(set_each $(short planar.iterations=1000))
step p-em-room           run p-em-room p-em-room $(set_each $(short planar.loops=1))
step p-em-room-noise     run p-em-room-noise p-em-room-noise $(set_each $(short planar.loops=1))
step p-em-demo           relslam sweep scenarios/p-em-demo.json --out "$out/p-em-demo" --force -q --jobs 1 \
                           $(set_each $(short planar.iterations=600))
# E28: Map E, one loop, σ_pt 0 to 0.2 (seconds a run: quick mode runs one seed instead of three);
# noise_sweep.py then writes the sweep's noise_sweep.csv.
noise_sweep() {
  sweep p-em-noise-sweep --seeds "$([ $quick -eq 1 ] && echo 1 || echo 3)" &&
    /usr/bin/python3 scripts/plot/noise_sweep.py "$out/p-em-noise-sweep"
}
step p-em-noise-sweep    noise_sweep
step em-bench            relslam em-bench scenarios/p-em-office-noise.json --out "$out/em-bench" --force -q \
                           --seeds "$([ $quick -eq 1 ] && echo 2 || echo 5)"
step e29-office          relslam em-bench scenarios/p-em-compare-office.json --compare --out "$out/e29-office" \
                           --force -q $(set_each $(short planar.iterations=100))
step e29-room            relslam em-bench scenarios/p-em-compare-room.json --compare --out "$out/e29-room" \
                           --force -q $(set_each $(short planar.iterations=100))

# 6.5 - 6.6: the figure eight, its variants and the run-time experiments.
step s-f8                run s-f8 s-f8
step s-f8-first-three    run s-f8-first-three s-f8 --set relative_point.basis=first_three
step s-f8-2l             run s-f8-2l s-f8-2l
step s-f8-2l-rebuilt     run s-f8-2l-rebuilt s-f8-2l --set relative_point.global_index=rebuilt
step s-f8-2l-const       sweep s-f8-2l-const
step s-f8-7l-const       sweep s-f8-7l-const $(set_each $(short sim.loops=2))
step s-f8-2x             run s-f8-2x s-f8-2x
step s-dens-q            sweep s-dens-q $(set_each $(short sim.iterations=1500))
step s-dens-qs           sweep s-dens-qs $(set_each $(short sim.iterations=1500))
step s-dens-o            sweep s-dens-o $(set_each $(short sim.iterations=1500))
step s-bin               relslam bench-binning scenarios/s-bin.json --out "$out/s-bin" --force -q $(set_each $(short binning_bench.seeds=3))
step s-dyn3              run s-dyn3 s-dyn3
step s-dyn3-no-binning   run s-dyn3-no-binning s-dyn3 --set relative_point.final_group.binning=false

# 6.7: against MRPT's 6D EKF (the slow part: the EKF's cost grows with its map).
# Quick mode keeps S-EKF-F8's loop closure (iteration 3800): Figs 146-149 are about what happens there.
step s-ekf-f8            run s-ekf-f8 s-ekf-f8 $(set_each $(short sim.iterations=4200))
step s-line              run s-line s-line $(set_each $(short sim.iterations=2000))
step s-stat              run s-stat s-stat $(set_each $(short sim.iterations=2000))
step s-dyn               run s-dyn s-dyn $(set_each $(short sim.iterations=2000))

# 6.8: Victoria Park, when the data is there.
if [ -f "$vp_data/measurements.dat" ]; then
  step vp-1181           relslam victoria-park --data "$vp_data" --window 1181:1642 --out "$out/vp-1181" --force -q
  step vp-4220           relslam victoria-park --data "$vp_data" --window 4220:4634 --out "$out/vp-4220" --force -q
  step vp-all-relative   relslam victoria-park --data "$vp_data" --window all --bridge --set algorithms=relative_point \
                           --out "$out/vp-all" --force -q
  step vp-bridged        relslam victoria-park scenarios/victoria-park-bridged.json --data "$vp_data" \
                           --out "$out/vp-bridged" --force -q
  if [ -x "$bench_vp" ]; then
    step vp-timing       env RELSLAM_VICTORIA_PARK="$vp_data" "$bench_vp" --benchmark_format=json --benchmark_out="$out/vp-timing.json"
  fi
else
  echo "victoria park: skipped, no data at $vp_data (set RELSLAM_VICTORIA_PARK)"
fi

# 6.9: forty loops.
step s-40                run s-40 s-40 $(set_each $(short sim.loops=5))

# Renders (Figs 127-129, 153-162): the runs replayed by relslam render.
render_figures() {
  local r="$out/renders"
  # renders.csv: which run, algorithm and iteration (empty: the last) each render draws, so that the
  # report can say what the run shows there.
  printf 'figure,run,algorithm,iteration,view\n' > "$r/renders.csv"
  printf '%s\n' 127,s-f8,relative_point,,top 128,s-f8,relative_point,,side 129,s-f8,relative_point,,top >> "$r/renders.csv"
  # (errexit does not reach into a function called from `if`: each command returns on failure)
  relslam render "$out/s-f8" --out "$r/fig127.png" -q || return 1
  relslam render "$out/s-f8" --view side --out "$r/fig128.png" -q || return 1
  relslam render "$out/s-f8" --fit robot --labels on --out "$r/fig129.png" -q || return 1
  # Figs 153-156: the EKF losing its pose to the dynamic points, at four moments of its run;
  # Figs 157-162: the Relative map around the iteration whose landmark error drops most (the
  # final group's binning flagging the movers, thesis 6.7.3).
  local moments
  moments=$(/usr/bin/python3 - "$out/s-dyn" <<'PY'
import csv, sys
def column(path, name):
    with open(path, newline="") as f:
        return [float(r[name]) if r[name] else float("nan") for r in csv.DictReader(f)]
run = sys.argv[1]
ekf = len(column(run + "/ekf6d/iterations.csv", "iteration"))
ekf_moments = [max(0, round(ekf * q) - 1) for q in (0.25, 0.5, 0.75, 1.0)]
error = column(run + "/relative_point/iterations.csv", "landmark_error")
drops = [(error[k - 1] - error[k], k) for k in range(1, len(error)) if error[k] == error[k] and error[k - 1] == error[k - 1]]
k = max(drops)[1] if drops else len(error) - 1
rp_moments = [max(0, min(len(error) - 1, k + d)) for d in (-60, -20, -1, 0, 20, 100)]
print(" ".join(map(str, ekf_moments + rp_moments)))
PY
) || return 1
  set -- $moments
  local fig=153
  for k in "$1" "$2" "$3" "$4"; do
    relslam render "$out/s-dyn" --algorithm ekf6d --iteration "$k" --fit robot --out "$r/fig$fig.png" -q || return 1
    echo "$fig,s-dyn,ekf6d,$k,top" >> "$r/renders.csv"
    fig=$((fig + 1))
  done
  shift 4
  for k in "$@"; do
    relslam render "$out/s-dyn" --iteration "$k" --fit robot --labels on --out "$r/fig$fig.png" -q || return 1
    echo "$fig,s-dyn,relative_point,$k,top" >> "$r/renders.csv"
    fig=$((fig + 1))
  done
}
step renders             render_figures

step report              /usr/bin/python3 scripts/plot/report.py --runs "$out" --out "$report" $(short --quick)

echo "reproduce: $(( (SECONDS - start_all) / 60 )) min $(( (SECONDS - start_all) % 60 )) s; report in $report/index.html and $report/claims.md"
if [ ${#failed[@]} -gt 0 ]; then
  echo "reproduce: failed steps: ${failed[*]}" >&2
  exit 1
fi
