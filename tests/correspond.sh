#!/usr/bin/env bash
# correspond.sh MESHPARTICLES MESH WORKDIR [OPTION...]: `meshparticles
# correspond` (with OPTIONs) on a population whose answer is known: MESH
# itself and three copies of it moved, turned and scaled at random (one with
# its vertices renumbered, one with the last bit of half its coordinates
# flipped, as another numpy's BLAS may round them). Each copy must be
# aligned back (fit near 0) and every particle must land where it lies on
# MESH, within 1% of the spacing: not exactly, because the joint
# refinement's 200 iterations amplify the transfer's differences of about
# 1e-6 spacings (even on a byte-identical copy) about a thousandfold: 0.0004
# to 0.004 spacings at most, measured on 14 such copies. Every output must
# be there, and a single mesh must be refused in one line.
set -euo pipefail
bin=$1 mesh=$2 work=$3
shift 3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
/usr/bin/python3 - "$mesh" "$work" <<'PY'
import sys
import numpy as np
mesh, work = sys.argv[1], sys.argv[2]
words = open(mesh).read().split()
n, f = int(words[1]), int(words[2])
vertices = np.array(words[4:4 + 3 * n], float).reshape(n, 3)
faces = np.array(words[4 + 3 * n:4 + 3 * n + 4 * f], int).reshape(f, 4)[:, 1:]
rng = np.random.default_rng(11)
for name, renumber, last_bits in (("moved", False, False), ("renumbered", True, False), ("rounded", False, True)):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    if np.linalg.det(q) < 0:
        q[:, 0] *= -1
    moved = rng.uniform(0.3, 4) * vertices @ q.T + rng.uniform(-100, 100, 3)
    if last_bits:
        flip = rng.random(moved.shape) < 0.5
        moved[flip] = np.nextafter(moved[flip], np.inf)
    order = rng.permutation(n) if renumber else np.arange(n)  # new vertex k is old vertex order[k]
    new_of_old = np.empty(n, int)
    new_of_old[order] = np.arange(n)
    with open(f"{work}/{name}.off", "w") as out:
        out.write(f"OFF\n{n} {f} 0\n")
        out.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in moved[order])
        out.writelines("3 %d %d %d\n" % tuple(new_of_old[t]) for t in faces)
    np.savetxt(f"{work}/{name}.ids", order, fmt="%d")
PY
"$bin" correspond "$mesh" "$work/moved.off" "$work/renumbered.off" "$work/rounded.off" -n 64 --samples 20 -q "$@" --out "$work/out" >"$work/stdout"
for file in summary.json shapes/000_$(basename "${mesh%.*}").csv shapes/001_moved.particles shapes/002_renumbered.csv \
            shapes/003_rounded.csv \
            model/model.json model/transforms.json; do
  [ -s "$work/out/$file" ] || fail "no $file"
done
/usr/bin/python3 - "$mesh" "$work" "$(basename "${mesh%.*}")" <<'PY' || exit 1
import csv, json, sys
import numpy as np
mesh, work, stem = sys.argv[1], sys.argv[2], sys.argv[3]
words = open(mesh).read().split()
n, f = int(words[1]), int(words[2])
vertices = np.array(words[4:4 + 3 * n], float).reshape(n, 3)
faces = np.array(words[4 + 3 * n:4 + 3 * n + 4 * f], int).reshape(f, 4)[:, 1:]
area = 0.5 * np.linalg.norm(np.cross(vertices[faces[:, 1]] - vertices[faces[:, 0]],
                                     vertices[faces[:, 2]] - vertices[faces[:, 0]]), axis=1).sum()
def on_mesh(name, ids=None):  # each particle's place on MESH, from its corners (back to MESH's ids) and weights
    rows = list(csv.DictReader(open(f"{work}/out/shapes/{name}.csv")))
    corners = np.array([[int(r[k]) for k in ("corner_a", "corner_b", "corner_c")] for r in rows])
    weights = np.array([[float(r[k]) for k in ("weight_a", "weight_b", "weight_c")] for r in rows])
    if ids is not None:
        corners = ids[corners]
    return (vertices[corners] * weights[:, :, None]).sum(axis=1)
template = on_mesh(f"000_{stem}")
spacing = np.sqrt(2 * area / (np.sqrt(3) * len(template)))
tolerance = 0.01  # spacings
for name, ids in (("001_moved", None), ("002_renumbered", np.loadtxt(f"{work}/renumbered.ids", dtype=int)),
                  ("003_rounded", None)):
    off = np.linalg.norm(on_mesh(name, ids) - template, axis=1) / spacing
    assert off.max() <= tolerance, f"{name}: particle {off.argmax()} {off.max():.3g} spacings from the template's"
summary = json.load(open(f"{work}/out/summary.json"))
fits = [shape["fit_rms"] for shape in summary["shapes"]]
assert max(fits) < 1e-6, fits
assert summary["warnings"] == [], summary["warnings"]
print(f"every particle within {tolerance} spacings of its place on the template on all three copies; fits", fits)
PY
set +e
errors=$("$bin" correspond "$mesh" --out "$work/one" -n 8 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -eq 2 ] && [ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "one mesh: exit $code: $errors"
grep -q "correspond needs at least 2 meshes, got 1" <<<"$errors" || fail "$errors"
# The same file twice is one mesh, and the refusal says why.
set +e
errors=$("$bin" correspond "$mesh" "$mesh" --out "$work/twice" -n 8 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -eq 2 ] && [ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "the same mesh twice: exit $code: $errors"
grep -q "got 1; .* is the same file as .*: run once" <<<"$errors" || fail "$errors"
# A shape of another topology runs, and is said to be one: the torus
# beside the committed sphere (on stdout's summary too, and in summary.json).
# Its --out holds what a run killed while it wrote its outputs leaves, hidden
# temporaries of a process that is gone: the run removes them and goes on.
meshes=$(dirname "$mesh")
sleep 0 & gone=$!
wait "$gone"
host=$(/usr/bin/python3 -c 'import re, socket; print(re.sub("[^A-Za-z0-9]", "_", socket.gethostname()))')
mkdir -p "$work/mixed/.shapes.tmp-$host-$gone-0" "$work/mixed/.model.tmp-$host-$gone-1"
touch "$work/mixed/.summary.tmp-$host-$gone-2.json"
"$bin" correspond "$meshes/sphere.off" "$meshes/torus.off" -n 32 --samples 10 --refine-iterations 0 --out "$work/mixed" \
  >/dev/null 2>"$work/mixed.log" || fail "a sphere and a torus (and a killed run's temporaries): $(cat "$work/mixed.log")"
leftover=$(find "$work/mixed" -maxdepth 1 -name '.*tmp-*')
[ -z "$leftover" ] || fail "left: $leftover"
grep -q "warning: .*torus.off (1 component, genus 1, no boundary) is not of the template's topology (1 component, genus 0, no boundary)" \
  "$work/mixed.log" || fail "no warning of a torus among spheres: $(cat "$work/mixed.log")"
# Turned about its axis, a torus fits a sphere as well as ever, and no pose
# lays a sphere's relief over a torus's: said too.
grep -q "warning: .*torus.off: the template's features agree with its own by .* at best.* (fit_relief, under 0.30)" \
  "$work/mixed.log" || fail "no warning of a torus's pose: $(cat "$work/mixed.log")"
/usr/bin/python3 -c 'import json, sys; w = json.load(open(sys.argv[1]))["warnings"]; assert len(w) == 2 and all("torus" in l for l in w), w' \
  "$work/mixed/summary.json" || fail "summary.json lacks the warnings"
echo "ok"
