#!/usr/bin/python3
"""Pictures of the per-iteration trace in `meshparticles run` reports.

    scripts/plot_trace.py REPORT.json [REPORT.json ...] [--out FILE.png]

Three panels, one line (or set of dots) per report: total energy per
iteration, particles moved per iteration, and wall time per iteration
against the particles moved in it - where a backend whose work follows the
moves (field) shows its cost falling with them. The first iteration is left
out of the time panel: it includes the OpenCL compiler's first launch.
Reports of runs on local distances get a fourth panel: per iteration, the
balls solved while it ran, its wall time, and the part of it the particle
loop spent waiting on balls.
Uses Debian's python3-matplotlib (scripts/setup.sh installs it).
"""
import argparse
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402


def label_of(report, path):
    params = report.get("params", {})
    parts = [params.get("backend", "?")]
    if params.get("weights") == "half":
        parts.append("half")
    parts.append(params.get("scheme", ""))
    if params.get("init"):
        parts.append(f"from {params['init']}")
    return " ".join(p for p in parts if p) or path.stem


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reports", nargs="+", type=Path, help="report.json files written by `meshparticles run`")
    parser.add_argument("--out", type=Path, help="PNG to write (default: trace.png next to the first report)")
    args = parser.parse_args()
    reports = []
    for path in args.reports:
        try:
            report = json.loads(path.read_text())
            trace = report["trace"]
        except (OSError, ValueError, KeyError, TypeError) as error:
            sys.exit(f"plot_trace: {path}: not a run report with a trace ({error})")
        reports.append((path, report, trace))

    with_balls = any("balls" in t for _, _, trace in reports for t in trace)
    fig, axes = plt.subplots(1, 4 if with_balls else 3, figsize=(21 if with_balls else 16, 4.6))
    energy_ax, moved_ax, time_ax = axes[:3]
    if with_balls:
        balls_ax = axes[3]
        seconds_ax = balls_ax.twinx()
    styles = ["-", "--", ":", "-."]  # identical runs (two backends) stay visible on top of each other
    for index, (path, report, trace) in enumerate(reports):
        label = label_of(report, path)
        iterations = range(1, len(trace) + 1)
        style = {"linestyle": styles[index % len(styles)], "linewidth": 2.2 - 0.4 * (index % 4)}
        energy_ax.plot(iterations, [t["energy"] for t in trace], label=label, **style)
        moved_ax.plot(iterations, [max(t["moved"], 0.5) for t in trace], label=label, **style)
        timed = trace[1:]
        time_ax.scatter([max(t["moved"], 0.5) for t in timed], [t["ms"] for t in timed], s=12, label=label)
        if with_balls and all("balls" in t for t in trace):
            who = f"{label}: " if len(reports) > 1 else ""
            balls_ax.plot(iterations, [max(t["balls"], 0.5) for t in trace], marker="o", markersize=3,
                          color="tab:blue", label=f"{who}balls solved", **style)
            seconds_ax.plot(iterations, [t["ms"] / 1000 for t in trace], color="tab:red",
                            label=f"{who}iteration", **style)
            seconds_ax.plot(iterations, [t["ball_ms"] / 1000 for t in trace], color="tab:orange",
                            label=f"{who}waiting on balls", **style)
    energy_ax.set(xlabel="iteration", ylabel="total energy", title="energy", yscale="log")
    moved_ax.set(xlabel="iteration", ylabel="particles moved (0 drawn at 0.5)", title="moves", yscale="log")
    time_ax.set(xlabel="particles moved in the iteration (0 drawn at 0.5)", ylabel="wall ms per iteration",
                title="time per iteration against moves (first iteration left out)", xscale="log", yscale="log")
    for ax in (energy_ax, moved_ax, time_ax):
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    if with_balls:
        balls_ax.set(xlabel="iteration", ylabel="balls solved in the iteration (0 drawn at 0.5)", yscale="log",
                     title="local distances: balls and time per iteration")
        seconds_ax.set(ylabel="seconds")
        balls_ax.grid(alpha=0.3, which="both")
        lines = balls_ax.get_legend_handles_labels()
        more = seconds_ax.get_legend_handles_labels()
        balls_ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8)
    first = reports[0][1]
    mesh = Path(first.get("mesh", {}).get("path", "")).name
    fig.suptitle(f"{mesh} n={first.get('params', {}).get('n', '?')} on {first.get('device', '?')}", fontsize=10)
    fig.tight_layout()
    out = args.out or args.reports[0].parent / "trace.png"
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(out)


if __name__ == "__main__":
    main()
