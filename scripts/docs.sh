#!/usr/bin/env bash
# Builds the documentation site into site/ (or OUT) with MkDocs, warnings as errors.
#   scripts/docs.sh [RELSLAM [OUT]]     RELSLAM: the relslam binary (default build/relslam)
# First generates, from the code and the shipped files (never kept by hand, gitignored):
#   docs/reference/keys.md          every scenario key: `relslam keys --markdown`
#   docs/reference/scenario-list.md every file in scenarios/ with its kind and description
# Needs the Debian packages mkdocs and mkdocs-material (scripts/setup.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h|--help) sed -n '2,7p' "$0"; exit 0 ;; esac
relslam=${1:-build/relslam}
out=${2:-site}
command -v mkdocs >/dev/null || { echo "docs: mkdocs is not installed (apt-get install mkdocs mkdocs-material, or scripts/setup.sh)" >&2; exit 1; }
[ -x "$relslam" ] || { echo "docs: no relslam binary at $relslam (build it: cmake --build build --target relslam, or give its path)" >&2; exit 1; }

mkdir -p docs/reference
{
  cat <<'HEAD'
# Scenario keys

Every key a scenario file may set, with its type, default and meaning. This page is generated
at build time from the code (`relslam keys --markdown`), so it always matches the binary;
`relslam keys PREFIX` prints the same on the terminal (e.g. `relslam keys ekf6d`), and
`--set key=value` overrides any of them on the command line.

Tags in the meaning column: `[T]` the thesis's choice, `[C]` a choice of ours.

HEAD
  "$relslam" keys --markdown
} > docs/reference/keys.md

python3 - <<'PY'
import glob, json, os, re
rows = []
for path in sorted(glob.glob('scenarios/*.json')):
    with open(path) as f:
        d = json.load(f)
    desc = d.get('description') or ''
    # Descriptions may cite internal work items; the docs cite the thesis only.
    desc = re.sub(r'\s*\(spec [^()]*\)', '', desc)
    desc = re.sub(r'as spec [0-9.]+ checks', 'as checked', desc)
    desc = re.sub(r'[;,]?\s*spec §?[0-9.]+', '', desc)
    desc = desc.replace("the spec's", 'the planned')
    desc = re.sub(r',?\s*issue \d+', '', desc)
    desc = desc.replace('(, ', '(').replace('()', '').replace('|', '\\|').replace('\n', ' ')
    rows.append(f"| `{os.path.basename(path)}` | {d.get('kind', 'simulation')} | {desc} |")
with open('docs/reference/scenario-list.md', 'w') as f:
    f.write('# Every scenario file\n\n'
            'Generated at build time from `scenarios/*.json` (each file\'s `kind` and `description`). '
            '`relslam scenario FILE` prints a file with every default filled in.\n\n'
            '| file | kind | what it reproduces |\n|---|---|---|\n' + '\n'.join(rows) + '\n')
PY

mkdocs build --strict --site-dir "$out"
echo "docs: site in $out/ (open $out/index.html)"
