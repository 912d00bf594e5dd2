#!/usr/bin/python3
"""Pictures of a shape model written by `meshparticles model ... --out DIR`.

    scripts/plot_model.py DIR [--out FILE.png] [--modes 2]

Top row: the variance the first M modes hold (compactness), and the model
measures against M (generalization: leave-one-out rebuild error; specificity:
distance from model samples to the nearest training shape; lower is better
for both, error bars one standard deviation). Below, for each of the first
--modes modes: the mean shape's particles, and the same particles moved two
standard deviations along the mode either way, coloured by how far each
moved (three views of the aligned frame: the shape's principal axes).
Uses Debian's python3-matplotlib and python3-numpy (scripts/setup.sh).
"""
import argparse
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model_dir", type=Path)
    parser.add_argument("--out", type=Path, help="PNG to write (default: DIR/model.png)")
    parser.add_argument("--modes", type=int, default=2, help="modes to draw on the mean shape")
    args = parser.parse_args()
    try:
        summary = json.loads((args.model_dir / "model.json").read_text())
        modes = json.loads((args.model_dir / "modes.json").read_text())
    except (OSError, ValueError) as error:
        sys.exit(f"plot_model.py: {args.model_dir}: not a model folder of `meshparticles model` ({error})")
    out = args.out or args.model_dir / "model.png"
    mean = np.array(modes["mean"])
    drawn = min(args.modes, len(modes["modes"]))

    figure = plt.figure(figsize=(12, 4 + 3.2 * drawn))
    grid = figure.add_gridspec(1 + drawn, 3)
    counts = np.arange(1, len(summary["compactness"]) + 1)
    axes = figure.add_subplot(grid[0, 0])
    axes.plot(counts, 100 * np.array(summary["compactness"]), "o-", markersize=3)
    axes.set(xlabel="modes M", ylabel="variance held (%)", title="compactness", ylim=(0, 101))
    axes.grid(alpha=0.3)
    for column, name in ((1, "generalization"), (2, "specificity")):
        values = summary[name]
        axes = figure.add_subplot(grid[0, column])
        m = np.arange(1, len(values["mean"]) + 1)
        if len(m):
            axes.errorbar(m, values["mean"], yerr=values["sd"], fmt="o-", markersize=3, capsize=2)
        axes.set(xlabel="modes M", ylabel="mean point distance", title=f"{name} (lower is better)")
        axes.grid(alpha=0.3)

    # The views: the mean's principal axes, so the shape faces the reader.
    centred = mean - mean.mean(axis=0)
    _, _, axes_of_shape = np.linalg.svd(centred, full_matrices=False)
    for row in range(drawn):
        mode = modes["modes"][row]
        vectors = np.array(mode["vectors"])
        sd = np.sqrt(mode["variance"])
        for column, (label, factor) in enumerate((("-2 sd", -2), ("mean", 0), ("+2 sd", 2))):
            shape = (mean + factor * sd * vectors - mean.mean(axis=0)) @ axes_of_shape.T
            moved = np.linalg.norm(factor * sd * vectors, axis=1)
            axes = figure.add_subplot(grid[1 + row, column])
            axes.scatter(shape[:, 0], shape[:, 1], c=moved, s=6, cmap="viridis",
                         vmin=0, vmax=max(2 * sd * np.linalg.norm(vectors, axis=1).max(), 1e-12))
            axes.set_aspect("equal")
            axes.set_xticks([])
            axes.set_yticks([])
            explained = 100 * mode["variance"] / summary["total_variance"]
            axes.set_title(f"mode {row + 1} ({explained:.1f}%): {label}")
    figure.suptitle(f"{len(summary['shapes'])} shapes, {summary['points']} points each")
    figure.tight_layout()
    figure.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
