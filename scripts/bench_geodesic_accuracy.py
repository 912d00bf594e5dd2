#!/usr/bin/python3
"""Our geodesic solvers against exact geodesic distances, on real meshes.

    scripts/bench_geodesic_accuracy.py [MESH ...] [--corpus] [--max-vertices V] [--sources K]
                                       [--binary FILE] [--json FILE] [--png FILE]

For each mesh, K sources (vertices spread over the input's numbering:
0, V/K, 2V/K, ...), each solved by `meshparticles geodesics MESH --source S
--geodesic G` for fmm, fim and dijkstra, and by the exact algorithm of
Mitchell, Mount and Papadimitriou (Surazhsky's implementation, pip's
pygeodesic). Every vertex farther from the source than 3 mean edge lengths
is compared, as docs/GEODESICS.md's accuracy table on the sphere does (near
the source a relative error says little). Per mesh and solver: the mean
relative error (signed: + is too long), the 99th percentile of its size, and
the largest error each way.

Why: the sphere and the flat patch of tests/geodesics_test.cpp are smooth,
well-shaped meshes. The meshes people bring have slivers, sharp edges,
holes and saddles, and every measurement (`quality`, report.json) and every
particle move reads these distances.

`--corpus` (the default without MESH): the meshes of Debian's libcgal-demo
(installed if missing, as scripts/real_meshes.sh does), up to
`--max-vertices` (default 60,000). A mesh the exact solver cannot take (a
face of more than three corners, a vertex no face uses, one our reader
drops or splits) is left out with its reason.

pygeodesic runs in the peers' virtual environment
($MESHPARTICLES_PEER_VENV, default ${XDG_CACHE_HOME:-~/.cache}/meshparticles/peer-venv,
made on first use), never a dependency of meshparticles; this script
re-invokes itself there with `--exact-worker`. Progress on stderr, a
Markdown table and a summary on stdout; `--png` draws each mesh's worst
error each way, fmm against fim (Debian's python3-matplotlib). Exit status 0; 2 for a missing
binary, mesh or venv.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare_samplers as shared  # noqa: E402  (venv, corpus and binary helpers)

PROG = "bench_geodesic_accuracy"
shared.PROG = PROG
ROOT = Path(__file__).resolve().parent.parent
SOLVERS = ["fmm", "fim", "dijkstra"]
NEAR_SOURCE_EDGES = 3  # vertices within this many mean edge lengths of the source are not compared
progress, die, Failure = shared.progress, shared.die, shared.Failure


# ---------------------------------------------------------------- inside the venv

def read_off_triangles(path):
    """(positions, triangles) of an OFF file of triangles; raises ValueError for anything else."""
    words = []
    for line in Path(path).read_text(errors="replace").splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            words.append(line.split())
    if not words or words[0][0] not in ("OFF", "COFF"):  # COFF: colours after each position, ignored
        raise ValueError(f"an OFF variant this reader does not take ({words[0][0] if words else 'empty'})")
    header = words[0][1:] or words[1]
    first = 1 if words[0][1:] else 2
    vertex_count, face_count = int(header[0]), int(header[1])
    positions = [[float(x) for x in row[:3]] for row in words[first:first + vertex_count]]
    triangles = []
    for row in words[first + vertex_count:first + vertex_count + face_count]:
        if int(row[0]) != 3:
            raise ValueError(f"a face of {row[0]} corners")
        triangles.append([int(x) for x in row[1:4]])
    return positions, triangles


def components(vertex_count, triangles):
    """Each vertex's piece: the smallest vertex it is joined to through triangles."""
    parent = list(range(vertex_count))

    def root(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v
    for a, b, c in triangles:
        for u, v in ((a, b), (b, c)):
            ru, rv = root(u), root(v)
            if ru != rv:
                parent[max(ru, rv)] = min(ru, rv)
    return [root(v) for v in range(vertex_count)]


def exact_worker(mesh, sources, out):
    """Writes {"distances": [[...] per source]} (exact, per input vertex) or {"refused": why} to OUT."""
    import numpy
    import pygeodesic.geodesic as geodesic
    try:
        positions, triangles = read_off_triangles(mesh)
    except (ValueError, IndexError) as error:
        Path(out).write_text(json.dumps({"refused": str(error)}))
        return
    used = set(v for t in triangles for v in t)
    if len(used) != len(positions):
        Path(out).write_text(json.dumps({"refused": f"{len(positions) - len(used)} vertices no face uses"}))
        return
    solver = geodesic.PyGeodesicAlgorithmExact(numpy.array(positions, dtype=float),
                                               numpy.array(triangles, dtype=numpy.int32))
    # Only the source's own piece is asked for: pygeodesic's answer for a
    # vertex it cannot reach carries an undefined source index, which
    # sometimes overflows its conversion (blobby_3cc, bones).
    piece = components(len(positions), triangles)
    rows = []
    for source in sources:
        targets = numpy.array([v for v in range(len(positions)) if piece[v] == piece[source]], dtype=numpy.int32)
        reached, _ = solver.geodesicDistances(numpy.array([source]), targets)
        row = [math.inf] * len(positions)
        for v, d in zip(targets, reached):
            row[int(v)] = float(d) if math.isfinite(d) and d < 1e300 else math.inf
        rows.append(row)
    Path(out).write_text(json.dumps({"distances": rows}))


# ---------------------------------------------------------------- the driver

def exact_python():
    venv = Path(os.environ.get("MESHPARTICLES_PEER_VENV") or shared.cache_home() / "meshparticles" / "peer-venv")
    python = shared.make_venv(venv, "peers'")
    if subprocess.run([str(python), "-c", "import numpy, pygeodesic"], capture_output=True).returncode != 0:
        progress(f"installing numpy and pygeodesic into {venv} (pip)")
        installed = subprocess.run([str(python), "-m", "pip", "install", "--quiet", "numpy", "pygeodesic"],
                                   stdout=sys.stderr, stderr=subprocess.PIPE, text=True)
        if installed.returncode != 0:
            die(f"{venv}: pip install pygeodesic failed ({shared.last_line(installed.stderr)})")
    return python


def exact_distances(python, mesh, sources, work):
    out = work / "exact.json"
    done = subprocess.run([str(python), str(Path(__file__).resolve()), "--exact-worker", str(mesh),
                           ",".join(map(str, sources)), str(out)], capture_output=True, text=True)
    if done.returncode != 0:
        raise Failure(f"exact solver failed: {shared.last_line(done.stderr)}")
    answer = json.loads(out.read_text())
    if "refused" in answer:
        raise Failure(answer["refused"])
    return answer["distances"]


def our_distances(binary, mesh, source, solver):
    done = shared.run_program([str(binary), "geodesics", str(mesh), "--source", str(source), "--geodesic", solver,
                               "--no-cache", "-q"], capture_output=True, text=True)
    if done.returncode != 0:
        raise Failure(f"geodesics --geodesic {solver} failed: {shared.last_line(done.stderr)}")
    return [float(x) for x in done.stdout.split()]


def mesh_size(binary, mesh):
    """(vertices, mean edge length) as `meshparticles info` gives them."""
    info = shared.run_program([str(binary), "info", str(mesh), "--json"], capture_output=True, text=True)
    if info.returncode != 0:
        raise Failure(shared.last_line(info.stderr).replace("meshparticles: error: ", ""))
    fields = json.loads(info.stdout)
    return int(fields["vertices"]), float(fields["mean_edge_length"])


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * (len(ordered) - 1) + 0.5))]


def compare_mesh(binary, python, mesh, vertices, edge, source_count, work):
    sources = sorted(set(k * vertices // source_count for k in range(source_count)))
    exact = exact_distances(python, mesh, sources, work)
    errors = {solver: [] for solver in SOLVERS}
    for source, truth in zip(sources, exact):
        for solver in SOLVERS:
            ours = our_distances(binary, mesh, source, solver)
            if len(ours) != len(truth):
                raise Failure(f"{len(ours)} distances from {solver}, {len(truth)} exact (the reader split vertices)")
            errors[solver] += [(d - t) / t for d, t in zip(ours, truth)
                               if math.isfinite(t) and t > NEAR_SOURCE_EDGES * edge and math.isfinite(d)]
    row = {"mesh": mesh.name, "vertices": vertices, "sources": sources}
    for solver, relative in errors.items():
        if not relative:
            raise Failure("no vertex far enough from the sources")
        row[solver] = {"mean": sum(relative) / len(relative), "p99": percentile([abs(r) for r in relative], 0.99),
                       "over": max(relative), "under": min(relative), "compared": len(relative)}
    return row


def percent(x):
    return f"{100 * x:+.2f}%"


def table(rows):
    lines = ["| mesh | V | " + " | ".join(f"{s} mean / p99 / over / under" for s in SOLVERS) + " |",
             "|---|---|" + "---|" * len(SOLVERS)]
    for row in sorted(rows, key=lambda r: -r["fmm"]["p99"]):
        cells = [f"{percent(row[s]['mean'])} / {100 * row[s]['p99']:.2f}% / {percent(row[s]['over'])} / "
                 f"{percent(row[s]['under'])}" for s in SOLVERS]
        lines.append(f"| {row['mesh']} | {row['vertices']:,} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def summary(rows):
    lines = [f"{len(rows)} meshes. Per solver, over the meshes:"]
    for solver in SOLVERS:
        p99s = [r[solver]["p99"] for r in rows]
        means = [abs(r[solver]["mean"]) for r in rows]
        lines.append(f"- {solver}: median |mean error| {100 * percentile(means, 0.5):.2f}%, "
                     f"median p99 {100 * percentile(p99s, 0.5):.2f}%; p99 over 1% on {sum(p > 0.01 for p in p99s)}, "
                     f"over 5% on {sum(p > 0.05 for p in p99s)}; the largest error "
                     f"{percent(max(r[solver]['over'] for r in rows))} / {percent(min(r[solver]['under'] for r in rows))}")
    fmm_worse = sum(r["fmm"]["over"] > r["fim"]["over"] + 0.01 for r in rows)
    fim_worse = sum(r["fim"]["over"] > r["fmm"]["over"] + 0.01 for r in rows)
    lines.append(f"- the largest over-estimate is 1 point or more larger with fmm on {fmm_worse} meshes, "
                 f"with fim on {fim_worse}")
    return "\n".join(lines)


def draw(rows, path):
    """Each mesh's worst over- and under-estimate, fmm across, fim up: below the diagonal fim is nearer."""
    import matplotlib
    matplotlib.use("Agg")  # files only
    import matplotlib.pyplot as plt
    figure, panels = plt.subplots(1, 2, figsize=(10, 4.8))
    for panel, key, title in ((panels[0], "over", "worst too long"), (panels[1], "under", "worst too short")):
        fmm = [100 * abs(r["fmm"][key]) for r in rows]
        fim = [100 * abs(r["fim"][key]) for r in rows]
        top = max(fmm + fim + [1.0]) * 1.05
        panel.plot([0, top], [0, top], color="0.6", linewidth=0.8)
        panel.scatter(fmm, fim, s=14)
        for row, x, y in zip(rows, fmm, fim):
            if max(x, y) > 10:
                panel.annotate(row["mesh"].rsplit(".", 1)[0], (x, y), fontsize=7, xytext=(3, 3),
                               textcoords="offset points")
        panel.set_xlim(0, top)
        panel.set_ylim(0, top)
        panel.set_xlabel("fmm, % of the exact distance")
        panel.set_ylabel("fim, %")
        panel.set_title(title)
    figure.suptitle(f"Against exact geodesics: each mesh's worst vertex ({len(rows)} meshes)")
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("meshes", nargs="*", type=Path, help="meshes (OFF, triangles); none: --corpus")
    parser.add_argument("--corpus", action="store_true", help="Debian libcgal-demo's meshes")
    parser.add_argument("--max-vertices", type=int, default=60000, help="corpus meshes up to this size")
    parser.add_argument("--sources", type=int, default=3, help="sources per mesh")
    parser.add_argument("--binary", type=Path, default=ROOT / "build" / "meshparticles")
    parser.add_argument("--json", type=Path, help="write the rows here too")
    parser.add_argument("--png", type=Path, help="draw each mesh's worst errors, fmm against fim, here")
    parser.add_argument("--exact-worker", nargs=3, metavar=("MESH", "SOURCES", "OUT"), help=argparse.SUPPRESS)
    arguments = parser.parse_args(argv)
    if arguments.sources < 1:
        parser.error("--sources must be at least 1")
    return arguments


def main(argv):
    arguments = parse_arguments(argv)
    if arguments.exact_worker:
        mesh, sources, out = arguments.exact_worker
        exact_worker(mesh, [int(s) for s in sources.split(",")], out)
        return 0
    shared.check_binary(arguments.binary)
    for mesh in arguments.meshes:
        if not mesh.is_file():
            die(f"{mesh}: no such mesh")
    meshes = arguments.meshes
    if arguments.corpus or not meshes:
        meshes = sorted(path for path in shared.corpus_directory().iterdir() if path.suffix == ".off")
    python = exact_python()
    rows = []
    with tempfile.TemporaryDirectory(prefix="geodesic-accuracy-") as work:
        for k, mesh in enumerate(meshes, 1):
            try:
                vertices, edge = mesh_size(arguments.binary, mesh)
                if (arguments.corpus or not arguments.meshes) and vertices > arguments.max_vertices:
                    continue
                progress(f"[{k}/{len(meshes)}] {mesh.name} ({vertices:,} vertices)")
                rows.append(compare_mesh(arguments.binary, python, mesh, vertices, edge, arguments.sources,
                                         Path(work)))
            except Failure as why:
                progress(f"{mesh.name}: left out ({why})")
    if not rows:
        die("no mesh could be compared")
    print(table(rows))
    print()
    print(summary(rows))
    if arguments.json:
        arguments.json.write_text(json.dumps(rows, indent=1))
    if arguments.png:
        draw(rows, arguments.png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
