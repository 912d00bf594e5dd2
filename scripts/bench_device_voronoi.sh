#!/usr/bin/env bash
# spread with the evening's Voronoi diagrams, its moves' cavity centres and
# the measurement's balls on the host and on a device: `--device` (the
# diagrams, the centres where the device has double precision, and on a
# GPU the balls) and `--device --geodesic fim` (the balls there on any
# device), case by case: the whole run's wall time, the diagrams' and the
# centres' own seconds (report.json evening.diagrams, evening.centres: all
# the proposals, wherever found) and the measurement's
# (seconds.geodesics + seconds.quality, its balls included),
# docs/PERFORMANCE.md ("spread's diagrams and measurement on the device").
#
#   scripts/bench_device_voronoi.sh [--device NAME] [--repeat K] [--models "M ..."]
#                                   [--sizes "N ..."] [--paths "P ..."] OUT_DIR
#
# NAME: what --device takes (default "Portable Computing Language"; "NVIDIA"
# on a GPU machine). Models (default "bull camel man cheese sphere"): CGAL
# meshes by name (found in $MESHPARTICLES_CGAL_MESHES, default
# ~/.cache/meshparticles/cgal-data/data/meshes; the evening runs on them),
# "sphere" for `generate sphere --vertices 200000` (no evening: the
# relaxation is kept). Sizes default "1024 4096"; paths "host device
# device-fim". Cases alternate the paths, repetition by repetition.
# MESHPARTICLES (default build/meshparticles) is the program.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${MESHPARTICLES:-$ROOT/build/meshparticles}"
CGAL="${MESHPARTICLES_CGAL_MESHES:-$HOME/.cache/meshparticles/cgal-data/data/meshes}"
device="Portable Computing Language" repeat=1 out=""
models="bull camel man cheese sphere" sizes="1024 4096" paths="host device device-fim"
usage="usage: $0 [--device NAME] [--repeat K] [--models \"M ...\"] [--sizes \"N ...\"] [--paths \"P ...\"] OUT_DIR"
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --models) models="$2"; shift 2 ;;
    --sizes) sizes="$2"; shift 2 ;;
    --paths) paths="$2"; shift 2 ;;
    -*) echo "$usage" >&2; exit 2 ;;
    *) out="$1"; shift ;;
  esac
done
[ -n "$out" ] || { echo "$usage" >&2; exit 2; }
mkdir -p "$out"
meshes=()
for model in $models; do
  if [ "$model" = sphere ]; then
    [ -f "$out/sphere_198812.off" ] || "$BIN" generate sphere --vertices 200000 --out-dir "$out" >/dev/null
    meshes+=("$out/sphere_198812.off")
  else
    [ -f "$CGAL/$model.off" ] || { echo "no $CGAL/$model.off (set MESHPARTICLES_CGAL_MESHES)" >&2; exit 1; }
    meshes+=("$CGAL/$model.off")
  fi
done
printf '| mesh | n | path | wall s (best of %s) | diagrams | diagram s | centres on | centres s | evening moves | geodesics + quality s | balls on device | rho |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n' "$repeat"
for mesh in "${meshes[@]}"; do
  for n in $sizes; do
    declare -A best=()
    for ((k = 0; k < repeat; ++k)); do
      for path in $paths; do
        run="$out/$(basename "$mesh" .off)_${n}_$path"
        extra=()
        [ "$path" = device ] && extra=(--device "$device")
        [ "$path" = device-fim ] && extra=(--device "$device" --geodesic fim)
        rm -rf "$run"
        start=$(date +%s.%N)
        "$BIN" run "$mesh" -n "$n" -q --out "$run" "${extra[@]}" >/dev/null
        wall=$(echo "$(date +%s.%N) - $start" | bc)
        if [ -z "${best[$path]:-}" ] || [ "$(echo "$wall < ${best[$path]}" | bc)" = 1 ]; then
          best[$path]=$wall
          cp "$run/report.json" "$run.best.json"  # the fastest repetition's seconds
        fi
      done
    done
    for path in $paths; do
      run="$out/$(basename "$mesh" .off)_${n}_$path"
      python3 - "$run.best.json" "$(basename "$mesh" .off)" "$n" "$path" "${best[$path]}" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
e = r.get("evening")
d = e["diagrams"] if e else None
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {float(sys.argv[5]):.2f} | "
      f"{d['count']} | {d['seconds']:.2f} | {e['centres']['on']} | {e['centres']['seconds']:.2f} | {e['moves']} | " if d else
      f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {float(sys.argv[5]):.2f} | no evening | - | - | - | - | ", end="")
s = r["seconds"]
print(f"{s['geodesics']:.2f} + {s['quality']:.2f} | {r['distances'].get('balls_on_device', 0)} | "
      f"{r['quality'].get('rho', float('nan')):.3f} |")
PY
    done
  done
done
