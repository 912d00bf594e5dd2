#!/usr/bin/env bash
# shape_model.sh MESHPARTICLES WORKDIR: `meshparticles model` end to end on a
# population whose answer is known: one base shape stretched by known
# amounts, each copy in a random pose and size. The model must hold all the
# variance in one mode, every file must be there, each transform must take
# its input onto its aligned file, and a file with another point count must
# be refused in one line.
set -euo pipefail
bin=$1 work=$2
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
/usr/bin/python3 - "$work" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
rng = np.random.default_rng(5)
base = rng.uniform(-1, 1, (120, 3)) * [1.0, 0.5, 0.3]
for k in range(6):
    shape = base.copy()
    shape[:, 0] += rng.uniform(-0.2, 0.2) * (base[:, 0] - base[:, 0].mean())
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    if np.linalg.det(q) < 0:
        q[:, 0] *= -1
    shape = rng.uniform(0.5, 3) * shape @ q.T + rng.uniform(-50, 50, 3)
    np.savetxt(f"{work}/shape_{k}.particles", shape, fmt="%.12g")
np.savetxt(f"{work}/short.particles", base[:-1], fmt="%.12g")
PY
"$bin" model "$work"/shape_*.particles --out "$work/model" --samples 100 -q >"$work/stdout"
grep -q "^shapes      6, 120 points each" "$work/stdout" || fail "summary: $(cat "$work/stdout")"
for file in mean.particles modes.csv modes.json transforms.json evaluation.csv model.json \
            000_shape_0.aligned.particles 005_shape_5.aligned.particles; do
  [ -s "$work/model/$file" ] || fail "no $file"
done
/usr/bin/python3 - "$work" <<'PY' || exit 1
import json, sys
import numpy as np
work = sys.argv[1]
model = json.load(open(f"{work}/model/model.json"))
assert model["compactness"][0] > 0.999, model["compactness"]
assert len(model["generalization"]["mean"]) == 4, model["generalization"]
transforms = json.load(open(f"{work}/model/transforms.json"))["world_to_aligned"]
for entry in transforms:
    world = np.loadtxt(entry["file"])
    m = np.array(entry["matrix"])
    aligned = world @ m[:3, :3].T + m[:3, 3]
    expected = np.loadtxt(f"{work}/model/{entry['aligned']}")
    error = np.abs(aligned - expected).max()
    assert error < 1e-6 * np.abs(expected).max(), (entry["file"], error)
print("model: one mode holds", model["compactness"][0], "; transforms reproduce the aligned files")
PY
set +e
errors=$("$bin" model "$work/shape_0.particles" "$work/short.particles" --out "$work/refused" 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -eq 2 ] || fail "a shape with 119 points: exit $code"
[ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "not one line: $errors"
grep -q "short.particles: 119 points, but .*shape_0.particles has 120: a shape model needs the same points on every shape" \
  <<<"$errors" || fail "$errors"
[ ! -e "$work/refused" ] || fail "a refused model left a folder"
# A coordinate whose square would overflow (it crashed the model): one line
# naming the file, exit 2.
{ echo "1e154 1e154 1e154"; tail -n +2 "$work/shape_1.particles"; } >"$work/huge.particles"
set +e
errors=$("$bin" model "$work/shape_0.particles" "$work/shape_2.particles" "$work/huge.particles" --out "$work/huge" \
         2>&1 >/dev/null)
code=$?
set -e
[ "$code" -eq 2 ] && [ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "huge coordinate: exit $code: $errors"
grep -q "huge.particles: line 1 has a coordinate beyond 1e150" <<<"$errors" || fail "$errors"
# Points 1e-170 apart: their squares underflow, so they once read as "all at
# one place"; the refusal names the real cause.
awk '{ printf "%.17g %.17g %.17g\n", $1 * 1e-170, $2 * 1e-170, $3 * 1e-170 }' "$work/shape_1.particles" \
  >"$work/tiny.particles"
set +e
errors=$("$bin" model "$work/shape_0.particles" "$work/tiny.particles" --out "$work/tiny" 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -eq 2 ] && [ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "tiny shape: exit $code: $errors"
grep -q "tiny.particles: its points lie within .*e-1[67][0-9] of each other, under 1e-150 (their squared distances would underflow)" \
  <<<"$errors" || fail "tiny shape: $errors"
[ ! -e "$work/tiny" ] || fail "a refused model left a folder"
# Three copies of one shape, moved: no variance above rounding, so no mode
# (it reported one mode holding 100%, and with none it crashed).
for k in 1 2 3; do
  awk -v k="$k" '{ printf "%.17g %.17g %.17g\n", $1 + 1000.1 * k, $2 - 0.3 * k, $3 + 7 * k }' "$work/shape_0.particles" \
    >"$work/same_$k.particles"
done
"$bin" model "$work/same_1.particles" "$work/same_2.particles" "$work/same_3.particles" --out "$work/same" \
  >"$work/same.out" || fail "three copies: exit $?"
grep -q "^modes       0$" "$work/same.out" || fail "three copies: $(cat "$work/same.out")"
/usr/bin/python3 -c "import json, sys; m = json.load(open(sys.argv[1])); assert m['compactness'] == [], m" \
  "$work/same/model.json" || fail "three copies: modes in model.json"
echo "ok"
