#!/usr/bin/env bash
# scripts/reproduce.sh --quick end to end with the built binary: every step succeeds, every
# figure of the report and every render is there, and claims.md compares every row.
# Usage: reproduce_quick_test.sh <relslam binary> <source dir> <work dir>
set -euo pipefail
relslam=$(realpath "$1")
src=$(realpath "$2")
work=$(realpath -m "$3")
rm -rf "$work"
"$src/scripts/reproduce.sh" --quick --binary "$relslam" --out "$work/runs" --report "$work/report"
passed=0 failed=0
check() { if "${@:2}"; then passed=$((passed + 1)); else echo "FAIL: $1"; failed=$((failed + 1)); fi; }
for n in 127 128 129 $(seq 153 162); do
  check "render fig$n" test -s "$work/report/figures/fig$n.png"
done
# Only the Victoria Park figures may be missing, and only where the data is absent.
vp_data=${RELSLAM_VICTORIA_PARK:-$src/../shared/datasets/victoria_park}
allowed='^$'
[ -f "$vp_data/measurements.dat" ] || allowed='vp-'
pages=$work/all-pages.html  # the figures are on the chapter pages; index.html is the summary
cat "$work"/report/chapter*.html > "$pages"
check "no figure missing from the report" bash -c "! grep 'Not produced' '$pages' | grep -qv '$allowed'"
for n in 46 55 61 64 65 66 67 68 70 71 72 73 74 79 82 87 90 97 105 108 110 111 117 119 120 126 130 136 137 145 146 150 152 167 171; do
  check "figure $n in the report" grep -q "src=\"figures/fig$n.png\"" "$pages"
done
for name in paper6 paper7 paper8 e27-timing e29-em-compare e23-w-ma e28-noise-sweep; do
  check "figure $name in the report" grep -q "src=\"figures/$name.png\"" "$pages"
done

# Every figure drawn says what our run shows (its own text, or the series it drew).
without=$(/usr/bin/python3 - "$pages" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
print(" ".join(m.group(1) for m in re.finditer(r'<section id="([^"]+)">(.*?)</section>', s, re.S)
               if '<img src="figures/' in m.group(2) and 'class="shows"' not in m.group(2)))
PY
)
check "every drawn figure says what our run shows (not: $without)" [ -z "$without" ]
check "claims.md has no row left unrun" bash -c "! grep -q 'not run' '$work/report/claims.md'"
check "every claim judged (holds, partly or does not hold)" bash -c "! grep -q '| \*not judged\* |' '$work/report/claims.md'"
check "the summary judges the EKF accuracy claim (Fig 147)" \
  grep -q "Relative vs EKF position error, figure eight (Fig 147).*class=\"\(holds\|partly\|fails\)\"" "$work/report/index.html"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
