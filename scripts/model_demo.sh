#!/usr/bin/env bash
# scripts/model_demo.sh [OUT_DIR]
#
# What: the shape model (`meshparticles model`) of a population whose correspondence is
# known, beside the models of the same population sampled shape by shape (`batch`) and by
# `meshparticles correspond` (template transfer), as in docs/CORRESPONDENCE.md, and how far
# each method's particle i lands from its true place (the correspondence error). The population: `generate --population 20 --vertices 2000`, atrium-
# like shapes of one parameterisation (vertex i is the same place of every shape). Known
# correspondence: spread's 256 particles on the first shape, snapped to their nearest
# vertices (particles.csv's `vertex`), taken at the same vertex ids on every shape. Shape by
# shape: `batch -n 256`, each shape on its own. Writes OUT_DIR/{corresponding,batch}/model and
# a picture of each (scripts/plot_model.py), and prints both evaluation tables.
#
# Why: a model is only as good as its correspondence; this shows how far apart the two are
# on the measures shape-model papers report (about 20 s here).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=$here/build/meshparticles
out=${1:-$(mktemp -d)}
[ -x "$bin" ] || { echo "build first: scripts/setup.sh" >&2; exit 2; }
mkdir -p "$out/meshes" "$out/corresponding"
"$bin" generate --population 20 --vertices 2000 --out-dir "$out/meshes" >/dev/null
"$bin" run "$out/meshes/atrium_000.off" -n 256 -q --out "$out/first" >/dev/null
/usr/bin/python3 - "$out" <<'PY'
import csv, sys
from pathlib import Path
out = Path(sys.argv[1])
ids = [int(row["vertex"]) for row in csv.DictReader(open(out / "first/particles.csv"))]
for mesh in sorted((out / "meshes").glob("atrium_*.off")):
    words = mesh.read_text().split()
    count = int(words[1])
    vertices = [words[4 + 3 * i: 7 + 3 * i] for i in range(count)]
    (out / "corresponding" / (mesh.stem + ".particles")).write_text(
        "".join(" ".join(vertices[i]) + "\n" for i in ids))
PY
"$bin" model "$out"/corresponding/*.particles --out "$out/corresponding/model" -q
"$bin" batch "$out"/meshes/atrium_*.off -n 256 -q --out "$out/batch" >/dev/null
"$bin" model "$out"/batch/atrium_*/particles.particles --out "$out/batch/model" -q
"$bin" correspond "$out"/meshes/atrium_*.off -n 256 -q --out "$out/correspond" >/dev/null
# The correspondence error: particle i of shape s sits at some vertex; the same vertex id on the
# first shape is its true place there; the distance to where particle i sits on the first shape,
# in hexagonal spacings of the first shape at n = 256, over every particle of shapes 1..19.
/usr/bin/python3 - "$out" <<'PY'
import csv, math, sys
from pathlib import Path
import numpy as np
out = Path(sys.argv[1])
words = (out / "meshes/atrium_000.off").read_text().split()
count, faces = int(words[1]), int(words[2])
v0 = np.array(words[4:4 + 3 * count], float).reshape(count, 3)
t0 = np.array(words[4 + 3 * count:4 + 3 * count + 4 * faces], int).reshape(faces, 4)[:, 1:]
area = 0.5 * np.linalg.norm(np.cross(v0[t0[:, 1]] - v0[t0[:, 0]], v0[t0[:, 2]] - v0[t0[:, 0]]), axis=1).sum()
d_hex = math.sqrt(2 * area / (math.sqrt(3) * 256))
ids = lambda path: np.array([int(row["vertex"]) for row in csv.DictReader(open(path))])
first = ids(out / "first/particles.csv")
methods = {
    "true correspondence": [first] * 20,
    "batch (shape by shape)": [ids(out / "batch" / f"atrium_{s:03d}/particles.csv") for s in range(20)],
    "correspond (template transfer)": [ids(p) for p in sorted((out / "correspond/shapes").glob("*.csv"))],
}
print("== correspondence error, particle spacings: median, mean, 90th percentile")
for name, per_shape in methods.items():
    error = np.concatenate([np.linalg.norm(v0[s] - v0[per_shape[0]], axis=1) for s in per_shape[1:]]) / d_hex
    print(f"{name:32s} {np.median(error):.2f}  {error.mean():.2f}  {np.percentile(error, 90):.2f}")
PY
for kind in corresponding batch correspond; do
  model=$out/$kind/model
  "$here/scripts/plot_model.py" "$model" --out "$out/$kind/model.png" >/dev/null
  echo "== $kind"
  head -6 "$model/evaluation.csv"
done
echo "pictures: $out/{corresponding,batch,correspond}/model.png"
