#!/usr/bin/env bash
# scripts/faust_population.sh [--person P] REPO OUT_DIR [SHAPES]
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
# scores). With --person P (0-9), takes instead the first SHAPES (default 10)
# of person P's 10 poses (tr_reg_{10P + pose}): one body whose arms and legs
# turn at the joints.
# Why: scripts/real_population.sh and scripts/correspondence_scoreboard.sh
# both start from it.
set -euo pipefail
usage="usage: faust_population.sh [--person P] REPO OUT_DIR [SHAPES]"
person=
if [ "${1:-}" = --person ]; then
  person=${2:?$usage}
  shift 2
  [[ $person =~ ^[0-9]$ ]] || { echo "faust_population: --person takes 0-9, not '$person'" >&2; exit 2; }
fi
repo=${1:?$usage}
out=${2:?$usage}
shapes=${3:-10}
if ! [[ $shapes =~ ^[0-9]+$ ]] || ((shapes < 2 || shapes > 10)); then
  echo "faust_population: SHAPES takes 2-10, not '$shapes'" >&2
  exit 2
fi
source_file() {  # PATH in the dataset -> stdout, from a work tree or a git folder
  if [ -e "$repo/$1" ]; then cat "$repo/$1"; else git --git-dir="$repo" show "HEAD:$1"; fi
}
rm -rf "$out" && mkdir -p "$out/shapes" "$out/maps"
entries=()
for ((k = 0; k < shapes; ++k)); do
  if [ -n "$person" ]; then index=$((10 * person + k)); else index=$((10 * k)); fi  # pose k, or person k's pose 0
  name=$(printf 'tr_reg_%03d' "$index")
  source_file "Dataset/FAUST/vtx_5k/$name.off" >"$out/shapes/$name.off"
  source_file "Dataset/FAUST/vtx_5k/corres/$name.vts" >"$out/maps/$name.vts"
  entries+=("{\"mesh\": \"shapes/$name.off\", \"map\": \"maps/$name.vts\"}")
done
(IFS=,; echo "{\"one_based\": true, \"reference\": 0, \"shapes\": [${entries[*]}]}") >"$out/population_map.json"
