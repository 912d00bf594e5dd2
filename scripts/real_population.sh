#!/usr/bin/env bash
# scripts/real_population.sh REPO OUT_DIR [N] [SHAPES]
#
# What: correspond and the CPD baseline on real human scans with a known map.
# REPO and SHAPES as scripts/faust_population.sh takes them (FAUST's
# registrations, each remeshed on its own, from
# llorz/SGA18_orientation_BCICP_dataset; never copied into this repository):
# lays out pose 0 of the first SHAPES (default 10) people under OUT_DIR with
# OUT_DIR/population_map.json (which scripts/correspondence_error.py scores),
# runs `correspond -n N` (default 256) and scripts/cpd_baseline.py on them and
# prints both rows.
# Why: issue 48's real population, scored by its known map.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=$here/build/meshparticles
repo=${1:?usage: real_population.sh REPO OUT_DIR [N] [SHAPES]}
out=${2:?usage: real_population.sh REPO OUT_DIR [N] [SHAPES]}
n=${3:-256} shapes=${4:-10}
[ -x "$bin" ] || { echo "build first: scripts/setup.sh" >&2; exit 2; }
"$here/scripts/faust_population.sh" "$repo" "$out" "$shapes"
"$bin" correspond "$out/shapes" -n "$n" -q --out "$out/correspond" >/dev/null
/usr/bin/python3 "$here/scripts/cpd_baseline.py" "$out/shapes" -n "$n" --out "$out/cpd" \
  --correspond "$out/correspond" --map-population "$out/population_map.json" --binary "$bin" --json "$out/figures.json"
