#!/usr/bin/env bash
# The generated map suite (docs/generated-maps.md): scenarios/gen-suite.json run by relslam sweep,
# every generator family x map seeds 1-10 x small and large frustum x {noise_free,
# default_noise, em (points, sigma_pt 0.05)} x 3 seeds, then the table per family, frustum and
# condition.
# Usage: scripts/generated_suite.sh [--quick] [--maps N] [--seeds N] [--out DIR] [--jobs N] [--table-only]
#   --quick       map seeds 1-2 and one seed (72 runs instead of 1080)
#   --maps N      map seeds 1-N (default 10); --seeds N: seeds per map (default 3)
#   --table-only  print the table of a finished (or partly finished) sweep folder again
# Columns: valid_constrained_% = pose valid over the iterations with two walls more than 20
# degrees apart in view (truth_wall_angle_deg, the noise-free sensor); carried_% = the share of the
# other iterations with a valid pose (the motion model, Rules 23-27); wrong_valid = the sum of
# the iterations column wrong_valid when the runs have it; map_error = final mean map error
# (mean over runs); walls = walls mapped / walls (mean over runs); dups = duplicates per run;
# ms = median time per iteration (Relative Plane, plus the extraction with EM).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
relslam="${RELSLAM:-$here/build/relslam}"
out=runs/generated-suite
jobs=2
maps=10
seeds=3
table_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) maps=2; seeds=1 ;;
    --maps) maps="$2"; shift ;;
    --seeds) seeds="$2"; shift ;;
    --out) out="$2"; shift ;;
    --jobs) jobs="$2"; shift ;;
    --table-only) table_only=1 ;;
    *) echo "usage: $0 [--quick] [--maps N] [--seeds N] [--out DIR] [--jobs N] [--table-only]" >&2; exit 2 ;;
  esac
  shift
done
if [ "$table_only" = 0 ]; then
  scenario="$here/scenarios/gen-suite.json"
  if [ "$maps" != 10 ]; then
    # The same suite with map seeds 1-N: a scenario file beside the sweep folder, so the
    # sweep's plan names what was run.
    mkdir -p "$(dirname "$out")"
    scenario="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")-scenario.json"
    /usr/bin/python3 - "$here/scenarios/gen-suite.json" "$scenario" "$maps" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
doc["sweep"]["planar.generate.seed"] = list(range(1, int(sys.argv[3]) + 1))
doc["description"] = "scripts/generated_suite.sh --maps " + sys.argv[3] + ": " + doc["description"]
json.dump(doc, open(sys.argv[2], "w"), indent=2)
PY
  fi
  # A failed cell is a row of sweep.csv (exit 1); the table shows what finished.
  "$relslam" sweep "$scenario" --out "$out" --seeds "$seeds" --jobs "$jobs" || [ $? = 1 ]
fi
/usr/bin/python3 - "$out" <<'PY'
import csv, math, pathlib, statistics, sys
from collections import defaultdict
out = pathlib.Path(sys.argv[1])
cells = defaultdict(list)
failed = defaultdict(int)
for summary in sorted(out.rglob("summary.csv")):
    run = summary.parent
    labels = dict(p.split("=", 1) for p in run.relative_to(out).parts if "=" in p)
    key = (labels.get("planar.generate.family", "?"), labels.get("planar.frustum", "?"), labels.get("variant", "?"))
    rows = [r for r in csv.DictReader(open(summary)) if r["algorithm"] == "relative_plane"]
    if not rows or rows[0]["status"] != "ok":
        failed[key] += 1
        continue
    its = list(csv.DictReader(open(run / "relative_plane" / "iterations.csv")))
    walls = sum(1 for _ in open(run / "ground_truth_walls.csv")) - 1
    cells[key].append((rows[0], its, walls))
def num(x):
    return float(x) if x not in ("", None) else math.nan
print("| family | frustum | condition | runs | valid_constrained_% | carried_% | wrong_valid | map_error | walls | dups | ms |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for key in sorted(set(cells) | set(failed)):
    runs = cells.get(key, [])
    cv = ct = ov = ot = 0
    wrong = None
    ms = []
    for s, its, _ in runs:
        for r in its:
            constrained = num(r.get("truth_wall_angle_deg")) > 20
            valid = r.get("pose_valid") == "1"
            if constrained: ct += 1; cv += valid
            else: ot += 1; ov += valid
            if "wrong_valid" in r and r["wrong_valid"] not in ("",):
                wrong = (wrong or 0) + int(float(r["wrong_valid"]))
            ms.append(num(r["runtime_ms"]) + (num(r["t_extract_ms"]) if r.get("t_extract_ms") else 0.0))
    mean = lambda xs: statistics.mean(xs) if xs else math.nan
    errors = [num(s["final_mean_map_error"]) for s, _, _ in runs if s["final_mean_map_error"]]
    pct = lambda a, b: f"{100.0 * a / b:.1f}" if b else "-"
    fail = f" ({failed[key]} failed)" if failed.get(key) else ""
    print(f"| {key[0]} | {key[1]} | {key[2]} | {len(runs)}{fail} | {pct(cv, ct)} | {pct(ov, ot)} | "
          f"{'n/a' if wrong is None else wrong} | {mean(errors):.3g} | "
          f"{mean([float(s['walls_mapped']) for s, _, _ in runs]):.1f}/{mean([w for _, _, w in runs]):.1f} | "
          f"{mean([float(s['duplicates']) for s, _, _ in runs]):.2f} | {statistics.median(ms) if ms else math.nan:.3f} |")
PY
