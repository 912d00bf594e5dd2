#!/usr/bin/python3
"""A Coherent Point Drift baseline for `correspond`, scored as correspond is.

    scripts/cpd_baseline.py POPULATION_DIR -n N --out DIR [--correspond DIR] [--binary PATH] [--json FILE]
                            [--map-population FILE]

POPULATION_DIR is what `meshparticles generate --population K --family ellipsoid` (or radii)
writes: the meshes and population.json. The first mesh (in name order, as `correspond DIR` takes
it) is the template. Its particles are its own default run's (`meshparticles run TEMPLATE -n N`,
as correspond samples its template); each is then carried onto every other shape by pycpd
(Myronenko and Song's CPD, pure numpy), the particles as the moving set and the shape's vertices
as the target, rigid then deformable (pycpd's defaults: w 0, alpha 2, beta 2, at most 100
iterations), and put on the shape's vertex nearest its end point. The template keeps its
particles, each on its nearest vertex too.

The generated shapes arrive turned at random, beyond a rigid CPD's reach from one start, so the
rigid stage starts, after both sets are centred and scaled to unit rms radius, from the pose as
given and from the 24 proper rotations that take the particles' principal axes onto the shape's
(orders as well as signs, as correspond's alignment tries): each start is fitted by 30 rigid
iterations onto about 500 of the shape's vertices, and the one that ends with the smallest
symmetric mean closest-point distance is fitted on to the end onto them all.

Writes DIR/shapes/NNN_STEM.particles (world coordinates, row i particle i), which
scripts/correspondence_error.py scores (or, with `--map-population FILE`, for shapes with a
known vertex map, scripts/map_correspondence_error.py), and prints one table: the spread of particle i
(median / mean / 90th percentile, in particle spacings of the parameter sphere) and each shape's
evenness by `meshparticles quality MESH FILE --distances local --cutoff 1.5` (the measure
correspond's summary.json gives each shape: rho, the closest pair over the hexagonal spacing, and
cover, the farthest surface point from a particle over it; docs/QUALITY.md), for CPD and, with
`--correspond DIR` (a `correspond POPULATION_DIR -n N --out DIR` run), for correspond's
particles measured the same way.

pycpd lives in the peers' virtual environment (scripts/bench_real_models.py: made on first use,
$MESHPARTICLES_PEER_VENV or ~/.cache/meshparticles/peer-venv, pip install pycpd); this script
re-invokes itself there with --worker for the registrations.
"""
import argparse
import itertools
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
START_ITERATIONS = 30  # each start's rigid fit, before the best is fitted to the end


def progress(message):
    print(f"cpd_baseline: {message}", file=sys.stderr, flush=True)


# ================================================================ worker (inside the peer venv)

def off_vertices(path):
    """The vertices of an OFF file (what `generate` writes)."""
    words = Path(path).read_text().split()
    if not words or words[0] != "OFF":
        sys.exit(f"cpd_baseline: {path}: not an OFF file")
    count = int(words[1])
    return np.array(words[4:4 + 3 * count], dtype=float).reshape(count, 3)


def normalised(points):
    """POINTS centred and scaled to unit rms radius, with the centre and the scale."""
    centre = points.mean(axis=0)
    scale = np.sqrt(((points - centre) ** 2).sum(axis=1).mean())
    return (points - centre) / scale, centre, scale


def principal_axes(points):
    """The rows are the principal axes of centred POINTS, largest spread first."""
    values, vectors = np.linalg.eigh(points.T @ points)
    return vectors[:, np.argsort(values)[::-1]].T


def proper_axis_maps(moving, target):
    """The 24 proper rotations taking MOVING's principal axes onto TARGET's, in any order and sign."""
    a, b = principal_axes(moving), principal_axes(target)
    rotations = []
    for order in itertools.permutations(range(3)):
        for signs in itertools.product((1, -1), repeat=3):
            rotation = b.T @ (np.array(signs)[:, None] * a[list(order)])
            if np.linalg.det(rotation) > 0:
                rotations.append(rotation)
    return rotations


def nearest(points, targets):
    """Index of the nearest of TARGETS for each of POINTS, and the distance (brute force, in blocks)."""
    index, distance = np.empty(len(points), dtype=int), np.empty(len(points))
    for start in range(0, len(points), 512):
        block = points[start:start + 512]
        squared = ((block[:, None, :] - targets[None, :, :]) ** 2).sum(axis=2)
        index[start:start + 512] = squared.argmin(axis=1)
        distance[start:start + 512] = np.sqrt(squared.min(axis=1))
    return index, distance


def chamfer(a, b):
    return nearest(a, b)[1].mean() + nearest(b, a)[1].mean()


def carry(particles, vertices):
    """PARTICLES registered onto VERTICES by CPD, rigid from the best start, then deformable."""
    from pycpd import DeformableRegistration, RigidRegistration

    moving, _, _ = normalised(particles)
    target, centre, scale = normalised(vertices)
    # The starts are judged on about 500 of the vertices after a short rigid fit; the best
    # goes on to the whole shape.
    sample = target[::max(1, len(target) // 500)]
    best = None
    for rotation in [np.eye(3)] + proper_axis_maps(moving, target):
        rigid, _ = RigidRegistration(X=sample, Y=moving @ rotation.T, max_iterations=START_ITERATIONS).register()
        fit = chamfer(rigid, sample)
        if best is None or fit < best[0]:
            best = (fit, rigid)
    rigid, _ = RigidRegistration(X=target, Y=best[1]).register()
    deformed, _ = DeformableRegistration(X=target, Y=rigid).register()
    return nearest(deformed * scale + centre, vertices)[0]


def worker(args):
    """Runs in the venv: the template's particles carried onto each mesh, one file per mesh."""
    template = np.loadtxt(args.template_particles, ndmin=2)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for index, mesh in enumerate(args.meshes):
        vertices = off_vertices(mesh)
        start = time.time()
        if index == 0:
            chosen = nearest(template, vertices)[0]
        else:
            chosen = carry(template, vertices)
        np.savetxt(out / f"{index:03d}_{Path(mesh).stem}.particles", vertices[chosen], fmt="%.9g")
        progress(f"{Path(mesh).name}: {time.time() - start:.1f} s")


# ================================================================ the measures (Debian's python3)

def run(command, **options):
    done = subprocess.run([str(part) for part in command], capture_output=True, text=True, **options)
    if done.returncode != 0:
        sys.exit(f"cpd_baseline: {' '.join(map(str, command))}: exit {done.returncode}: {done.stderr.strip()[-400:]}")
    return done.stdout


def spread(population_json, files):
    """The yardstick's figures (scripts/correspondence_error.py, for a generated population or a map)."""
    with tempfile.TemporaryDirectory() as scratch:
        figures = Path(scratch) / "spread.json"
        run([sys.executable, ROOT / "scripts/correspondence_error.py", population_json, *files, "--json", figures])
        return json.loads(figures.read_text())


def evenness(binary, meshes, files):
    """Per shape, rho and cover of its particles on its own surface, as correspond measures each shape."""
    figures = []
    for mesh, file in zip(meshes, files):
        quality = json.loads(run([binary, "quality", mesh, file, "--json", "-q", "--distances", "local",
                                  "--cutoff", "1.5"]))
        figures.append(quality.get("quality", quality))
    return figures


def table_row(label, score, figures):
    rho = np.array([f["rho"] for f in figures], dtype=float)
    cover = np.array([f["cover"] for f in figures], dtype=float)
    return (f"| {label} | {score['median']:.2f} / {score['mean']:.2f} / {score['p90']:.2f} | "
            f"{rho.min():.2f} / {np.median(rho):.2f} | {np.median(cover):.2f} / {cover.max():.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--template-particles", help=argparse.SUPPRESS)
    parser.add_argument("--meshes", nargs="+", help=argparse.SUPPRESS)
    parser.add_argument("population", nargs="?", type=Path)
    parser.add_argument("-n", type=int, default=256)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--correspond", type=Path, help="a correspond run on the population, to score beside")
    parser.add_argument("--binary", type=Path, default=ROOT / "build/meshparticles")
    parser.add_argument("--json", type=Path, help="also write the figures here")
    parser.add_argument("--map-population", type=Path,
                        help="score by this map population (scripts/map_correspondence_error.py's measure) instead of "
                             "POPULATION_DIR/population.json")
    args = parser.parse_args()
    if args.worker:
        return worker(args)
    if args.population is None:
        parser.error("give the population's folder")

    sys.path.insert(0, str(ROOT / "scripts"))
    import bench_real_models as peers
    import compare_samplers as shared
    python = shared.make_venv(peers.peer_venv(), "peers'")
    if not peers.imports(python, "pycpd"):
        peers.install_packages(python, ["pycpd"])

    population_json = args.map_population or args.population / "population.json"
    meshes = sorted(str(path) for path in args.population.glob("*.off"))
    if len(meshes) < 2:
        sys.exit(f"cpd_baseline: {args.population}: fewer than 2 meshes")
    progress(f"sampling the template {Path(meshes[0]).name} (n = {args.n})")
    run([args.binary, "run", meshes[0], "-n", args.n, "-q", "--out", args.out / "template"])
    start = time.time()
    subprocess.run([str(python), __file__, "--worker", "--out", str(args.out / "shapes"),
                    "--template-particles", str(args.out / "template/particles.particles"),
                    "--meshes", *meshes], check=True)
    seconds = time.time() - start
    files = [str(args.out / "shapes" / f"{index:03d}_{Path(mesh).stem}.particles")
             for index, mesh in enumerate(meshes)]
    results = {"cpd": {"spread": spread(population_json, files), "evenness": evenness(args.binary, meshes, files),
                       "seconds": seconds}}
    if args.correspond:
        theirs = sorted(str(path) for path in (args.correspond / "shapes").glob("*.particles"))
        results["correspond"] = {"spread": spread(population_json, theirs),
                                 "evenness": evenness(args.binary, meshes, theirs)}
    print(f"{len(meshes)} shapes, n = {args.n}; CPD took {seconds:.0f} s")
    print("| particles | spread of particle i: median / mean / p90 | rho: least / median | cover: median / most |")
    print("|---|---|---|---|")
    for key, label in (("correspond", "correspond"), ("cpd", "CPD (pycpd, rigid then deformable)")):
        if key in results:
            print(table_row(label, results[key]["spread"], results[key]["evenness"]))
    if args.json:
        args.json.write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
