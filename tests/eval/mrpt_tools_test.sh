#!/usr/bin/env bash
# MRPT's own tools accept what `relslam simulate` writes: rawlog-edit counts the records and
# sees the actions/sensory-frames format, and kf-slam (the 6D EKF) processes every step.
# Where the Victoria Park data is, the same for `relslam convert victoria-park` with the 2D EKF.
# Usage: mrpt_tools_test.sh <relslam binary> <source dir>
set -euo pipefail
relslam=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
iterations=60

for tool in rawlog-edit kf-slam; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool not installed (scripts/setup.sh installs mrpt-apps)"; exit 1; }
done

"$relslam" simulate "$source_dir/scenarios/s-f8.json" --out "$work/run" -q \
  --set sim.density=25 --set sim.iterations=$iterations
rawlog="$work/run/observations.rawlog"

info=$(rawlog-edit --info -i "$rawlog" 2>&1)
echo "$info" | grep -E "objects|format|Sensor"
echo "$info" | grep -Eq "Overall number of objects +: $((2 * iterations))$" || { echo "FAIL: object count"; exit 1; }
echo "$info" | grep -Eq "Actions/SensoryFrame format +: Yes" || { echo "FAIL: format"; exit 1; }
echo "$info" | grep -Eq "RELSLAM_SIM / +$iterations " || { echo "FAIL: observation count"; exit 1; }

# run_kf_slam NAME IMPLEMENTATION RAWLOG STEPS FILTER_KEYS: kf-slam with logging off, which must
# reach step STEPS-1; its log is $work/NAME.log.
run_kf_slam() {
  local name=$1 implementation=$2 log=$3 steps=$4 keys=$5
  cat > "$work/$name.ini" <<INI
[MappingApplication]
kf_implementation=$implementation
logOutput_dir=$work/$name-out
SAVE_LOG_FREQUENCY=1000000
SAVE_DA_LOG=false
SAVE_3D_SCENES=false
SAVE_MAP_REPRESENTATIONS=false
SHOW_3D_LIVE=false

[RangeBearingKFSLAM]
$keys

[RangeBearingKFSLAM_KalmanFilter]
method=1
INI
  (cd "$work" && timeout 300 kf-slam "$name.ini" "$log") > "$work/$name.log" 2>&1 \
    || { tail -20 "$work/$name.log"; echo "FAIL: kf-slam ($name) exited non-zero"; exit 1; }
  grep -q "Step $((steps - 1)) - " "$work/$name.log" \
    || { tail -20 "$work/$name.log"; echo "FAIL: kf-slam ($name) did not reach the last step"; exit 1; }
}

run_kf_slam kf CRangeBearingKFSLAM "$rawlog" "$iterations" "force_ignore_odometry=true
std_sensor_range=0.1
std_sensor_yaw_deg=0.1
std_sensor_pitch_deg=0.1
stds_Q_no_odo=[0.35 0.35 0.35 0.005 0.005 0.005 0.005]"
grep -q "KF-SLAM finished" "$work/kf.log" || { echo "FAIL: kf-slam did not finish"; exit 1; }
# The robot drove straight ahead (MRPT +x) for iterations-1 steps of 1145/3800 units.
last=$(grep "Mean pose" "$work/kf.log" | tail -1)
echo "kf-slam last pose: $last"
x=$(echo "$last" | sed -E 's/.*=\(([-0-9.]+),.*/\1/')
awk -v x="$x" -v n="$iterations" 'BEGIN { want = (n - 1) * 1145 / 3800; d = x - want; if (d < 0) d = -d; exit !(d < 0.5) }' \
  || { echo "FAIL: kf-slam final x $x is not near $(( (iterations - 1) * 1145 / 3800 ))"; exit 1; }

vp=${RELSLAM_VICTORIA_PARK:-$source_dir/../shared/datasets/victoria_park}
if [ -f "$vp/measurements.dat" ]; then
  scans=50
  "$relslam" convert victoria-park --data "$vp" --window 1181:$((1180 + scans)) \
    --scenario "$source_dir/scenarios/victoria-park.json" --out "$work/vp.rawlog" -q
  info=$(rawlog-edit --info -i "$work/vp.rawlog" 2>&1)
  echo "$info" | grep -Eq "Overall number of objects +: $((2 * scans))$" || { echo "$info"; echo "FAIL: VP object count"; exit 1; }
  echo "$info" | grep -Eq "Actions/SensoryFrame format +: Yes" || { echo "FAIL: VP format"; exit 1; }
  run_kf_slam kf2d CRangeBearingKFSLAM2D "$work/vp.rawlog" "$scans" "std_sensor_range=0.5
std_sensor_yaw_deg=1
data_assoc_method=1"
  # About 0.57 m forward per scan at the window's start (dead reckoning).
  echo "kf-slam 2D on Victoria Park, last pose: $(grep "Mean pose" "$work/kf2d.log" | tail -1)"
else
  echo "skipped the Victoria Park part: no data at $vp (set RELSLAM_VICTORIA_PARK)"
fi
echo "PASS"
