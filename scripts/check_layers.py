#!/usr/bin/python3
"""Checks that host/ depends one way: each folder includes only itself and
the folders below it in LAYERS (the pipeline's order), so no folder cycle can
form; and that python/, the front end beside cli/, includes no cli/ header
(what both front ends share is in options/). Prints the folder graph; with
--png FILE also draws it (matplotlib). Exit 1 and one line per offending
include when a folder reaches up or sideways.

    scripts/check_layers.py [--png docs/images/layers.png]
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
    ["geodesics", "fixtures"],
    ["particles"],
    ["backends", "quality", "shape_model"],
    ["pipeline"],
    ["measurement"],
    ["reports", "launch"],
    ["batch", "correspondence"],
    ["options"],
    ["cli"],
]
# The other front end, outside host/: it may include any folder of host/
# but this one.
PYTHON_BESIDE = "cli"

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/[^"]+"')


def draw(edges, file):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    place = {}
    for r, folders in enumerate(LAYERS):
        for k, folder in enumerate(folders):
            place[folder] = ((k + 1) / (len(folders) + 1), r)
    figure, axes = plt.subplots(figsize=(7, 8))
    for source, targets in edges.items():
        for target in targets:
            (x0, y0), (x1, y1) = place[source], place[target]
            axes.annotate("", xy=(x1, y1 + 0.18), xytext=(x0, y0 - 0.18),
                          arrowprops=dict(arrowstyle="->", color="0.6", lw=0.8, shrinkA=0, shrinkB=0))
    for folder, (x, y) in place.items():
        axes.text(x, y, folder + "/", ha="center", va="center", fontsize=11,
                  bbox=dict(boxstyle="round", facecolor="#dbe8f6", edgecolor="#3a6ea5"))
    axes.set_xlim(0, 1)
    axes.set_ylim(-0.6, len(LAYERS) - 0.4)
    axes.axis("off")
    axes.set_title("host/: who includes whom (arrows point down only)")
    figure.tight_layout()
    figure.savefig(file, dpi=110)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--png", help="also draw the folder graph, layer by layer, into this PNG")
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
    python = host.parent / "python"
    for path in sorted(python.rglob("*.[ch]pp")):
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if match and (match.group(1) == PYTHON_BESIDE or match.group(1) not in rank):
                problems.append(f"{path.relative_to(host.parent)}:{number}: python/ includes {match.group(1)}/, "
                                f"which is not a folder of host/ below {PYTHON_BESIDE}/")
    for r, folders in reversed(list(enumerate(LAYERS))):
        for folder in folders:
            print(f"{folder:12} -> {', '.join(sorted(edges.get(folder, []))) or '-'}")
    if args.png:
        draw(edges, args.png)
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
