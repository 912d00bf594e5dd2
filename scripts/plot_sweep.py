#!/usr/bin/python3
"""Pictures of `meshparticles sweep --json` and `meshparticles bench --json`.

    scripts/plot_sweep.py RESULT.json [RESULT.json ...] [--out DIR]

A sweep file gives RESULT_heatmap.png: median update-kernel time over
(work-group size, tile size), one panel per kernel, skipped and FAILED
configurations marked. A bench file gives RESULT_bench.png: time per
iteration on a log scale, one panel per mesh, ours beside the paper's.
Uses Debian's python3-matplotlib (scripts/setup.sh installs it).
"""
import argparse
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402


def plot_sweep(result, title, out):
    kernels = [k for k in ("naive", "tiled", "field") if any(r["kernel"] == k for r in result["rows"])]
    fig, axes = plt.subplots(1, len(kernels), figsize=(6.5 * len(kernels), 5), squeeze=False)
    for ax, kernel in zip(axes[0], kernels):
        rows = [r for r in result["rows"] if r["kernel"] == kernel]
        wgs = sorted({r["wg"] for r in rows})
        tiles = sorted({r["tile"] for r in rows if r["tile"] is not None}) or [None]
        grid = [[math.nan] * len(tiles) for _ in wgs]
        labels = [[""] * len(tiles) for _ in wgs]
        for r in rows:
            i, j = wgs.index(r["wg"]), tiles.index(r["tile"])
            if r["status"] == "ok":
                grid[i][j] = r["median_ms"]
                labels[i][j] = f"{r['median_ms']:.3g}"
            else:
                labels[i][j] = "skip" if r["status"] == "skipped" else "FAIL"
        image = ax.imshow(grid, cmap="viridis_r", aspect="auto", origin="lower")
        fig.colorbar(image, ax=ax, label="update kernels, ms per iteration (median)")
        for i in range(len(wgs)):
            for j in range(len(tiles)):
                if labels[i][j] in ("skip", "FAIL"):
                    color = "red"
                else:  # dark text on the light (fast) end of the colour map
                    color = "black" if image.norm(grid[i][j]) < 0.5 else "white"
                ax.text(j, i, labels[i][j], ha="center", va="center", fontsize=8, color=color)
        ax.set_yticks(range(len(wgs)), [str(w) for w in wgs])
        ax.set_ylabel("work-group size")
        ax.set_xticks(range(len(tiles)), ["-" if t is None else str(t) for t in tiles])
        ax.set_xlabel("tile size" if tiles != [None] else "(no tile)")
        best = result["best"].get(kernel)
        best_text = f"best wg {best['wg']}" + (f" tile {best['tile']}" if best and best["tile"] else "") if best else "none timed"
        ax.set_title(f"{kernel}: {best_text}" + (f", {best['median_ms']:.3g} ms" if best else ""))
    colors = f" K={result['colors']}" if result.get("colors") else ""
    fig.suptitle(f"{title}: {Path(result['mesh']).name}, n={result['n']}, {result['scheme']}{colors}, "
                 f"{result['device']['name']}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def plot_bench(result, title, out):
    meshes = list(dict.fromkeys(c["mesh"] for c in result["cases"]))
    fig, axes = plt.subplots(1, len(meshes), figsize=(5.5 * len(meshes), 4.8), squeeze=False)
    colors = {"serial": "tab:gray", "naive": "tab:orange", "tiled": "tab:blue", "field": "tab:green",
              "serial-field": "tab:olive"}
    # The field rows stand beside the paper's GPU2 in the table; here the
    # paper's own bars are drawn once, with its own rows.
    has_paper_bars = {"serial", "naive", "tiled"}
    for ax, mesh in zip(axes[0], meshes):
        cases = [c for c in result["cases"] if c["mesh"] == mesh]
        backends = list(dict.fromkeys(r["backend"] for c in cases for r in c["rows"]))
        width = 0.8 / (2 * len(backends))
        for b, backend in enumerate(backends):
            for source, key, hatch in (("ours", "ms_per_iteration", None), ("paper", "paper_ms", "//")):
                if source == "paper" and backend not in has_paper_bars:
                    continue
                xs, ys = [], []
                for x, case in enumerate(cases):
                    row = next((r for r in case["rows"] if r["backend"] == backend), None)
                    if row and row.get(key):
                        xs.append(x + (2 * b + (source == "paper") - len(backends) + 0.5) * width)
                        ys.append(row[key])
                ax.bar(xs, ys, width, color=colors.get(backend, "tab:green"), hatch=hatch,
                       alpha=0.55 if source == "paper" else 1.0, edgecolor="black", linewidth=0.4,
                       label=f"{backend} ({source})")
        ax.set_yscale("log")
        ax.set_xticks(range(len(cases)), [str(c["n"]) for c in cases])
        ax.set_xlabel("particles")
        ax.set_ylabel("ms per iteration (log)")
        ax.set_title(f"{mesh} ({cases[0]['vertices']} vertices)")
        ax.grid(axis="y", which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7, ncol=2)
    fig.suptitle(f"{title}: ours on {result['device']} ({result['iterations']} iterations)\n"
                 "beside the paper's Tables 1-2 (hatched)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+", type=Path, help="JSON from sweep --json or bench --json")
    parser.add_argument("--out", type=Path, help="directory for the PNGs (default: next to each JSON)")
    args = parser.parse_args()
    for path in args.results:
        try:
            result = json.loads(path.read_text())
        except (OSError, ValueError) as error:
            sys.exit(f"plot_sweep: {path}: not readable JSON ({error})")
        directory = args.out or path.parent
        directory.mkdir(parents=True, exist_ok=True)
        if "rows" in result and "best" in result:
            out = directory / f"{path.stem}_heatmap.png"
            plot_sweep(result, "sweep", out)
        elif "cases" in result:
            out = directory / f"{path.stem}_bench.png"
            plot_bench(result, "bench", out)
        else:
            sys.exit(f"plot_sweep: {path}: neither a sweep nor a bench result")
        print(out)


if __name__ == "__main__":
    main()
