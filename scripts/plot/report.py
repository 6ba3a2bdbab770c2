#!/usr/bin/python3
"""The report of the thesis reproduction, answers first.

OUT/index.html is the summary page: Relative Point against the EKF and the other baselines (errors
and time per iteration, with the numbers, from summary.csv of each comparison run) and every thesis
claim with its verdict (holds / partly / does not hold, claims.py) and its figure. One page per
thesis chapter follows (OUT/chapter4.html, chapter5.html, chapter6.html): each figure with its
number, caption, what the thesis says, what our run shows and our plot (figures.py) or render
(RUNS/renders/fig<N>.png from `relslam render`, named by its caption); the figures no run can make
yet are listed with the reason (catalogue.PENDING). OUT/claims.md holds the thesis's numbers and
facts next to ours with the verdict. Images live in OUT/figures/ and are referenced relatively.

Usage: /usr/bin/python3 scripts/plot/report.py --runs RUNS --out report [--quick]
  --quick   the runs were shortened (scripts/reproduce.sh --quick): every page says so at the top and
            figure titles say what was run
Exit codes: 0 written (missing runs are listed in the report), 1 some file was malformed.
"""
import argparse
import csv
import html
import os
import re
import shutil
import sys

import catalogue
import claims
import figures as fg
from measures import compare
from relslam_data import DataError, load_run
from relslam_data.names import algorithm_label

QUICK = "Quick mode: the runs are shortened, so these numbers differ from full runs and from the thesis."
CHAPTERS = [(4, "Chapter 4: Relative Plane", "chapter4.html"), (5, "Chapter 5: EM plane extraction", "chapter5.html"),
            (6, "Chapter 6: Relative Point", "chapter6.html")]
CHAPTER5_NUMBERS = {46, *range(55, 62), *range(103, 109)}
# The comparison runs of thesis 6.7 and 6.8: run folder, what it is, the figure that shows it.
COMPARISONS = [("s-ekf-f8", "figure eight, density 25 (thesis 6.7.1)", 147),
               ("s-line", "straight line (6.7.2)", 151), ("s-stat", "stationary viewpoint (6.7.2)", 152),
               ("s-dyn", "dynamic points (6.7.3)", 153), ("vp-1181", "Victoria Park, scans 1181-1642 (6.8)", 163),
               ("vp-4220", "Victoria Park, scans 4220-4634 (6.8)", 165)]
VERDICT_CLASS = {claims.HOLDS: "holds", claims.PARTLY: "partly", claims.DOES_NOT: "fails",
                 claims.NOT_JUDGED: "unjudged", claims.NOT_RUN: "unjudged"}
OURS_CHARS = 240  # the summary's "ours" column is cut here; claims.md has the whole text
STYLE = ("body{font-family:sans-serif;max-width:1100px;margin:auto;padding:0 1em}img{max-width:100%}"
         "nav{position:sticky;top:0;background:#fff;border-bottom:1px solid #ccc;padding:.4em 0;z-index:1}"
         "nav a{margin-right:1.2em}.missing{color:#a00}.pending{color:#864}.shows{background:#eef6ee;padding:.3em}"
         ".quick{background:#ffd;padding:.5em;border:1px solid #cc9}section{border-top:1px solid #ccc;margin-top:1em}"
         "table{border-collapse:collapse;font-size:90%;margin:.5em 0}td,th{border:1px solid #ccc;padding:.2em .5em;"
         "vertical-align:top}td.num{text-align:right}.holds{background:#dfd}.partly{background:#ffd}"
         ".fails{background:#fdd}.unjudged{color:#666}.pair{display:flex;gap:1em}.pair img{width:50%}"
         ".headline{font-size:110%;background:#eef;padding:.5em;border:1px solid #99c}")


def chapter_of_number(number):
    """The thesis chapter of a figure number (renders and pending figures carry only their number)."""
    return 5 if number in CHAPTER5_NUMBERS else 4 if number < 110 else 6


def page(title, body, quick):
    links = [("index.html", "Summary")] + [(f, t) for _, t, f in CHAPTERS] + [("claims.md", "claims.md")]
    nav = " ".join(f'<a href="{f}">{html.escape(t)}</a>' for f, t in links)
    notes = f'<p class="quick">{QUICK}</p>' if quick else ""
    return (f'<!DOCTYPE html>\n<html><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f'<style>{STYLE}</style></head><body>\n<nav>{nav}</nav>\n<h1>{html.escape(title)}</h1>\n{notes}\n{body}'
            f'</body></html>\n')


# ---- the chapter pages -----------------------------------------------------------------------

def copy_renders(runs, figures_dir):
    """{render number: image path relative to the report, or None when relslam render made none}."""
    found = {}
    for number in catalogue.RENDERS:
        source = os.path.join(runs, "renders", f"fig{number}.png")
        if os.path.exists(source):
            shutil.copyfile(source, os.path.join(figures_dir, f"fig{number}.png"))
        found[number] = f"figures/fig{number}.png" if os.path.exists(source) else None
    return found


def render_shows(runs):
    """{render number: what our run shows at the rendered iteration}, from RUNS/renders/renders.csv
    (reproduce.sh writes which run, algorithm and iteration each render drew) and that run's
    iterations.csv."""
    path = os.path.join(runs, "renders", "renders.csv")
    if not os.path.exists(path):
        return {}
    shows, loaded = {}, {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            try:
                run = loaded.setdefault(row["run"], load_run(os.path.join(runs, row["run"])))
            except DataError as e:
                shows[int(row["figure"])] = f"(not read: {e})"
                continue
            algorithm = run.algorithms.get(row["algorithm"])
            if algorithm is None:
                continue
            shows[int(row["figure"])] = describe_state(algorithm, row)
    return shows


def describe_state(algorithm, row):
    """One line on an algorithm's state at a rendered iteration: its errors and map."""
    it = algorithm.iterations
    k = int(row["iteration"]) if row["iteration"] else int(it["iteration"].iloc[-1])
    at = it[it["iteration"] == k]
    if at.empty:
        return f"{algorithm_label(algorithm.name)}: iteration {k} is not in its iterations.csv"
    r = at.iloc[0]
    parts = [f"{algorithm_label(algorithm.name)} at iteration {k} of {len(it)} ({row['view']} view)"]
    for column, text in [("landmark_error", "landmark error {:.3g}"), ("position_error", "position error {:.3g}"),
                         ("landmarks_in_map", "{:.0f} points on the map"), ("groups", "{:.0f} groups"),
                         ("final_groups", "{:.0f} final"), ("dynamic_flagged", "{:.0f} flagged dynamic")]:
        if column in r and r[column] == r[column]:
            parts.append(text.format(r[column]))
    return ", ".join(parts)


def section(key, title, image, problem, source, shows="", pending=""):
    caption, statement = catalogue.CATALOGUE[key]
    label = (f"Figure {key}" if isinstance(key, int) else f"Paper Figure {key[5:]}" if str(key).startswith("paper")
             else "Extra")
    body = (f'<img src="{html.escape(image)}" alt="{html.escape(label)}: {html.escape(title)}">' if image
            else f'<p class="pending">Not reproducible yet: {html.escape(pending)}</p>' if pending
            else f'<p class="missing">Not produced: {html.escape(problem)}</p>')
    if shows:
        body = f'<p class="shows"><b>What our run shows:</b> {html.escape(shows)}</p>\n' + body
    anchor = f"fig{key}" if isinstance(key, int) else str(key)
    return (f'<section id="{html.escape(anchor)}"><h2>{label}: {html.escape(title)}</h2>\n'
            f'<p class="caption"><b>Thesis caption:</b> {html.escape(caption)}</p>\n'
            f'<p class="thesis"><b>What the thesis says:</b> {html.escape(statement)}</p>\n'
            f'<p class="source">Ours from: <code>{html.escape(source)}</code></p>\n{body}</section>\n')


def chapter_sections(results, renders, render_notes):
    """{chapter: [section html]} in thesis order: charts and renders by number, the paper's, extras last."""
    entries = {c: [] for c, _, _ in CHAPTERS}
    for r in results:
        problem = {"missing": f"missing run {r.detail}", "error": r.detail}.get(r.status, "")
        image = f"figures/{r.figure.name}.png" if r.status == "ok" else None
        entries[fg.chapter_of(r.figure)].append((fg.order(r.figure), section(
            r.figure.id, r.title or r.figure.title, image, problem, ", ".join(r.figure.runs), r.shows)))
    for number, image in renders.items():
        problem = f"no renders/fig{number}.png in the runs folder (relslam render makes it)"
        title = "render: " + catalogue.CATALOGUE[number][0].split(".")[0]
        entries[chapter_of_number(number)].append(((0, number, ""), section(
            number, title, image, problem, f"renders/fig{number}.png", render_notes.get(number, ""))))
    for number, reason in catalogue.PENDING.items():
        entries[chapter_of_number(number)].append(((0, number, ""), section(
            number, "not reproducible yet", None, "", "no run yet", pending=reason)))
    return {c: [text for _, text in sorted(e, key=lambda e: e[0])] for c, e in entries.items()}


# ---- the summary page ------------------------------------------------------------------------

def number(value, digits=3):
    """3 significant digits, but never powers of ten for 1000 and more (a reader compares 2216 with 146
    more easily than 2.22e+03)."""
    if value is None or value != value:
        return "–"
    return f"{value:.0f}" if abs(value) >= 10 ** digits else f"{value:.{digits}g}"


def comparison_table(runs):
    """Relative Point against each baseline in every comparison run that exists: one row per algorithm."""
    head = ("<tr><th>experiment</th><th>algorithm</th><th>status</th><th>iterations</th>" +
            "".join(f"<th>{html.escape(h)}</th>" for h in compare.SUMMARY_COLUMNS.values()) + "</tr>")
    body, notes, untruthed = [], [], False
    for folder, what, figure in COMPARISONS:
        if not os.path.isdir(os.path.join(runs, folder)):
            continue
        try:
            rows = compare.algorithm_rows(load_run(os.path.join(runs, folder)).summary)
        except DataError as e:
            notes.append(f"<li>{html.escape(folder)}: {html.escape(str(e))}</li>")
            continue
        untruthed = untruthed or folder.startswith("vp-")
        link = f'<a href="chapter6.html#fig{figure}">{html.escape(what)}</a> (<code>{folder}</code>)'
        for i, (name, r) in enumerate(rows.iterrows()):
            cells = "".join(f'<td class="num">{number(r.get(c))}</td>' for c in compare.SUMMARY_COLUMNS)
            first = f'<td rowspan="{len(rows)}">{link}</td>' if i == 0 else ""
            status = html.escape(str(r["status"]))
            body.append(f"<tr>{first}<td>{html.escape(algorithm_label(name))}</td><td>{status}</td>"
                        f'<td class="num">{number(r.get("iterations"), 6)}</td>{cells}</tr>')
        base = next((b for b in ("ekf6d", "ekf2d") if b in rows.index), None)
        if base and claims.common.ALG in rows.index:
            speedup = compare.times_faster(rows, claims.common.ALG, base)
            notes.append(f"<li>{html.escape(what)}: {algorithm_label(claims.common.ALG)} is {number(speedup)}× "
                         f"faster than {html.escape(algorithm_label(base))} (median ms per iteration).</li>")
    if not body:
        return "<p>No comparison run in this report (scripts/reproduce.sh makes them).</p>"
    if untruthed:
        notes.append("<li>–: no truth to score against (Victoria Park has GPS only; its figures set the maps and "
                     "paths against GPS).</li>")
    return (f"<table>{head}{''.join(body)}</table>\n<ul>{''.join(notes)}</ul>\n")


FIGURE_NUMBER = re.compile(r"\b(?:paper )?Figs?\.? (\d+)")


def claim_figure(quantity, thesis, sources, ids):
    """The report anchor of the figure a claim is about: the figure its text names, else the first
    figure drawn from the run it read; None where there is none."""
    m = FIGURE_NUMBER.search(quantity) or FIGURE_NUMBER.search(thesis)
    if m and "paper Fig" not in m.group(0) and int(m.group(1)) in ids:
        n = int(m.group(1))
        return f"{CHAPTERS[[4, 5, 6].index(chapter_of_number(n))][2]}#fig{n}", f"Fig {n}"
    run = re.search(r"`([^/`]+)", sources)
    for f in fg.FIGURES:
        if run and run.group(1) in f.runs:
            return f"chapter{fg.chapter_of(f)}.html#{f.name}", f"Fig {f.id}" if isinstance(f.id, int) else f.name
    return None


def claims_table(rows, ids):
    counts = {v: sum(r[3] == v for r in rows) for v in VERDICT_CLASS}
    out = ["<p>" + ", ".join(f'<span class="{VERDICT_CLASS[v]}">{n} {v}</span>' for v, n in counts.items() if n) +
           f' of {len(rows)} claims. The full numbers and the files each came from: <a href="claims.md">claims.md'
           "</a>.</p>",
           "<table><tr><th>thesis claim</th><th>the thesis</th><th>ours (what the verdict checked)</th><th>verdict</th>"
           "<th>figure</th></tr>"]
    for quantity, thesis, ours, verdict, sources in rows:
        link = claim_figure(quantity, thesis, sources, ids)
        figure = f'<a href="{link[0]}">{html.escape(link[1])}</a>' if link else ""
        # what the verdict checked says most in little room; the whole text is in claims.md
        ours = ours.split(claims.CHECKED, 1)[-1]
        short = ours if len(ours) <= OURS_CHARS else ours[:OURS_CHARS].rsplit(" ", 1)[0] + " …"
        out.append(f"<tr><td>{html.escape(quantity)}</td><td>{html.escape(thesis)}</td><td>{html.escape(short)}</td>"
                   f'<td class="{VERDICT_CLASS[verdict]}">{html.escape(verdict)}</td><td>{figure}</td></tr>')
    return "\n".join(out) + "</table>\n"


def headline(runs, rows):
    """The first lines: how Relative Point compares with the EKF on the figure eight, and the count of
    claims that hold."""
    said = []
    path = os.path.join(runs, COMPARISONS[0][0])
    if os.path.isdir(path):
        try:
            r = compare.algorithm_rows(load_run(path).summary)
        except DataError:
            r = None
        if r is not None and {"relative_point", "ekf6d"} <= set(r.index):
            rel, ekf = r.loc["relative_point"], r.loc["ekf6d"]
            said.append(f"On the figure eight (thesis 6.7.1) Relative Point takes "
                        f"{number(rel['runtime_median_ms'])} ms per iteration (median) against "
                        f"{number(ekf['runtime_median_ms'])} ms for MRPT's 6D EKF "
                        f"({number(compare.times_faster(r, 'relative_point', 'ekf6d'))}× faster); its final position "
                        f"error is {number(rel['final_position_error'])} against "
                        f"{number(ekf['final_position_error'])}, "
                        f"its final landmark error per landmark {number(rel['final_mean_landmark_error'])} against "
                        f"{number(ekf['final_mean_landmark_error'])}.")
    for quantity, _, ours, verdict, _ in rows:
        if quantity.startswith("Relative vs EKF position error, figure eight"):
            said.append(f"The thesis calls the two position errors comparable (Fig 147): that <b>{verdict}</b> here "
                        f"({html.escape(ours)}).")
    counts = {v: sum(r[3] == v for r in rows) for v in VERDICT_CLASS}
    unjudged = [f"{counts[claims.NOT_JUDGED]} are not judged (their runs lack what the verdict needs: see the table)"
                if counts[claims.NOT_JUDGED] else "",
                f"{counts[claims.NOT_RUN]} were not run" if counts[claims.NOT_RUN] else ""]
    unjudged = " and ".join(u for u in unjudged if u)
    said.append(f"Of {len(rows)} thesis claims, {counts[claims.HOLDS]} hold, {counts[claims.PARTLY]} partly hold and "
                f"{counts[claims.DOES_NOT]} do not" + (f"; {unjudged}" if unjudged else "") +
                ': <a href="#claims">each claim with its verdict</a> and what it checked. A time the thesis reports '
                "counts as a budget (ours at most the thesis's holds); its 2004 processor is no yardstick for more.")
    failed = [html.escape(q) for q, _, _, v, _ in rows if v == claims.DOES_NOT]
    if failed:
        said.append(f"<br><b>Do not hold:</b> {'; '.join(failed)}.")
    return f'<p class="headline">{" ".join(said)}</p>\n'


def summary_body(runs, results, renders, claim_rows):
    made = sum(r.status == "ok" for r in results) + sum(v is not None for v in renders.values())
    total = len(results) + len(renders)
    missing = sorted({r.detail for r in results if r.status == "missing"})
    ids = {r.figure.id for r in results if r.status == "ok"} | {n for n, v in renders.items() if v}
    key = [f'<div class="pair"><a href="chapter6.html#fig{n}"><img src="figures/fig{n}.png" alt="Figure {n}"></a>'
           for n in (147,) if n in ids]
    key += [f'<a href="chapter6.html#fig{n}"><img src="figures/fig{n}.png" alt="Figure {n}"></a></div>'
            for n in (148,) if n in ids and key]
    chapters = "".join(f'<li><a href="{f}">{html.escape(t)}</a></li>' for _, t, f in CHAPTERS)
    return (f"{headline(runs, claim_rows)}<h2>Relative Point against the EKF and the other baselines</h2>\n"
            f"{comparison_table(runs)}"
            f"{''.join(key)}\n<h2 id='claims'>The thesis's claims: do they hold in our runs?</h2>\n"
            f"{claims_table(claim_rows, ids)}\n<h2>Figures by chapter</h2>\n<ul>{chapters}</ul>\n"
            f"<p>{made} of {total} figures produced from <code>{html.escape(runs)}</code>.</p>\n" +
            (f"<p>Missing runs: {html.escape('; '.join(missing))}.</p>\n" if missing else ""))


def write_pages(out, runs, results, renders, render_notes, claim_rows, quick):
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page("Relative SLAM: how our runs compare with the thesis", summary_body(
            runs, results, renders, claim_rows), quick))
    sections = chapter_sections(results, renders, render_notes)
    for chapter, title, name in CHAPTERS:
        toc = "".join(f'<li><a href="#{m.group(1)}">{m.group(2)}</a></li>'
                      for m in (re.search(r'<section id="([^"]+)"><h2>([^<]+)</h2>', s) for s in sections[chapter]))
        with open(os.path.join(out, name), "w") as f:
            f.write(page(f"Relative SLAM: thesis {title}", f"<details><summary>{len(sections[chapter])} figures"
                         f"</summary><ul>{toc}</ul></details>\n" + "".join(sections[chapter]), quick))


def write_claims(path, runs, claim_rows, quick):
    lines = [f"> {QUICK}", ""] if quick else []
    lines += ["# Thesis numbers against ours", "",
              f"Computed from the run folders in `{runs}`: Chapter 6 (Relative Point, thesis 6.5-6.9), Chapter 4 "
              "(Relative Plane, 4.2-4.3) and Chapter 5 (EM, 3.5.4, 5.2, the companion paper). The thesis ran on an "
              "Athlon 64 3400+ (2004): compare ratios and shapes, not milliseconds.", "",
              "Verdict: **holds**, **partly** or **does not hold** where the claim can be judged from the numbers "
              f"(counts: within a factor {claims.NUMBER_HOLDS:g} of the thesis's number holds, within "
              f"{claims.NUMBER_PARTLY:g} partly; \"comparable\" errors: within a factor {compare.COMPARABLE:g} holds, "
              f"{compare.PARTLY:g} partly; maps: every variant as the thesis says holds; times: at most the thesis's "
              "time holds, up to twice it partly; the other claims: every part the row's \"checked\" list names "
              "holds, some partly, none does not, with the thresholds of scripts/plot/measures/verdicts.py); "
              "*not judged* where the runs lack what the verdict needs (a file, a variant, a second run size).", "",
              "| quantity | thesis | ours | verdict | source file |", "|---|---|---|---|---|"]
    for q, t, o, v, src in claim_rows:
        mark = f"*{v}*" if v in (claims.NOT_JUDGED, claims.NOT_RUN) else f"**{v}**"
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in (q, t, o, mark, src)) + " |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return sum(row[2].startswith("error:") for row in claim_rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", required=True, help="folder holding the run folders")
    parser.add_argument("--out", required=True, help="report folder (index.html, chapter pages, claims.md, figures/)")
    parser.add_argument("--quick", action="store_true", help="the runs are shortened; say so")
    args = parser.parse_args()
    figures_dir = os.path.join(args.out, "figures")
    os.makedirs(figures_dir, exist_ok=True)
    results = fg.render_all(args.runs, figures_dir, quick=args.quick)
    renders = copy_renders(args.runs, figures_dir)
    for number_, image in renders.items():
        if image is None:
            print(f"fig{number_}: render not produced (no {os.path.join(args.runs, 'renders', f'fig{number_}.png')})")
    claim_rows = claims.rows(args.runs)
    write_pages(args.out, args.runs, results, renders, render_shows(args.runs), claim_rows, args.quick)
    claim_errors = write_claims(os.path.join(args.out, "claims.md"), args.runs, claim_rows, args.quick)
    print(f"report: wrote {os.path.join(args.out, 'index.html')} (summary), the chapter pages and "
          f"{os.path.join(args.out, 'claims.md')}")
    return 1 if claim_errors or any(r.status == "error" for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
