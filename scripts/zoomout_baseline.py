"""A ZoomOut (functional maps) baseline for `correspond`: the template's particles carried to each shape.

    PYTHON scripts/zoomout_baseline.py POPULATION_DIR -n N --out DIR [--binary PATH]

PYTHON is one with pyfmaps (PyPI, MIT licence, `import pyFM`), numpy and scipy:
scripts/correspondence_scoreboard.sh makes such a virtual environment under its OUT_DIR; this
script is never a dependency of the program. POPULATION_DIR holds the meshes (OFF) of one
population; the first in name order (as `correspond DIR` takes it) is the template. Its particles
are its own default run's (`meshparticles run TEMPLATE -n N`, as correspond samples its template),
each put on the template's nearest vertex. For every other shape, pyFM computes a functional map
between the template and the shape (each scaled to unit area, as the generated populations' shapes
differ in scale; Laplace-Beltrami eigenvectors of each mesh, WKS descriptors,
pyFM's default energy weights, a 50 x 50 map refined by ZoomOut (Melzi et al. 2019) in 10 steps of
10 to 150 x 150) and turns it into a vertex map from the template to the shape; each particle goes
to the shape vertex its template vertex maps to. The template keeps its snapped particles.

Writes DIR/shapes/NNN_STEM.particles (world coordinates, row i particle i, in the meshes' name
order), which scripts/correspondence_error.py scores (by the population's map, or for a generated
population its population.json) and `meshparticles quality` measures, and DIR/seconds.json (the
maps' time). Progress on stderr.
"""
import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

ROOT = Path(__file__).resolve().parent.parent
START_EIGENVECTORS = 50  # the map's size before ZoomOut
ZOOMOUT_STEPS, ZOOMOUT_STEP = 10, 10  # 50 -> 150 eigenvectors


def progress(message):
    print(f"zoomout_baseline: {message}", file=sys.stderr, flush=True)


def read_off(path):
    """(vertices, triangles) of an OFF file."""
    words = Path(path).read_text().split()
    if not words or not words[0].endswith("OFF"):
        sys.exit(f"zoomout_baseline: {path}: not an OFF file")
    vertex_count, face_count = int(words[1]), int(words[2])
    vertices = np.array(words[4:4 + 3 * vertex_count], dtype=float).reshape(vertex_count, 3)
    at, faces = 4 + 3 * vertex_count, []
    for _ in range(face_count):
        corners = int(words[at])
        if corners != 3:
            sys.exit(f"zoomout_baseline: {path}: a face with {corners} corners (triangles only)")
        faces.append([int(word) for word in words[at + 1:at + 4]])
        at += 1 + corners
    return vertices, np.array(faces, dtype=int)


def template_to_shape(template, shape):
    """ZoomOut's vertex map: entry v the shape's vertex that the template's vertex v maps to. template is a
    pyFM TriMesh, shared by the calls so that its spectrum is computed once."""
    from pyFM.functional import FunctionalMapping
    from pyFM.mesh import TriMesh
    # get_p2p maps mesh2 to mesh1, so the shape is mesh1 and the template mesh2.
    model = FunctionalMapping(TriMesh(*shape, normalize=True), template)
    model.preprocess(descr_type="WKS", k_process=START_EIGENVECTORS + ZOOMOUT_STEPS * ZOOMOUT_STEP + 10)
    model.fit(K=(START_EIGENVECTORS, START_EIGENVECTORS))
    refined = model.zoomout_refine(nit=ZOOMOUT_STEPS, step=ZOOMOUT_STEP)
    return model.get_p2p(refined, n_jobs=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("population", type=Path)
    parser.add_argument("-n", type=int, default=256)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--binary", type=Path, default=ROOT / "build/meshparticles")
    args = parser.parse_args()

    meshes = sorted(args.population.glob("*.off"))
    if len(meshes) < 2:
        sys.exit(f"zoomout_baseline: {args.population}: fewer than 2 meshes")
    progress(f"sampling the template {meshes[0].name} (n = {args.n})")
    done = subprocess.run([str(args.binary), "run", str(meshes[0]), "-n", str(args.n), "-q", "--out",
                           str(args.out / "template")], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"zoomout_baseline: sampling the template: exit {done.returncode}: {done.stderr.strip()[-400:]}")
    particles = np.loadtxt(args.out / "template/particles.particles", ndmin=2)
    template = read_off(meshes[0])
    on_template = cKDTree(template[0]).query(particles)[1]  # each particle's nearest template vertex

    (args.out / "shapes").mkdir(parents=True, exist_ok=True)
    from pyFM.mesh import TriMesh
    template_mesh = TriMesh(*template, normalize=True)  # unit area (WKS is not scale-free), centred
    start = time.time()
    for index, mesh in enumerate(meshes):
        shape = template if index == 0 else read_off(mesh)
        chosen = on_template if index == 0 else template_to_shape(template_mesh, shape)[on_template]
        file = args.out / "shapes" / f"{index:03d}_{mesh.stem}.particles"
        scratch = file.with_suffix(".particles.tmp")
        np.savetxt(scratch, shape[0][chosen], fmt="%.9g")
        scratch.replace(file)  # a file that is there is whole (the scoreboard resumes by it)
        progress(f"{mesh.name}: {time.time() - start:.1f} s")
    (args.out / "seconds.json").write_text(json.dumps({"seconds": time.time() - start}) + "\n")


if __name__ == "__main__":
    main()
