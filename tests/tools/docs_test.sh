#!/usr/bin/env bash
# Docs.BuildWithoutWarnings: the documentation site builds with `mkdocs build --strict` (no
# warning, no broken internal link) into a scratch folder, the generated scenario-keys page lists
# every key `relslam keys` prints, README.md stays under 200 lines, and neither README.md, docs/,
# the code, the tests nor the scenario files cite the internal design notes or issue numbers.
#   docs_test.sh RELSLAM SOURCE_DIR SCRATCH_DIR
# Exit 77 (skipped) when mkdocs is not installed.
set -euo pipefail
relslam=$1 src=$2 scratch=$3
fail=0

lines=$(wc -l < "$src/README.md")
if [ "$lines" -ge 200 ]; then
  echo "FAIL: README.md has $lines lines; keep it under 200 (move detail into docs/)"; fail=1
fi
if hits=$(grep -rn -e '\.\./shared/specs' -e 'spec §' "$src/README.md" "$src/docs" --include='*.md' --include=README.md); then
  echo "FAIL: README.md or docs/ cites the internal design notes (cite the thesis instead):"; echo "$hits"; fail=1
fi
# Nor do the code, the tests or the scenario files: no design-note section ("spec §5.8", "spec A38",
# "(spec 4.1.2)"), no issue number. The Victoria Park data's default folder under ../shared is a path,
# not a citation.
if hits=$(grep -rnE -e '\bspecs?( [a-z_]+\.md)? ?(§|A[0-9]|[0-9]+\.[0-9])' -e "\bspec's\b" -e '\b[Ii]ssues? #?[0-9]+' \
            -e '\.\./shared/specs' "$src/libslam" "$src/sim" "$src/eval" "$src/tests" "$src/scenarios" "$src/scripts" \
            "$src/bench" --include='*.cpp' --include='*.hpp' --include='*.py' --include='*.sh' --include='*.json' |
          grep -v -e 'tests/tools/docs_test.sh' -e 'scripts/docs.sh'); then
  echo "FAIL: code, tests or scenarios cite the internal design notes or an issue (cite the thesis instead):"
  echo "$hits"; fail=1
fi

if ! command -v mkdocs >/dev/null 2>&1; then
  echo "SKIP: mkdocs is not installed (apt-get install mkdocs mkdocs-material); README checks: $([ $fail -eq 0 ] && echo passed || echo FAILED)"
  [ $fail -eq 0 ] && exit 77 || exit 1
fi

# Build from a copy, so the test never writes into the source tree.
rm -rf "$scratch"; mkdir -p "$scratch/src"
cp -r "$src/docs" "$src/mkdocs.yml" "$src/scenarios" "$scratch/src/"
mkdir -p "$scratch/src/scripts"; cp "$src/scripts/docs.sh" "$scratch/src/scripts/"
rm -f "$scratch/src/docs/reference/keys.md" "$scratch/src/docs/reference/scenario-list.md"
if ! (cd "$scratch/src" && bash scripts/docs.sh "$relslam" "$scratch/site") > "$scratch/build.log" 2>&1; then
  echo "FAIL: scripts/docs.sh (mkdocs build --strict) failed:"; grep -v '^INFO' "$scratch/build.log" | tail -30; fail=1
elif grep -E '^(WARNING|ERROR)' "$scratch/build.log"; then
  echo "FAIL: mkdocs warned"; fail=1
fi

keys_page="$scratch/src/docs/reference/keys.md"
missing=0
while read -r key; do
  grep -qF "| \`$key\` |" "$keys_page" 2>/dev/null || { echo "FAIL: the keys page lacks $key"; missing=$((missing + 1)); }
done < <("$relslam" keys | sed -n 's/^\([a-z0-9_.]*\) = .*/\1/p')
count=$("$relslam" keys | grep -c '^[a-z0-9_.]* = ' || true)
if [ "$count" -lt 50 ]; then echo "FAIL: relslam keys printed only $count keys"; fail=1; fi
[ $missing -eq 0 ] || fail=1
for page in index.html reference/keys.html algorithms/relative-plane.html; do
  [ -f "$scratch/site/$page" ] || { echo "FAIL: the site lacks $page"; fail=1; }
done

if [ $fail -eq 0 ]; then echo "docs: site built without warnings; the keys page lists all $count keys; README.md $lines lines"; fi
exit $fail
