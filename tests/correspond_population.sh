#!/usr/bin/env bash
# correspond_population.sh MESHPARTICLES SCRIPTS WORKDIR: `correspond` on a
# population whose true correspondence is known (`generate --population
# --family ellipsoid`: shapes meshed each on its own, posed at random). Each
# particle's places, mapped back to the shapes' common parameter
# (scripts/correspondence_error.py), must lie within issue 31's spread
# (median 0.3, 90th percentile 0.6 particle spacings); `batch`, which samples
# each shape on its own, must score far worse (the yardstick can tell).
set -euo pipefail
bin=$1 scripts=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
"$bin" generate --population 6 --family ellipsoid --vertices 1200 --out-dir "$work/shapes" 2>/dev/null
[ -s "$work/shapes/population.json" ] || fail "no population.json"
"$bin" correspond "$work/shapes" -n 64 --samples 20 -q --out "$work/correspond" >/dev/null
"$bin" batch "$work/shapes" -n 64 -q --out "$work/batch" >/dev/null
score() { /usr/bin/python3 "$scripts/correspondence_error.py" "$work/shapes/population.json" "$@" --json "$work/score.json" >/dev/null
          /usr/bin/python3 -c "import json, sys; d = json.load(open(sys.argv[1])); print(d['median'], d['p90'])" "$work/score.json"; }
read -r median p90 < <(score "$work"/correspond/shapes/*.particles)
echo "correspond: median $median, 90th percentile $p90"
/usr/bin/python3 -c "import sys; sys.exit(not (float(sys.argv[1]) <= 0.3 and float(sys.argv[2]) <= 0.6))" "$median" "$p90" \
  || fail "correspond spreads particle i by $median (median) / $p90 (90th percentile) spacings"
read -r batch_median batch_p90 < <(score "$work"/batch/*/particles.particles)
echo "batch: median $batch_median, 90th percentile $batch_p90"
/usr/bin/python3 -c "import sys; sys.exit(not float(sys.argv[1]) >= 1.5)" "$batch_median" \
  || fail "batch's independent samplings score $batch_median: the yardstick cannot tell them from corresponding ones"

# FAMILY SEED MEDIAN: a 6-shape population of the family, corresponded at
# n = 64; no shape may lie turned as a whole (more than 20 degrees) from the
# others, and particle i's median spread must be at most MEDIAN.
no_shape_turned() {
  local family=$1 seed=$2 median=$3
  "$bin" generate --population 6 --family "$family" --vertices 1200 --seed "$seed" --out-dir "$work/$family" 2>/dev/null
  "$bin" correspond "$work/$family" -n 64 --samples 20 -q --out "$work/${family}_correspond" >/dev/null
  /usr/bin/python3 "$scripts/correspondence_error.py" "$work/$family/population.json" \
    "$work/${family}_correspond"/shapes/*.particles --json "$work/${family}_score.json"
  /usr/bin/python3 - "$work/${family}_score.json" "$median" <<'CHECK' || fail "the $family family: a shape lies turned, or particle i spreads far"
import json, sys
score = json.load(open(sys.argv[1]))
turned = [shape for shape in score["per_shape"] if shape["turn_degrees"] > 20]
for shape in turned:
    print(f"{shape['file']}: turned {shape['turn_degrees']:.0f} degrees from the others")
sys.exit(bool(turned) or score["median"] > float(sys.argv[2]))
CHECK
}

# The radii family: radii that swap order from shape to shape, and bumps
# and knobs of their own heights (seed 1: a rigid fit's criterion turned 5 of
# its 6 shapes 74 to 174 degrees, median spread 2.41; an affine one with
# the medoid, 44 degrees at most and 0.56; the bodies' turns, 13 and 0.23).
no_shape_turned radii 1 0.35
# The bent family: bodies that are their own half turn but for three small
# bumps, which one fit onto the template mistakes (seed 3: shape 5 turned
# 180 degrees by its fit alone, median spread 0.96). The population chooses
# among the poses the fits leave open.
no_shape_turned bent 3 0.3

# Bent either way (seed 5, 12 shapes): every shape bent the template's way
# keeps the pose its bumps chose, not turned from the template (a rigid fit
# onto a medoid bent the other way turned one half round, judged by the
# silhouette). Those bent the other way are not held to it (docs/CORRESPONDENCE.md).
# SHAPES VERTICES SEED SIDES: a bent-either population corresponded at
# n = 64; no shape bent SIDES ("same": as the template, "any") may lie
# turned more than 20 degrees from the template.
none_turned_from_template() {
  local shapes=$1 vertices=$2 seed=$3 sides=$4 dir=$work/either_$1_$3
  "$bin" generate --population "$shapes" --family bent-either --vertices "$vertices" --seed "$seed" --out-dir "$dir" 2>/dev/null
  "$bin" correspond "$dir" -n 64 --samples 20 -q --out "${dir}_correspond" >/dev/null
  /usr/bin/python3 "$scripts/correspondence_error.py" "$dir/population.json" \
    "${dir}_correspond"/shapes/*.particles --json "${dir}_score.json" >/dev/null
  /usr/bin/python3 - "$dir/population.json" "${dir}_score.json" "$sides" <<'CHECK' || fail "bent either way, seed $seed: a shape lies turned from the template"
import json, sys
shapes = json.load(open(sys.argv[1]))["shapes"]
scored = json.load(open(sys.argv[2]))["per_shape"]
turned = [(shape["mesh"], score["turn_from_first_degrees"]) for shape, score in zip(shapes, scored)
          if (sys.argv[3] == "any" or shape["bend_side"] == shapes[0]["bend_side"]) and score["turn_from_first_degrees"] > 20]
for mesh, degrees in turned:
    print(f"{mesh}: turned {degrees:.0f} degrees from the template")
sys.exit(bool(turned))
CHECK
}
none_turned_from_template 12 2000 5 same
# Seed 5 at 2,500 vertices: two shapes bent the other way, which the coarse
# fit laid in the half turn at 0.33 (under sure_relief), are posed by their
# canonical forms, which lay the relief better (0.59, 0.46).
none_turned_from_template 6 2500 5 any
echo "ok"
