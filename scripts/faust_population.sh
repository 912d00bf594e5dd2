#!/usr/bin/env bash
# scripts/faust_population.sh REPO OUT_DIR [SHAPES]
#
# What: the real test population of docs/CORRESPONDENCE.md, laid out for correspond and scored by its
# known map. REPO is a copy of llorz/SGA18_orientation_BCICP_dataset (Ren et
# al. 2018: FAUST's registrations, each remeshed on its own to about 5,000
# vertices, with corres/NAME.vts: line k the vertex that is sample k on every
# shape), a work tree or a bare git folder (as the session's fetch tool leaves
# it). Its files are FAUST's (MPI's licence: research only, no
# redistribution): they are copied under OUT_DIR and never into this
# repository. Takes pose 0 of the first SHAPES (default 10) of FAUST's 10
# people (tr_reg_000, 010, ...) into OUT_DIR/shapes and OUT_DIR/maps, and
# writes OUT_DIR/population_map.json (which scripts/correspondence_error.py
# scores).
# Why: scripts/real_population.sh and scripts/correspondence_scoreboard.sh
# both start from it.
set -euo pipefail
repo=${1:?usage: faust_population.sh REPO OUT_DIR [SHAPES]}
out=${2:?usage: faust_population.sh REPO OUT_DIR [SHAPES]}
shapes=${3:-10}
source_file() {  # PATH in the dataset -> stdout, from a work tree or a git folder
  if [ -e "$repo/$1" ]; then cat "$repo/$1"; else git --git-dir="$repo" show "HEAD:$1"; fi
}
rm -rf "$out" && mkdir -p "$out/shapes" "$out/maps"
entries=()
for ((person = 0; person < shapes; ++person)); do
  name=$(printf 'tr_reg_%03d' $((10 * person)))
  source_file "Dataset/FAUST/vtx_5k/$name.off" >"$out/shapes/$name.off"
  source_file "Dataset/FAUST/vtx_5k/corres/$name.vts" >"$out/maps/$name.vts"
  entries+=("{\"mesh\": \"shapes/$name.off\", \"map\": \"maps/$name.vts\"}")
done
(IFS=,; echo "{\"one_based\": true, \"reference\": 0, \"shapes\": [${entries[*]}]}") >"$out/population_map.json"
