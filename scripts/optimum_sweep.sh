#!/usr/bin/env bash
# Every estimator against the batch optimum (docs/algorithms/batch-optimum.md): S-EKF-F8 seeds 1-10 and
# S-F8-2L seeds 1-5, Relative Point (the scenario's thesis preset, adaptive, adaptive with the
# global relaxation), MRPT's 6D EKF and the batch optimum, then the table (scripts/optimum_table.py).
#
#   scripts/optimum_sweep.sh OUT [RELSLAM] [JOBS]
#
# Each scenario is six relslam sweeps over the same seeds, so the slow EKF and the optimum run
# once per seed: base/ (Relative Point thesis, the optimum), adaptive/ and relaxed/ (Relative
# Point alone), motion/ (the optimum with the EKF's constant-position motion model, the EKF's
# floor), ekfmodel/ (the optimum with the EKF's motion and sensor model), ekf/ (the EKF alone);
# the table checks that all saw the same frames. S-F8-2L runs with S-EKF-F8's EKF
# settings (prev_min 8 as there). A sweep with a failed or stopped run still goes on (exit 1).
set -uo pipefail
out=${1:?usage: scripts/optimum_sweep.sh OUT [RELSLAM] [JOBS]}
relslam=${2:-build/relslam}
jobs=${3:-2}
here=$(cd "$(dirname "$0")/.." && pwd)
ekf=(--set ekf6d.std_range=0.2 --set ekf6d.std_yaw_deg=0.5 --set ekf6d.std_pitch_deg=0.5
     --set 'ekf6d.stds_q=[0.175,0.175,0.175,0.0025,0.0025,0.0025,0.0025]' --set relative_point.final_group.prev_min=8)
relaxed=(--set relative_point.preset=adaptive --set relative_point.global_relaxation=periodic
         --set relative_point.relaxation_period=100)

sweep() {  # scenario name seeds folder args...
  local scenario=$1 name=$2 seeds=$3 folder=$4
  shift 4
  echo "== $name/$folder"
  "$relslam" sweep "$here/scenarios/$scenario" --out "$out/$name/$folder" --seeds "$seeds" --jobs "$jobs" -q "$@"
}

# The cheap runs first (Relative Point and the optimum take seconds per seed), the EKF last
# (minutes per seed): an interrupted sweep still gives the optimum's table.
specs=("s-ekf-f8.json S-EKF-F8 10" "s-f8-2l.json S-F8-2L 5")
for spec in "${specs[@]}"; do
  read -r scenario name seeds <<<"$spec"
  sweep "$scenario" "$name" "$seeds" base "${ekf[@]}" --set 'algorithms=["relative_point","batch_optimum"]'
  sweep "$scenario" "$name" "$seeds" adaptive "${ekf[@]}" --set relative_point.preset=adaptive \
    --set 'algorithms=["relative_point"]'
  sweep "$scenario" "$name" "$seeds" relaxed "${ekf[@]}" "${relaxed[@]}" --set 'algorithms=["relative_point"]'
  sweep "$scenario" "$name" "$seeds" motion "${ekf[@]}" --set batch_optimum.motion_model=ekf6d \
    --set 'algorithms=["batch_optimum"]'
  sweep "$scenario" "$name" "$seeds" ekfmodel "${ekf[@]}" --set batch_optimum.motion_model=ekf6d \
    --set batch_optimum.noise_model=ekf6d --set 'algorithms=["batch_optimum"]'
done
for spec in "${specs[@]}"; do
  read -r scenario name seeds <<<"$spec"
  sweep "$scenario" "$name" "$seeds" ekf "${ekf[@]}" --set 'algorithms=["ekf6d"]'
done
/usr/bin/python3 "$here/scripts/optimum_table.py" "$out"
