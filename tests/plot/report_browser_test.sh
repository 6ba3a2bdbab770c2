#!/usr/bin/env bash
# The report in a browser: a small report (one EKF comparison run cut to 150 iterations, the four
# planes run and one render) is generated and each of its pages is loaded in headless Chromium;
# every <img> must be there and decoded (naturalWidth > 0), the summary page must hold the comparison
# table and the claims with verdicts, and every page must link the others. Skipped (77) without
# chromium (Debian package `chromium`, installed by scripts/setup.sh).
# Usage: report_browser_test.sh <relslam binary> <source dir> <work dir>
set -uo pipefail
relslam=$(realpath "$1")
src=$(realpath "$2")
work=$(realpath -m "$3")
source "$src/tests/plot/checks.sh"
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIP: no chromium on PATH (scripts/setup.sh installs the Debian package chromium)"
  exit 77
fi
rm -rf "$work"
runs=$work/runs
report=$work/report
"$relslam" run "$src/scenarios/s-ekf-f8.json" --set sim.iterations=150 --out "$runs/s-ekf-f8" --force -q ||
  die "relslam run s-ekf-f8"
"$relslam" run "$src/scenarios/p-four-planes.json" --out "$runs/p-four-planes" --force -q || die "relslam run p-four-planes"
mkdir -p "$runs/renders"
"$relslam" render "$runs/s-ekf-f8" --out "$runs/renders/fig127.png" -q || die "relslam render"
printf 'figure,run,algorithm,iteration,view\n127,s-ekf-f8,relative_point,,top\n' > "$runs/renders/renders.csv"
/usr/bin/python3 "$src/scripts/plot/report.py" --runs "$runs" --out "$report" --quick > "$work/report.log" 2>&1
expect "report.py exits 0 (see $work/report.log)" [ $? -eq 0 ]

# Each page is copied beside itself with a script that, once the page has loaded, writes what it
# found into the body's data-check attribute; --dump-dom prints the DOM after the load.
probe='<script>window.addEventListener("load",()=>{const i=[...document.images];document.body.setAttribute("data-check",
JSON.stringify({images:i.length,broken:i.filter(x=>!x.complete||x.naturalWidth===0).map(x=>x.getAttribute("src")),
links:[...document.querySelectorAll("nav a")].map(a=>a.getAttribute("href"))}));});</script>'
load() {  # load PAGE: prints the page's data-check JSON
  local page=$report/$1 probe_page=$report/.probe-$1
  sed "s#</body>#${probe//$'\n'/}</body>#" "$page" > "$probe_page"
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --allow-file-access-from-files \
    --virtual-time-budget=10000 --dump-dom "file://$probe_page" 2>/dev/null |
    grep -o "data-check=\"[^\"]*\"" | sed 's/^data-check="//; s/"$//; s/&quot;/"/g'
  rm -f "$probe_page"
}
field() { /usr/bin/python3 -c 'import json, sys; print(json.loads(sys.argv[1])[sys.argv[2]])' "$1" "$2"; }
for page in index.html chapter4.html chapter5.html chapter6.html; do
  expect "$page written" [ -s "$report/$page" ]
  check=$(load "$page")
  if [ -z "$check" ]; then fail "$page: chromium loaded nothing"; continue; fi
  # (the small report has no Chapter 5 run: its page lists the figures as not produced)
  [ "$page" = chapter5.html ] || expect "$page: the page holds images" [ "$(field "$check" images)" -gt 0 ]
  broken=$(field "$check" broken)
  expect "$page: every image loads (broken: $broken)" [ "$broken" = "[]" ]
  for other in index.html chapter4.html chapter5.html chapter6.html claims.md; do
    expect "$page links $other" grep -q "'$other'" <<< "$(field "$check" links)"
  done
done
index=$report/index.html
expect "summary page compares Relative Point with the EKF" grep -q "<td>EKF (MRPT, 6D)</td>" "$index"
expect "summary page says how much faster Relative Point is" grep -q "Relative Point is [0-9.e+]*× faster" "$index"
expect "summary page judges the EKF accuracy claim (Fig 147)" \
  grep -q "Relative vs EKF position error, figure eight (Fig 147).*class=\"\(holds\|partly\|fails\)\"" "$index"
expect "summary page links the claim to its figure" grep -q 'href="chapter6.html#fig147"' "$index"
expect "the render is named by its caption" grep -q "Figure 127: render: Figure eight top view" "$report/chapter6.html"
expect "the render says what our run shows" grep -q "What our run shows:</b> Relative Point at iteration 149" \
  "$report/chapter6.html"
expect "claims.md has the verdict column" grep -q "^| quantity | thesis | ours | verdict | source file |$" \
  "$report/claims.md"
# A screenshot of the summary page for a person to look at (not checked).
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --window-size=1280,1600 \
  --screenshot="$work/summary.png" "file://$index" >/dev/null 2>&1 || true
summary
[ "$failed" -eq 0 ]
