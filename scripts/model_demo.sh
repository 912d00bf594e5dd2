#!/usr/bin/env bash
# scripts/model_demo.sh [OUT_DIR]
#
# What: the shape model (`meshparticles model`) of a population whose correspondence is
# known, beside the model of the same population sampled shape by shape (`batch`), as in
# docs/CORRESPONDENCE.md. The population: `generate --population 20 --vertices 2000`, atrium-
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
for kind in corresponding batch; do
  "$here/scripts/plot_model.py" "$out/$kind/model" --out "$out/$kind/model.png" >/dev/null
  echo "== $kind"
  head -6 "$out/$kind/model/evaluation.csv"
done
echo "pictures: $out/corresponding/model.png, $out/batch/model.png"
