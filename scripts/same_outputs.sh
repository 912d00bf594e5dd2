#!/usr/bin/env bash
# same_outputs.sh BEFORE AFTER [WORKDIR]: do two builds of meshparticles write
# the same outputs? For refactors, which must not change a byte. Runs `run`
# (spread and paper, every backend kind, dense and local distances), `batch`
# and `correspond` with each binary on the committed meshes and a generated
# population, then compares every file. What may differ between two runs of
# one binary is left out: in JSON, timings (keys holding "seconds", ending in
# "ms"), the version, report.json's digest in batch's summary and the balls
# the local store's helper threads happened to solve per iteration; in CSV,
# the columns holding "seconds". Every other file is compared byte for byte. Prints the files that differ; exit 1 if any do.
#   scripts/same_outputs.sh /tmp/before/meshparticles build/meshparticles
set -euo pipefail
before=$(realpath "$1") after=$(realpath "$2")
work=${3:-$(mktemp -d)}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
meshes="$root/meshes"
export MESHPARTICLES_DEVICE="${MESHPARTICLES_DEVICE:-Portable Computing Language}"

outputs() (  # BIN DIR: every command's outputs under DIR, named relative to it
  bin=$1 out=.
  mkdir -p "$2" && cd "$2"
  for mesh in sphere torus atrium patch; do
    "$bin" run "$meshes/$mesh.off" -n 48 --seed 3 -q --out "$out/spread-$mesh" >/dev/null
  done
  "$bin" run "$meshes/high_valence.off" -n 6 -q --out "$out/spread-high_valence" >/dev/null
  "$bin" run "$meshes/sphere.off" -n 40 --method paper --backend serial -q --out "$out/paper-serial" >/dev/null
  for backend in naive tiled field; do
    "$bin" run "$meshes/torus.off" -n 40 --method paper --backend "$backend" -q --out "$out/paper-$backend" >/dev/null
  done
  "$bin" run "$meshes/torus.off" -n 40 --method paper --backend serial-field --potential gauss -q \
    --out "$out/paper-gauss" >/dev/null
  "$bin" run "$meshes/atrium.off" -n 40 --method paper --distances local -q --out "$out/paper-local" >/dev/null
  "$bin" batch "$meshes" -n 3 -q --out "$out/batch" >/dev/null
  "$bin" generate --population 4 --family ellipsoid --vertices 900 --out-dir "$out/population" 2>/dev/null
  "$bin" correspond "$out/population" -n 32 --samples 12 -q --out "$out/correspond" >/dev/null
)

echo "same_outputs: writing with $before" >&2
outputs "$before" "$work/before"
echo "same_outputs: writing with $after" >&2
outputs "$after" "$work/after"

python3 - "$work/before" "$work/after" <<'PY'
import json, os, sys
before, after = sys.argv[1], sys.argv[2]

def timing(key):
    return ("seconds" in key or key == "ms" or key.endswith("_ms")
            or key in ("version", "report_sha256", "balls"))

def without_timings(node):
    if isinstance(node, dict):
        return {k: without_timings(v) for k, v in node.items() if not timing(k)}
    if isinstance(node, list):
        return [without_timings(v) for v in node]
    return node

def csv_without_timings(text):
    rows = [line.split(",") for line in text.decode().splitlines()]
    keep = [i for i, name in enumerate(rows[0]) if "seconds" not in name] if rows else []
    return [[row[i] for i in keep if i < len(row)] for row in rows]

def files(top):
    return sorted(os.path.relpath(os.path.join(d, f), top)
                  for d, _, names in os.walk(top) for f in names)

differ = sorted(set(files(before)) ^ set(files(after)))
for name in sorted(set(files(before)) & set(files(after))):
    a = open(os.path.join(before, name), "rb").read()
    b = open(os.path.join(after, name), "rb").read()
    if name.endswith(".json"):
        a, b = (without_timings(json.loads(x)) for x in (a, b))
    elif name.endswith("summary.csv"):
        a, b = (csv_without_timings(x) for x in (a, b))
    if a != b:
        differ.append(name)
for name in differ:
    print("differs:", name)
print(f"same_outputs: {len(files(before))} files, {len(differ)} differ")
sys.exit(1 if differ else 0)
PY
