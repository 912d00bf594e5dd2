#!/usr/bin/env bash
# paper_method.sh MESHPARTICLES MESHES DATA WORKDIR: `run --method paper`
# makes exactly the moves the default made before spread became the default.
# DATA/paper_default/MESH_N.txt holds the input vertex of each particle as
# the default run of commit 45b2e36 wrote it (particles.csv, column 2; field
# on the dense table for torus and sphere, serial-field on local balls for
# the atrium), made on PoCL.
set -euo pipefail
bin=$1 meshes=$2 data=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
for saved in "$data"/paper_default/*.txt; do
  case_name=$(basename "$saved" .txt)   # MESH_N
  mesh=${case_name%_*} n=${case_name##*_}
  "$bin" run "$meshes/$mesh.off" -n "$n" --method paper --no-cache --out "$work/$case_name" -q > /dev/null
  tail -n +2 "$work/$case_name/particles.csv" | cut -d, -f2 > "$work/$case_name.txt"
  cmp -s "$saved" "$work/$case_name.txt" || { echo "FAIL: $case_name: --method paper moved elsewhere than the old default"; exit 1; }
  grep -q '"method_from": "--method"' "$work/$case_name/report.json" || { echo "FAIL: $case_name: method_from"; exit 1; }
done
echo "ok"
