#!/usr/bin/python3
"""A self-contained report of the thesis reproduction (Chapter 4's Relative Plane figures and Chapter
6's Relative Point figures): OUT/index.html shows, per thesis figure, its number, caption and what
the thesis says next to our plot (figures.py, with a line on what our run shows where the figure
measures one) or render (RUNS/renders/fig<N>.png from `relslam render`), and lists the figures no
run can make yet (catalogue.PENDING) with the reason; OUT/claims.md holds the thesis's numbers and
facts next to ours (claims.py). Images live in OUT/figures/ and are referenced relatively.

Usage: /usr/bin/python3 scripts/plot/report.py --runs RUNS --out report [--quick]
  --quick   the runs were shortened (scripts/reproduce.sh --quick): both files say so at the top
Exit codes: 0 written (missing runs are listed in the report), 1 some file was malformed.
"""
import argparse
import html
import os
import shutil
import sys

import catalogue
import claims
import figures as fg

QUICK = "Quick mode: the runs are shortened, so these numbers differ from full runs and from the thesis."


def copy_renders(runs, figures_dir):
    """{render number: image path relative to the report, or None when relslam render made none}."""
    found = {}
    for number in catalogue.RENDERS:
        source = os.path.join(runs, "renders", f"fig{number}.png")
        if os.path.exists(source):
            shutil.copyfile(source, os.path.join(figures_dir, f"fig{number}.png"))
        found[number] = f"figures/fig{number}.png" if os.path.exists(source) else None
    return found


def section(key, title, image, problem, source, shows="", pending=""):
    caption, statement = catalogue.CATALOGUE[key]
    label = f"Figure {key}" if isinstance(key, int) else "Extra"
    body = (f'<img src="{html.escape(image)}" alt="{html.escape(label)}">' if image
            else f'<p class="pending">Not reproducible yet: {html.escape(pending)}</p>' if pending
            else f'<p class="missing">Not produced: {html.escape(problem)}</p>')
    if shows:
        body = f'<p class="shows"><b>What our run shows:</b> {html.escape(shows)}</p>\n' + body
    anchor = f"fig{key}" if isinstance(key, int) else str(key)
    return (f'<section id="{html.escape(anchor)}"><h2>{label}: {html.escape(title)}</h2>\n'
            f'<p class="caption"><b>Thesis caption:</b> {html.escape(caption)}</p>\n'
            f'<p class="thesis"><b>What the thesis says:</b> {html.escape(statement)}</p>\n'
            f'<p class="source">Ours from: <code>{html.escape(source)}</code></p>\n{body}</section>\n')


def figure_sections(results, renders):
    """Sections in thesis order: charts and renders by number, extras last."""
    entries = []
    for r in results:
        problem = {"missing": f"missing run {r.detail}", "error": r.detail}.get(r.status, "")
        image = f"figures/{r.figure.name}.png" if r.status == "ok" else None
        order = r.figure.id if isinstance(r.figure.id, int) else 1000
        entries.append((order, section(r.figure.id, r.figure.title, image, problem, ", ".join(r.figure.runs),
                                       r.shows)))
    for number, image in renders.items():
        problem = f"no renders/fig{number}.png in the runs folder (relslam render makes it)"
        entries.append((number, section(number, "render", image, problem, f"renders/fig{number}.png")))
    for number, reason in catalogue.PENDING.items():
        entries.append((number, section(number, "not reproducible yet", None, "", "no run yet", pending=reason)))
    return [text for _, text in sorted(entries, key=lambda e: e[0])]


def write_index(path, runs, results, renders, quick):
    made = sum(r.status == "ok" for r in results) + sum(v is not None for v in renders.values())
    total = len(results) + len(renders)  # PENDING figures are listed, not counted
    missing = sorted({r.detail for r in results if r.status == "missing"})
    notes = [f'<p class="quick">{QUICK}</p>'] if quick else []
    notes.append(f"<p>{made} of {total} figures produced from <code>{html.escape(runs)}</code>. "
                 f'Thesis numbers against ours: <a href="claims.md">claims.md</a>.</p>')
    if missing:
        notes.append(f"<p>Missing runs: {html.escape('; '.join(missing))}.</p>")
    style = ("body{font-family:sans-serif;max-width:1100px;margin:auto}img{max-width:100%}"
             ".missing{color:#a00}.pending{color:#864}.shows{background:#eef6ee;padding:.3em}"
             ".quick{background:#ffd;padding:.5em;border:1px solid #cc9}"
             "section{border-top:1px solid #ccc;margin-top:1em}")
    with open(path, "w") as f:
        f.write(f'<!DOCTYPE html>\n<html><head><meta charset="utf-8"><title>relslam: thesis Chapters 4 and 6 figures'
                f'</title><style>{style}</style></head><body>\n<h1>Relative SLAM: thesis Chapter 4 (Relative Plane) '
                f'and Chapter 6 (Relative Point) figures</h1>\n{"".join(notes)}\n'
                f'{"".join(figure_sections(results, renders))}</body></html>\n')


def write_claims(path, runs, quick):
    lines = [f"> {QUICK}", ""] if quick else []
    lines += ["# Thesis numbers against ours", "",
              f"Computed from the run folders in `{runs}` (spec relative_point.md §10; the Relative Plane rows: "
              "relative_plane_em.md §6.3, experiments E01-E10, E12, E15, E18, E21, E31, E32). The thesis ran on an "
              "Athlon 64 3400+ (2004): compare ratios and shapes, not milliseconds.", "",
              "| quantity | thesis | ours | source file |", "|---|---|---|---|"]
    rows = claims.rows(runs)
    lines += ["| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |" for row in rows]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return sum(row[2].startswith("error:") for row in rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", required=True, help="folder holding the run folders")
    parser.add_argument("--out", required=True, help="report folder (index.html, claims.md, figures/)")
    parser.add_argument("--quick", action="store_true", help="the runs are shortened; say so")
    args = parser.parse_args()
    figures_dir = os.path.join(args.out, "figures")
    os.makedirs(figures_dir, exist_ok=True)
    results = fg.render_all(args.runs, figures_dir)
    renders = copy_renders(args.runs, figures_dir)
    for number, image in renders.items():
        if image is None:
            print(f"fig{number}: render not produced (no {os.path.join(args.runs, 'renders', f'fig{number}.png')})")
    write_index(os.path.join(args.out, "index.html"), args.runs, results, renders, args.quick)
    claim_errors = write_claims(os.path.join(args.out, "claims.md"), args.runs, args.quick)
    print(f"report: wrote {os.path.join(args.out, 'index.html')} and {os.path.join(args.out, 'claims.md')}")
    return 1 if claim_errors or any(r.status == "error" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
