#!/usr/bin/env python3
"""Fails on any #include that runs up a layer (folders are layers).

    tests/tools/layers_test.py SOURCE_DIR

The stack, bottom to top: libslam (core < spatial < point and the algorithm folders beside it < relax),
sim (by file, below), eval (config < io < metrics < sources < algorithms < experiments < cli,
each a folder eval/<layer>/{include,src}).
A file may include its own layer and those below it; folders of one rank (point, plane, em)
may not include each other. A file in no layer is an error too: place it in the table.

Inside a layer (each libslam folder, each eval layer) the concepts (a header with its source,
public or private) may not include each other in a circle, directly or through others: what two
of them share lives in its own header below both. A public header may not include one private to
its layer's src/ folder: users of the layer cannot reach it. Known circles whose fix is large are
in ALLOWED_CIRCLES, each with its reason; an entry that no longer closes a circle is an error too.
"""
import re
import sys
from pathlib import Path

# libslam: relslam/<folder>/..., ranked by folder.
# relax (the Ceres solve of the Relative Point relaxation) sits on point.
LIBSLAM = {"core": 0, "spatial": 1, "point": 2, "plane": 2, "scan": 2, "em": 2, "relax": 3}
# sim: one concept per file, ranked by file stem (src/ and include/relslam/sim/ alike).
SIM = {
    "random": 0, "checked": 0, "centerline": 0, "frustum": 0, "viewing_frustum": 0, "planar_world": 0,
    "options": 1, "figure_eight": 1, "straight_line": 1, "plane_noise": 1, "planar_path": 1,
    "ray_cast": 1, "odometry_noise": 1,
    "path": 2, "plane_sensor": 2, "laser_sensor": 2, "depth_camera": 2,
    "world": 3, "column_grid": 3, "planar_map": 3, "point_sensor": 3,
    "simulator": 4, "planar_simulator": 4,
    "planar_sight": 5,
    # The map generator: its shared pieces, the families, the generator that checks their maps.
    "map_layout": 4, "generated_rooms": 5, "generated_corridors": 5, "generated_office": 5,
    "map_generator": 6,
}
# eval: relslam/eval/<layer>/... or, for internal headers, "<layer>/x.hpp" under eval/src.
EVAL = ["config", "io", "metrics", "sources", "algorithms", "experiments", "cli"]
PROJECTS = ["libslam", "sim", "eval"]  # libslam < sim < eval

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)

# Includes inside a layer that close a circle, allowed for now: (layer, includer, included) by
# concept (path under include/relslam/<...>/ or src/, no extension) -> why it stays.
ALLOWED_CIRCLES = {
}


def layer_of_file(root, path):
    """(project, rank, group) of a source file, or None when it is in no layer."""
    rel = path.relative_to(root).parts
    project = rel[0]
    if project == "libslam":
        folder = rel[3] if rel[1] == "include" else rel[2]  # include/relslam/<f>/ or src/<f>/
        return ("libslam", LIBSLAM.get(folder), folder) if folder in LIBSLAM else None
    if project == "sim":
        stem = path.stem
        return ("sim", SIM[stem], stem) if stem in SIM else None
    if project == "eval":  # eval/<layer>/{include,src}/..., eval/app/main.cpp on top
        if rel[1] == "app":
            return ("eval", len(EVAL), "app")
        return ("eval", EVAL.index(rel[1]), rel[1]) if rel[1] in EVAL else None
    return None


def layer_of_include(text, including):
    """(project, rank, group) of an included header, or None for one outside the stack."""
    parts = text.split("/")
    if parts[0] == "relslam" and len(parts) >= 3:
        if parts[1] == "sim":
            stem = Path(parts[-1]).stem
            return ("sim", SIM.get(stem, -1), stem)
        if parts[1] == "eval" and len(parts) >= 4:
            return ("eval", EVAL.index(parts[2]) if parts[2] in EVAL else -1, parts[2])
        if parts[1] in LIBSLAM:
            return ("libslam", LIBSLAM[parts[1]], parts[1])
        return None
    # Internal headers: "x.hpp" beside the file (its own layer in eval, by stem in sim).
    if including[0] == "eval" and len(parts) == 1:
        return including
    if including[0] == "sim":
        stem = Path(parts[-1]).stem
        return ("sim", SIM.get(stem, -1), stem)
    return None


def check(root):
    """Every include of the tree against the layers: (files, problems)."""
    problems, files = [], 0
    for project in PROJECTS:
        for path in sorted((root / project).rglob("*")):
            if path.suffix not in (".hpp", ".cpp"):
                continue
            files += 1
            own = layer_of_file(root, path)
            rel = path.relative_to(root)
            if own is None:
                problems.append(f"{rel}: in no layer; add its folder or file to tests/tools/layers_test.py")
                continue
            text = path.read_text()
            for match in INCLUDE.finditer(text):
                included = layer_of_include(match.group(1), own)
                if included is None:
                    continue
                line = text.count("\n", 0, match.start(1)) + 1
                where = f"{rel}:{line}: {match.group(1)}"
                if included[1] == -1:
                    problems.append(f"{where}: the header is in no layer")
                elif PROJECTS.index(included[0]) > PROJECTS.index(own[0]):
                    problems.append(f"{where}: {own[0]} may not include {included[0]} (libslam < sim < eval)")
                elif included[0] == own[0] and included[1] > own[1]:
                    problems.append(f"{where}: {own[2]} (rank {own[1]}) includes {included[2]} (rank {included[1]}), "
                                    "a layer above it")
                elif included[0] == own[0] and included[1] == own[1] and included[2] != own[2]:
                    problems.append(f"{where}: {own[2]} and {included[2]} are side by side and may not include each other")
                elif own[0] == "sim" and included[0] == "libslam" and included[2] != "core":
                    problems.append(f"{where}: sim sees only relslam/core of libslam")
    return files, problems


def layer_folders(root):
    """(name, public include folder, src folder, include prefix) of each layer checked inside."""
    for folder in LIBSLAM:
        yield f"libslam/{folder}", root / "libslam/include/relslam" / folder, root / "libslam/src" / folder, \
            f"relslam/{folder}/"
    for layer in EVAL:
        yield f"eval/{layer}", root / "eval" / layer / "include/relslam/eval" / layer, root / "eval" / layer / "src", \
            f"relslam/eval/{layer}/"


def resolve(target, folder, private):
    """The file a quoted include names: beside the including file, else in the layer's src/ (its
    private include folder, as the build sets it); None when neither has it."""
    for candidate in (folder / target, private / target):
        if candidate.is_file():
            return candidate
    return None


def circles(graph):
    """The strongly connected parts of more than one node of {node: {successor: where}} (Tarjan)."""
    index, low, stack, on_stack, parts = {}, {}, [], set(), []

    def visit(node):
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for succ in graph.get(node, {}):
            if succ not in index:
                visit(succ)
                low[node] = min(low[node], low[succ])
            elif succ in on_stack:
                low[node] = min(low[node], index[succ])
        if low[node] == index[node]:
            part = set()
            while True:
                top = stack.pop()
                on_stack.discard(top)
                part.add(top)
                if top == node:
                    break
            if len(part) > 1:
                parts.append(part)

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return parts


def check_inside(root, allowed):
    """Circles between the concepts of one layer and public headers that include private ones.

    A concept is a header with its source (x.hpp, x.cpp): when x.cpp includes y.hpp and y's header
    or source includes x.hpp, neither can be read, tested or moved without the other, although no
    header includes itself. So the graph is drawn between concepts, not files."""
    problems = []
    for name, public, private, prefix in layer_folders(root):
        graph = {}  # concept -> {included concept: "file:line: include"}
        for base in (public, private):
            if not base.exists():
                continue
            for path in sorted(base.rglob("*")):
                if path.suffix not in (".hpp", ".cpp"):
                    continue
                concept = str(path.relative_to(base).with_suffix(""))
                text = path.read_text()
                for match in INCLUDE.finditer(text):
                    target = match.group(1)
                    where = f"{path.relative_to(root)}:{text.count(chr(10), 0, match.start(1)) + 1}: {target}"
                    if target.startswith(prefix):
                        included = str(Path(target[len(prefix):]).with_suffix(""))
                    elif (file := resolve(target, path.parent, private)) and private in file.parents:
                        included = str(file.relative_to(private).with_suffix(""))
                        if base == public:
                            problems.append(f"{where}: a public header includes a header private to {name}/src")
                    else:
                        continue  # another layer's: the check above
                    if included != concept:
                        graph.setdefault(concept, {}).setdefault(included, where)
        found = circles(graph)
        for layer, includer, included in allowed:
            if layer != name:
                continue
            if included not in graph.get(includer, {}) or not any({includer, included} <= part for part in found):
                problems.append(f"ALLOWED_CIRCLES: {layer}: {includer} -> {included} closes no circle; drop the entry")
            graph.get(includer, {}).pop(included, None)
        for part in circles(graph):
            edges = [graph[a][b] for a in sorted(part) for b in sorted(graph.get(a, {})) if b in part]
            problems.append(f"{name}: {', '.join(sorted(part))} include each other in a circle (move what they share "
                            "into its own header below them):\n    " + "\n    ".join(edges))
    return problems


def self_test():
    """The check itself: a tree with one include of each wrong kind must give one problem each."""
    import tempfile
    cases = {
        "eval/io/src/reader.cpp": '#include "relslam/eval/cli/app.hpp"',          # io -> cli
        "eval/config/include/relslam/eval/config/k.hpp": '#include "relslam/eval/metrics/x.hpp"',  # upwards
        "libslam/src/point/a.cpp": '#include "relslam/plane/b.hpp"',              # side by side
        "libslam/src/core/c.cpp": '#include "relslam/sim/world.hpp"',             # libslam -> sim
        "sim/src/world.cpp": '#include "relslam/point/rlt_point.hpp"',           # sim -> point
        "sim/src/options.cpp": '#include "relslam/sim/simulator.hpp"',           # options -> simulator
        "eval/nowhere/src/x.cpp": "",                                             # no layer
        "eval/cli/src/fine.cpp": '#include "relslam/eval/io/csv_writer.hpp"',     # allowed
    }
    # Inside a layer: a circle through three concepts (one problem), a public header including a
    # private one, an allowed circle (none) and an allow-list entry for an include that is gone.
    inside = {
        "libslam/src/plane/ring_a.cpp": '#include "relslam/plane/ring_b.hpp"',
        "libslam/include/relslam/plane/ring_b.hpp": '#include "relslam/plane/ring_c.hpp"',
        "libslam/include/relslam/plane/ring_c.hpp": '#include "relslam/plane/ring_a.hpp"',
        "eval/io/include/relslam/eval/io/shown.hpp": '#include "hidden.hpp"',
        "eval/io/src/hidden.hpp": "",
        "eval/metrics/src/factory.cpp": '#include "relslam/eval/metrics/made.hpp"',
        "eval/metrics/include/relslam/eval/metrics/made.hpp": '#include "relslam/eval/metrics/factory.hpp"',
    }
    allowed = {("eval/metrics", "factory", "made"): "planted", ("eval/cli", "gone", "away"): "planted"}
    expected_inside = 3
    with tempfile.TemporaryDirectory() as tmp:
        for rel, text in {**cases, **inside}.items():
            path = Path(tmp) / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text + "\n")
        _, problems = check(Path(tmp))
        problems += check_inside(Path(tmp), allowed)
    expected = len(cases) - 1 + expected_inside
    if len(problems) != expected:
        print("layers_test --self-test: expected", expected, "problems, got:", *problems, sep="\n  ")
        return 1
    print(f"layers_test --self-test: all {expected} wrong includes caught")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
    files, problems = check(root)
    problems += check_inside(root, ALLOWED_CIRCLES)
    for p in problems:
        print(p)
    print(f"layers_test: {files} files, {len(problems)} includes against the layers")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
