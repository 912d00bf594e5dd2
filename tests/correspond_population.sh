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
echo "ok"
