#!/usr/bin/env bash
# A one-machine Slurm (controller and node on 127.0.0.1) runs the slurm.sbatch that
# relslam sweep --emit writes; --aggregate then gives the table a local sweep gives.
# Installs Debian's slurmd, slurmctld and munge itself if they are missing (scripts/setup.sh
# stays free of Slurm), starts the daemons, and stops exactly those it started.
# Exits 77 (CTest: skipped) with a message when Slurm cannot be had or started here.
# usage: slurm_sweep_test.sh <relslam> <source dir> <scratch dir>
set -euo pipefail
relslam="$(realpath "$1")"
source_dir="$(realpath "$2")"
work="$3"
skip() { echo "SKIP: $*" >&2; exit 77; }

if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null ||
  ! command -v sbatch >/dev/null; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null && sudo -n true 2>/dev/null || skip "Slurm is not installed and there is no root to install it"
    sudo="sudo -n"
  fi
  echo "installing slurmctld slurmd slurm-client munge"
  $sudo apt-get update -qq || skip "apt-get update failed"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends slurmctld slurmd slurm-client munge \
    >/dev/null || skip "could not install Slurm"
fi
[ "$(id -u)" -eq 0 ] || skip "the one-machine Slurm is started as root (slurmd must be); run the long tests as root"

rm -rf "$work"
mkdir -p "$work/state" "$work/spool" "$work/log" "$work/munge"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT

# munge: our own key, socket and daemon, so an installed munge service is left alone.
key="$work/munge/munge.key"
socket="$work/munge/munge.socket"
dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
chmod 400 "$key"
mkdir -p /run/munge /var/log/munge /var/lib/munge
munged --foreground --force --key-file="$key" --socket="$socket" --pid-file="$work/munge/munged.pid" \
  --seed-file="$work/munge/seed" --log-file="$work/log/munged.log" >"$work/log/munged.out" 2>&1 &
pids+=($!)

cores=$(nproc)
memory=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)
cat >"$work/slurm.conf" <<CONF
ClusterName=relslamtest
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
SlurmctldPort=$((16817 + RANDOM % 1000))
SlurmdPort=$((17818 + RANDOM % 1000))
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cores RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i -f "$SLURM_CONF" >"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N localhost >"$work/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 30); do
  sinfo -h -o %T 2>/dev/null | grep -Eq '^idle' && break
  sleep 1
done
if ! sinfo -h -o %T 2>/dev/null | grep -Eq '^idle'; then
  tail -n 20 "$work/log/"* >&2 || true
  skip "could not start slurmctld and slurmd on 127.0.0.1 here (logs above)"
fi
echo "slurm up: $(sinfo -h -o '%P %D %T')"

grid=(--param sim.noise_sigma=0.05,0.1 --seeds 2 -q --set sim.iterations=200 --set sim.density=30
  --set output.rawlog=false --set output.observations_csv=false)
"$relslam" sweep "$source_dir/scenarios/s-f8.json" --emit "$work/emitted" --slurm-mem 200M --slurm-time 00:10:00 \
  --slurm-throttle 2 "${grid[@]}"
RELSLAM_BIN_DIR="$(dirname "$relslam")" sbatch --wait "$work/emitted/slurm.sbatch"
"$relslam" sweep --aggregate "$work/emitted" -q
"$relslam" sweep "$source_dir/scenarios/s-f8.json" --out "$work/local" "${grid[@]}"

# The tables agree but for the measured times.
python3 - "$work/local" "$work/emitted" <<'PY'
import csv, json, sys
local, emitted = sys.argv[1], sys.argv[2]
for table in ("aggregate.csv", "sweep.csv"):
    a = list(csv.reader(open(f"{local}/{table}")))
    b = list(csv.reader(open(f"{emitted}/{table}")))
    assert a[0] == b[0] and len(a) == len(b), table
    keep = [i for i, name in enumerate(a[0]) if "runtime" not in name]
    for x, y in zip(a[1:], b[1:]):
        assert [x[i] for i in keep] == [y[i] for i in keep], (table, x, y)
engine = json.load(open(f"{emitted}/sim.noise_sigma=0.1/seed-2/manifest.json"))["engine"]
assert engine["name"] == "slurm" and "SLURM_ARRAY_TASK_ID" in engine, engine
print("slurm sweep: same tables as the local sweep; engine", engine)
PY
ls "$work/emitted/slurm-logs" | grep -q '_4.out' || { echo "no per-task log" >&2; exit 1; }
echo "PASS"
