#!/usr/bin/env python3
"""Checks that host/ depends one way: each folder includes only itself and
the folders below it in LAYERS (the pipeline's order), so no folder cycle can
form. Prints the folder graph; with --dot FILE also writes it as Graphviz.
Exit 1 and one line per offending include when a folder reaches up or
sideways.

    scripts/check_layers.py [--dot out/layers.dot]
"""
import argparse
import pathlib
import re
import sys

# Lowest first. A folder may include folders of a lower rank only; folders
# of the same rank are independent of each other.
LAYERS = [
    ["common"],
    ["mesh", "opencl", "tuning"],
    ["geodesics"],
    ["particles"],
    ["backends", "quality"],
    ["pipeline"],
    ["measurement"],
    ["reports"],
    ["cli"],
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/[^"]+"')


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dot", help="also write the folder graph to this Graphviz file")
    args = parser.parse_args()
    host = pathlib.Path(__file__).resolve().parent.parent / "host"
    rank = {folder: r for r, folders in enumerate(LAYERS) for folder in folders}
    edges, problems = {}, []
    for path in sorted(host.rglob("*.[ch]pp")):
        folder = path.relative_to(host).parts[0]
        if folder not in rank:
            problems.append(f"host/{folder}/ is not in LAYERS of {pathlib.Path(__file__).name}: place it")
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match or match.group(1) == folder:
                continue
            target = match.group(1)
            edges.setdefault(folder, set()).add(target)
            if target not in rank or rank[target] >= rank[folder]:
                problems.append(f"{path.relative_to(host.parent)}:{number}: {folder}/ includes {target}/, "
                                f"which is not below it")
    for r, folders in reversed(list(enumerate(LAYERS))):
        for folder in folders:
            print(f"{folder:12} -> {', '.join(sorted(edges.get(folder, []))) or '-'}")
    if args.dot:
        lines = ["digraph layers {", "  rankdir=TB; node [shape=box];"]
        lines += [f"  {a} -> {b};" for a in sorted(edges) for b in sorted(edges[a])]
        pathlib.Path(args.dot).write_text("\n".join(lines + ["}"]) + "\n")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
