#!/usr/bin/env bash
# The plane-extraction table of README "Plane extraction": EM2, EM1 and the Open3D
# baseline on the identical point frames of p-em-office-noise (E24: Map D, small frustum) and
# p-em-room-noise (E26: Map E, large frustum), σ_pt 0.05, seed 1, and the whole pipeline's time
# (extraction plus Relative Plane with parts 2-3 per iteration, simulator excluded).
# Usage: scripts/em_table.sh [out folder, default runs/em-table] [extra relslam --set ...]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-runs/em-table}"
shift || true
relslam="${RELSLAM:-$here/build/relslam}"
for scene in office room; do
  for extractor in em2 em1 ransac_open3d; do
    "$relslam" run "$here/scenarios/p-em-$scene-noise.json" --out "$out/$scene-$extractor" --force -q \
      --set relative_plane.extractor="$extractor" "$@"
  done
done
python3 - "$out" <<'PY'
import csv, statistics, sys, pathlib
out = pathlib.Path(sys.argv[1])
print("| map | extractor | frames | points/frame | median ms/frame | recall (frame mean) | precision (frame mean) | mean normal error (°) | pipeline median ms |")
print("|---|---|---|---|---|---|---|---|---|")
for scene, name in (("office", "D (small)"), ("room", "E (large)")):
    for extractor in ("em2", "em1", "ransac_open3d"):
        run = out / f"{scene}-{extractor}"
        rows = list(csv.DictReader(open(run / "em_frames.csv")))
        its = list(csv.DictReader(open(run / "relative_plane" / "iterations.csv")))
        mean = lambda key: statistics.mean(float(r[key]) for r in rows)
        normals = [float(r["mean_normal_err_deg"]) for r in rows if r["mean_normal_err_deg"]]
        pipeline = [float(r["runtime_ms"]) + float(r["t_extract_ms"]) for r in its]
        print(f"| {name} | {extractor} | {len(rows)} | {statistics.mean(int(r['n_points']) for r in rows):.0f} | "
              f"{statistics.median(float(r['ms']) for r in rows):.3f} | {mean('recall'):.4f} | {mean('precision'):.4f} | {statistics.mean(normals):.3f} | {statistics.median(pipeline):.3f} |")
PY
