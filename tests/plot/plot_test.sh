#!/usr/bin/env bash
# The thesis figure scripts (scripts/plot/figures.py, report.py, claims.py) against a tiny fixture
# of real, seeded, shortened runs of the relslam binary (every folder scripts/reproduce.sh makes,
# the planar Chapter 4 and the point-sensor Chapter 5 ones included):
# each figure renders a valid PNG of the expected size, the report references every figure and
# render, claims.md has every row, a missing run folder is skipped by name and a malformed CSV is
# reported by file and column without a traceback. Takes about a minute on two cores.
#
# Usage: tests/plot/plot_test.sh <relslam binary> <source dir> <work dir>
#   Victoria Park figures need the data set ($RELSLAM_VICTORIA_PARK, else <source dir>/../shared/
#   datasets/victoria_park); the timing chart needs relslam_bench_victoria_park
#   ($RELSLAM_BENCH_VICTORIA_PARK, else bench/ next to the relslam binary). Without them those
#   figures are skipped with a message.
set -uo pipefail
[ $# -eq 3 ] || { echo "usage: $0 <relslam binary> <source dir> <work dir>" >&2; exit 2; }
relslam=$(realpath "$1")
src=$(realpath "$2")
work=$(realpath -m "$3")
python=/usr/bin/python3  # Debian's, with matplotlib
plot=$src/scripts/plot
vp_data=${RELSLAM_VICTORIA_PARK:-$src/../shared/datasets/victoria_park}
vp_bench=${RELSLAM_BENCH_VICTORIA_PARK:-$(dirname "$relslam")/bench/relslam_bench_victoria_park}
SIZE="1000 600"  # figures.py FIGSIZE x DPI

source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"

runs=$work/runs
rm -rf "$runs" "$work/figures" "$work/report" "$work/empty" "$work/bad"
mkdir -p "$runs" "$work/empty" || die "cannot create $work"
cd "$src" || die "no source dir $src"

# ---- fixture: shortened real runs ------------------------------------------------------------
make_run() {  # make_run FOLDER relslam-arguments...
  local out=$1
  shift
  "$relslam" "$@" --out "$runs/$out" -q || die "relslam $* --out $runs/$out failed"
}
short=(--set sim.iterations=150)
make_run s-f8 run scenarios/s-f8.json "${short[@]}"
make_run s-f8-first-three run scenarios/s-f8.json "${short[@]}" --set relative_point.basis=first_three
make_run s-f8-2l run scenarios/s-f8-2l.json "${short[@]}"
make_run s-f8-2l-rebuilt run scenarios/s-f8-2l.json "${short[@]}" --set relative_point.global_index=rebuilt
make_run s-f8-2l-const sweep scenarios/s-f8-2l-const.json --set sim.iterations=60
make_run s-f8-7l-const sweep scenarios/s-f8-7l-const.json --set sim.iterations=60
make_run s-f8-2x run scenarios/s-f8-2x.json --set sim.iterations=250
make_run s-dens-q sweep scenarios/s-dens-q.json --param sim.density=25,50,75 --set sim.iterations=60
make_run s-dens-qs sweep scenarios/s-dens-qs.json --param sim.density=25,50,75 --set sim.iterations=60
make_run s-dens-o sweep scenarios/s-dens-o.json --param sim.density=75,100 --set sim.iterations=60
make_run s-bin bench-binning scenarios/s-bin.json --set 'binning_bench.points=[20,40,60]' \
  --set 'binning_bench.percentages=[0,10,20,30,40,45,47,50,90]' --set binning_bench.seeds=2
make_run s-dyn3 run scenarios/s-dyn3.json "${short[@]}"
make_run s-dyn3-no-binning run scenarios/s-dyn3.json "${short[@]}" --set relative_point.final_group.binning=false
make_run s-ekf-f8 run scenarios/s-ekf-f8.json --set sim.iterations=80
make_run s-line run scenarios/s-line.json --set sim.iterations=80
make_run s-stat run scenarios/s-stat.json --set sim.iterations=80
make_run s-dyn run scenarios/s-dyn.json "${short[@]}"
make_run s-40 run scenarios/s-40.json --set sim.iterations=400
# Chapter 4 (planar): seconds in all; two loops of Map A are enough for the first-vs-last-loop claim.
make_run p-four-planes run scenarios/p-four-planes.json --set planar.loops=2
make_run p-e01-invariance run scenarios/p-e01-invariance.json
make_run p-hallway run scenarios/p-hallway.json
make_run p-office run scenarios/p-office.json --set planar.iterations=400
make_run p-e05-edge-on sweep scenarios/p-e05-edge-on.json --set planar.iterations=900
make_run p-e06-rule12 sweep scenarios/p-e06-rule12.json --set planar.iterations=400
make_run p-e31-chain-order sweep scenarios/p-e31-chain-order.json --set planar.iterations=300
make_run p-e21-completed-map run scenarios/p-e21-completed-map.json --set planar.iterations=400
make_run p-e10-rule21-22 sweep scenarios/p-e10-rule21-22.json --set planar.iterations=400
# experiments (Relative Plane part 2), shortened the same way.
make_run p-e02-key-point-pairs run scenarios/p-e02-key-point-pairs.json --set planar.iterations=600
make_run p-e07-interval-mode sweep scenarios/p-e07-interval-mode.json --set planar.iterations=300 --seeds 2
make_run p-e08-bad-key-points sweep scenarios/p-e08-bad-key-points.json --set planar.iterations=400
make_run p-e09-plane5 sweep scenarios/p-e09-plane5.json --set planar.iterations=400
make_run p-e12-rule28 sweep scenarios/p-e12-rule28.json --set planar.iterations=400
make_run p-e15-loop-closure-map-e sweep scenarios/p-e15-loop-closure-map-e.json --set planar.iterations=400
make_run p-e18-collinear run scenarios/p-e18-collinear.json --set planar.iterations=400
make_run p-e32-runtime sweep scenarios/p-e32-runtime.json --set planar.iterations=300
make_run p-e19-save-system sweep scenarios/p-e19-save-system.json --set planar.iterations=300
make_run p-e20-pseudo-merge sweep scenarios/p-e20-pseudo-merge.json --set planar.iterations=300
# experiments (Relative Plane part 3): E17's interval checks, hints and roll-back; the motion
# model's E11 (whole, Map E1 is 351 iterations), E13, E14 (whole), E16 and E22 (the second corner is on
# the shortened run's second "loop").
make_run p-e17-interval-check sweep scenarios/p-e17-interval-check.json --set planar.iterations=400
make_run p-e11-first-corner sweep scenarios/p-e11-first-corner.json --seeds 2
make_run p-e13-grow-threshold sweep scenarios/p-e13-grow-threshold.json --set planar.iterations=300
make_run p-e14-frustum-shape sweep scenarios/p-e14-frustum-shape.json
make_run p-e16-rule29 sweep scenarios/p-e16-rule29.json --set planar.iterations=300
make_run p-e22-one-partial-plane run scenarios/p-e22-one-partial-plane.json --set planar.iterations=600

expected=(64 65 66 67 70 71 72 73)  # Chapter 4
expected+=(68 $(seq 74 82) 87 90 91 92 97 e32-runtime)  # experiments
expected+=(94 98 99 101 102)  # E17, E19, E20
expected+=(69 83 84 85 86 88 89 93 95 96 100)  # E22, E11, E13, E14, E16, E17, E19

# Chapter 5 (points -> EM -> Relative Plane): short runs of E23-E27, the test bench, E29.
make_run p-em-office run scenarios/p-em-office.json --set planar.iterations=150
make_run p-em-office-noise run scenarios/p-em-office-noise.json --set planar.iterations=150
make_run p-em-room run scenarios/p-em-room.json --set planar.iterations=150
make_run p-em-room-noise run scenarios/p-em-room-noise.json --set planar.iterations=150
make_run p-em-demo sweep scenarios/p-em-demo.json --set planar.iterations=100 --jobs 1
make_run em-bench em-bench scenarios/p-em-office-noise.json --seeds 2
make_run e29-office em-bench scenarios/p-em-compare-office.json --compare --set planar.iterations=40
make_run e29-room em-bench scenarios/p-em-compare-room.json --compare --set planar.iterations=40
# E23's w_ma variants on E23 and E24, and E28's noise sweep (two seeds, so noise_sweep.csv averages them).
make_run p-em-office-w-ma sweep scenarios/p-em-office.json --set planar.iterations=150
make_run p-em-office-noise-w-ma sweep scenarios/p-em-office-noise.json --set planar.iterations=150
make_run p-em-noise-sweep sweep scenarios/p-em-noise-sweep.json --set planar.iterations=60 --seeds 2
"$python" "$plot/noise_sweep.py" "$runs/p-em-noise-sweep" >/dev/null || die "noise_sweep.py failed"
noise_csv=$runs/p-em-noise-sweep/noise_sweep.csv
expect "noise_sweep.csv: header" [ "$(head -1 "$noise_csv")" = "variant,point_sigma,inlier_distance,seeds,frames,\
em_recall,em_precision,mean_normal_err_deg,em_median_ms,final_mean_map_error,final_mean_map_error_std,walls_mapped,walls_seen,\
duplicates,pose_valid_fraction" ]
expect "noise_sweep.csv: one row per σ_pt, ascending, two seeds each" [ "$(tail -n +2 "$noise_csv" | cut -d, -f2,4 | \
  tr '\n' ' ')" = "0,2 0.025,2 0.05,2 0.1,2 0.15,2 0.2,2 " ]
expect "noise_sweep.csv: noise-free EM normal error under 0.01°" \
  awk -F, 'NR == 2 { exit !($8 != "" && $8 < 0.01) }' "$noise_csv"
out=$("$python" "$plot/noise_sweep.py" "$work/empty" 2>&1)
expect "noise_sweep.py on a folder without a sweep: exit 1" [ $? -eq 1 ]
expect "noise_sweep.py names the missing sweep.csv" grep -q "empty/sweep.csv: file not found" <<<"$out"

expected+=(46 55 56 57 58 59 60 61 105 106 107 108 paper6 paper7 paper8 e27-timing e29-em-compare)  # Chapter 5
expected+=(e23-w-ma e28-noise-sweep)
expected+=(110 111 112 113 114 115 116 117 $(seq 119 126) $(seq 130 152) $(seq 167 171) components)
if [ -d "$vp_data" ]; then
  make_run vp-1181 victoria-park --data "$vp_data" --window 1181:1230
  make_run vp-4220 victoria-park --data "$vp_data" --window 4220:4270
  expected+=(163 164 165 166)
  if [ -x "$vp_bench" ]; then
    RELSLAM_VICTORIA_PARK=$vp_data "$vp_bench" --benchmark_filter='BM_VictoriaParkLevels/[123]/0' \
      --benchmark_format=json >"$runs/vp-timing.json" 2>/dev/null || die "$vp_bench failed"
    expected+=(vp-timing)
  else
    echo "note: no $vp_bench: the Victoria Park timing chart is not tested"
  fi
else
  echo "note: no Victoria Park data at $vp_data: Figs 163-166 and the timing chart are not tested"
fi
png_name() { case $1 in [0-9]*) echo "fig$1.png" ;; *) echo "$1.png" ;; esac; }

# ---- fit helpers -----------------------------------------------------------------------------
expect "fit helpers (tests/plot/fit_test.py)" "$python" "$src/tests/plot/fit_test.py" "$src"

# ---- figures.py: every figure ----------------------------------------------------------------
log=$work/figures.log
"$python" "$plot/figures.py" --runs "$runs" --out "$work/figures" >"$log" 2>&1
expect "figures.py exits 0 (see $log)" [ $? -eq 0 ]
expect "figures.py reports no error (see $log)" not grep -q ": error:" "$log"
check_png() {  # check_png FILE: exists, non-empty, a PNG of SIZE pixels
  local size
  [ -s "$1" ] || { fail "$1 missing or empty"; return; }
  size=$("$python" "$src/tests/plot/png_size.py" "$1") || { fail "$1 is not a PNG"; return; }
  if [ "$size" = "$SIZE" ]; then ok; else fail "$1 is $size pixels, expected $SIZE"; fi
}
for id in "${expected[@]}"; do
  check_png "$work/figures/$(png_name "$id")"
done
expect "figures.py writes nothing but the PNGs" [ "$(find "$work/figures" -type f ! -name '*.png' | wc -l)" -eq 0 ]

# ---- report.py -------------------------------------------------------------------------------
mkdir -p "$runs/renders"
# Two real renders (relslam render replays the run); the others stay missing on purpose.
"$relslam" render "$runs/s-f8" --view side --width 800 --height 600 --out "$runs/renders/fig128.png" -q
expect "relslam render writes fig128" [ -s "$runs/renders/fig128.png" ]
# what reproduce.sh records beside its renders: the run, algorithm and iteration each one drew
printf 'figure,run,algorithm,iteration,view\n128,s-f8,relative_point,,side\n' > "$runs/renders/renders.csv"
expect "the render is 800x600" [ "$("$python" "$src/tests/plot/png_size.py" "$runs/renders/fig128.png")" = "800 600" ]
"$python" "$plot/report.py" --runs "$runs" --out "$work/report" --quick >"$work/report.log" 2>&1
expect "report.py exits 0 (see $work/report.log)" [ $? -eq 0 ]
index=$work/report/index.html
claims_md=$work/report/claims.md
expect "index.html written" [ -s "$index" ]
expect "index.html says quick mode" grep -q "Quick mode" "$index"
# The figures live on the chapter pages (index.html is the summary): search them all.
pages=$work/all-pages.html
cat "$work"/report/chapter*.html > "$pages"
for page in chapter4.html chapter5.html chapter6.html; do
  expect "$page written, with the summary page's navigation" grep -q 'href="index.html">Summary' "$work/report/$page"
done
expect "index.html compares Relative Point with the EKF" grep -q "Relative Point against the EKF" "$index"
expect "index.html lists the claims with verdicts" grep -q "do they hold in our runs" "$index"
for id in "${expected[@]}"; do
  name=$(png_name "$id")
  expect "the chapter pages show $name" grep -q "src=\"figures/$name\"" "$pages"
  expect "report/figures/$name exists" [ -s "$work/report/figures/$name" ]
done
expect "the chapter pages show the render fig128" grep -q 'src="figures/fig128.png"' "$pages"
for n in 127 129 $(seq 153 162); do
  expect "the chapter pages list render $n as not produced" grep -q "no renders/fig$n.png" "$pages"
done
expect "the chapter pages have thesis captions" grep -q "Figure eight landmark error" "$pages"
expect "the chapter pages have thesis statements" grep -q "What the thesis says" "$pages"
expect "the chapter pages have the paper's captions" grep -q "The lines from the planes signify which grouping" "$pages"

# Every figure drawn says what our run shows (its own text, or the series it drew).
without=$(/usr/bin/python3 - "$pages" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
print(" ".join(m.group(1) for m in re.finditer(r'<section id="([^"]+)">(.*?)</section>', s, re.S)
               if '<img src="figures/' in m.group(2) and 'class="shows"' not in m.group(2)))
PY
)
expect "every drawn figure says what our run shows (not: $without)" [ -z "$without" ]
expect "the chapter pages say what our planar runs show" grep -q "What our run shows:</b> 4 of 4 seen walls mapped" "$pages"
expect "the chapter pages say what the E02 pair shows (Fig 68, paper Fig 4)" \
  grep -q "What our run shows:</b> RltPlanes [0-9]* and [0-9]*, iterations" "$pages"
expect "claims.md written" [ -s "$claims_md" ]
expect "claims.md says quick mode" grep -q "Quick mode" "$claims_md"
expect "claims.md has the table header" grep -q "^| quantity | thesis | ours | verdict | source file |$" "$claims_md"
for row in "loop length" "RltPoints / groups / final groups" "visible points per observation (ρ ≈ 100)" \
  "run time after loop closure" "binning overhead" "octree vs quad at ρ = 400: init" \
  "octree vs quad at ρ = 400: load" "ρ = 550: time per iteration" "ρ = 550: visible points" \
  "ρ = 550: total points" "share of minimum computation" "Relative vs EKF" "dynamic test" \
  "Victoria Park per scan, 1" "Victoria Park per scan, 2" "Victoria Park per scan, 3" \
  "E01 Rule 3 invariance" "E03 four planes: no drift" "E03 four planes: map correct" "E04 hallway" \
  "E05 (a)" "E05 (b)" "E05 (c)" "E06 Rule 12 on vs off" "E31 Rule 2" \
  "E02 key-point pairs" "E07 interval mode" "E08 wrong key points heal" "E09 plane 5" "E10 Rule 22" \
  "E12 Rule 28" "E15 Map E loop closure" "E18 collinear pieces" "E32 time per iteration" \
  "E19 save system" "E20 pseudo plane merging" \
  "E11 first motion-model test" "E13 growth threshold" "E14 frustum shape" "E16 Rule 29" "E22 one partial plane" \
  "E23 Map D, points" "E24 E23 with point noise" "E25 Map E, points" "E26 E25 with point noise" \
  "E27 paper demo without noise" "E27 paper demo with noise" "E27 real time including EM" "E30 EM test bench" "E29 EM2 vs EM1" \
  "E23 moving-average window" "E28 noise sweep"; do
  expect "claims.md row '$row'" grep -q "^| $row" "$claims_md"
done
expect "claims.md: E20 compares Rule 37 on and off" \
  grep -q "^| E20 pseudo plane merging.*| seed-1: [0-9]* one-way link(s), current group differs in [0-9]* iteration(s)" "$claims_md"
expect "claims.md computes RltPoints from s-f8" \
  grep -q "^| RltPoints.*| [0-9]* / [0-9]* / [0-9]* .*s-f8/relative_point/iterations.csv\` |$" "$claims_md"
expect "claims.md: E03 compares loop 1 with loop 2" \
  grep -q "^| E03 four planes: no drift.*| no drift: mean map error per plane, loop 1 [0-9.e-]*, loop 2 " "$claims_md"
expect "claims.md: E04's hallway map is correct" \
  grep -q "^| E04 hallway.*| 4 groups, 3 links .*; correct: " "$claims_md"
expect "claims.md: E05 (c) map is correct" grep -q "^| E05 (c).*| c_cull_on_rule10_on: correct: " "$claims_md"
expect "claims.md: E29 compares EM1 and EM2 on both maps" \
  grep -q "^| E29 EM2 vs EM1.*| e29-office (40 frames): EM2 .* (EM1/EM2 [0-9.]*).*; e29-room (40 frames): " "$claims_md"
expect "claims.md: E27 gives ms per iteration of EM and RP" \
  grep -q "^| E27 real time including EM.*| office_no_noise: EM [0-9.e-]* + RP [0-9.e-]* ms median" "$claims_md"
expect "claims.md: E23's w_ma row gives every window without and with noise" \
  grep -q "^| E23 moving-average window.*| p-em-office-w-ma: w_ma_3: .* w_ma_5: .* w_ma_8: .* — p-em-office-noise-w-ma: w_ma_3: " \
  "$claims_md"
expect "claims.md: E28 reads noise_sweep.csv, two seeds per σ_pt" \
  grep -q "^| E28 noise sweep.*| 2 seed(s) per σ_pt; map error .* σ_pt 0.2: EM recall .*| \`p-em-noise-sweep/noise_sweep.csv\` |$" \
  "$claims_md"
expect "the chapter pages have the paper's Fig 6 caption" grep -q "An example of the simulation used to test the algorithm" "$pages"
expect "claims.md: every simulated row has a number" \
  [ "$(grep -v 'Victoria Park' "$claims_md" | grep -c '| not run |')" -eq 0 ]
expect "claims.md: no errors" not grep -q "| error:" "$claims_md"
expect "claims.md: E11 places the motion model before the turn" \
  grep -q "^| E11 first motion-model test.*| 2 seed(s): the motion model starts [0-9.]*-[0-9.]* units before the turn" \
  "$claims_md"
expect "claims.md: E14's planar small frustum sees past f = 7, the radial one does not" \
  grep -q "^| E14 frustum shape.*planar_small: .*farthest end 8\.[01][0-9]*;.*radial_small: .*farthest end [67][.0-9]*;" \
  "$claims_md"
expect "claims.md: E17 counts the roll-backs with the checks on" \
  grep -q "^| E17 interval checks.*interval_check_off: .* 0 roll-back(s) .*interval_check_on: .* [1-9][0-9]* roll-back(s) from " "$claims_md"

# ---- missing and malformed inputs ------------------------------------------------------------
out=$("$python" "$plot/figures.py" --runs "$work/empty" --out "$work/empty/figures" 2>&1)
expect "missing runs: exit 0" [ $? -eq 0 ]
expect "missing runs: Fig 146 skipped naming s-ekf-f8" grep -q "fig146: skipped, missing s-ekf-f8" <<<"$out"
expect "missing runs: no PNG written" [ ! -e "$work/empty/figures/fig146.png" ]
expect "missing runs: Fig 70 skipped naming p-four-planes" grep -q "fig70: skipped, missing p-four-planes" <<<"$out"
"$python" "$plot/report.py" --runs "$work/empty" --out "$work/empty/report" >/dev/null 2>&1
expect "missing runs: report exits 0" [ $? -eq 0 ]
expect "missing runs: claims say not run" \
  grep -q "| RltPoints.*| not run | \*not run\* | missing s-f8 |" "$work/empty/report/claims.md"

mkdir -p "$work/bad"
cp -r "$runs/s-ekf-f8" "$runs/s-f8" "$work/bad/"
sed -i '1s/landmark_error/landmark_err/' "$work/bad/s-ekf-f8/ekf6d/iterations.csv"
sed -i '3s/^\([0-9]*\),[^,]*,/\1,oops,/' "$work/bad/s-f8/relative_point/iterations.csv"
out=$("$python" "$plot/figures.py" --runs "$work/bad" --out "$work/bad/figures" --fig 146 119 2>&1)
expect "malformed CSV: exit 1" [ $? -eq 1 ]
expect "malformed CSV: names the file and missing column" \
  grep -q "s-ekf-f8/ekf6d/iterations.csv: missing column(s) landmark_error" <<<"$out"
expect "malformed CSV: no traceback" not grep -q "Traceback" <<<"$out"
expect "malformed CSV: Fig 119 skipped naming s-f8-first-three" \
  grep -q "fig119: skipped, missing s-f8-first-three" <<<"$out"
mkdir -p "$work/bad/s-f8-first-three"
out=$("$python" "$plot/figures.py" --runs "$work/bad" --out "$work/bad/figures" --fig 119 2>&1)
expect "bad value: Fig 119 reports file, line and column" \
  grep -q "s-f8/relative_point/iterations.csv: line 3: column landmark_error: not a number" <<<"$out"
out=$("$python" "$plot/figures.py" --runs "$work/bad" --out "$work/bad/figures" --fig 999 2>&1)
expect "unknown figure: exit 2" [ $? -eq 2 ]

summary
[ "$failed" -eq 0 ]
