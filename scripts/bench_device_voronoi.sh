#!/usr/bin/env bash
# spread with the evening's Voronoi diagrams and the measurement's balls on
# the host and on a device: `--device` (the diagrams, and on a GPU the
# balls) and `--device --geodesic fim` (the balls there on any device),
# case by case: the whole run's wall
# time, the diagrams' own seconds (report.json evening.diagrams) and the
# measurement's (seconds.geodesics + seconds.quality, its balls included),
# docs/PERFORMANCE.md ("spread's diagrams and measurement on the device").
#
#   scripts/bench_device_voronoi.sh [--device NAME] [--repeat K] OUT_DIR
#
# NAME: what --device takes (default "Portable Computing Language"; "NVIDIA"
# on a GPU machine). The cases: CGAL's bull (6,200 vertices; the evening runs there; found in
# $MESHPARTICLES_CGAL_MESHES, default ~/.cache/meshparticles/cgal-data/data/meshes)
# and `generate sphere --vertices 200000`, each at n = 1,024 and 4,096.
# MESHPARTICLES (default build/meshparticles) is the program.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${MESHPARTICLES:-$ROOT/build/meshparticles}"
CGAL="${MESHPARTICLES_CGAL_MESHES:-$HOME/.cache/meshparticles/cgal-data/data/meshes}"
device="Portable Computing Language" repeat=1 out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    -*) echo "usage: $0 [--device NAME] [--repeat K] OUT_DIR" >&2; exit 2 ;;
    *) out="$1"; shift ;;
  esac
done
[ -n "$out" ] || { echo "usage: $0 [--device NAME] [--repeat K] OUT_DIR" >&2; exit 2; }
mkdir -p "$out"
[ -f "$out/sphere_198812.off" ] || "$BIN" generate sphere --vertices 200000 --out-dir "$out" >/dev/null
[ -f "$CGAL/bull.off" ] || { echo "no $CGAL/bull.off (set MESHPARTICLES_CGAL_MESHES)" >&2; exit 1; }
printf '| mesh | n | path | wall s (best of %s) | diagrams | diagram s | evening moves | geodesics + quality s | balls on device | rho |\n|---|---|---|---|---|---|---|---|---|---|\n' "$repeat"
for mesh in "$CGAL/bull.off" "$out/sphere_198812.off"; do
  for n in 1024 4096; do
    for path in host device device-fim; do
      best=""
      for ((k = 0; k < repeat; ++k)); do
        run="$out/$(basename "$mesh" .off)_${n}_$path"
        extra=()
        [ "$path" = device ] && extra=(--device "$device")
        [ "$path" = device-fim ] && extra=(--device "$device" --geodesic fim)
        rm -rf "$run"
        start=$(date +%s.%N)
        "$BIN" run "$mesh" -n "$n" -q --out "$run" "${extra[@]}" >/dev/null
        wall=$(echo "$(date +%s.%N) - $start" | bc)
        if [ -z "$best" ] || [ "$(echo "$wall < $best" | bc)" = 1 ]; then
          best=$wall
          cp "$run/report.json" "$run.best.json"  # the fastest repetition's seconds
        fi
      done
      python3 - "$run.best.json" "$(basename "$mesh" .off)" "$n" "$path" "$best" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
e = r.get("evening")
d = e["diagrams"] if e else None
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {float(sys.argv[5]):.2f} | "
      f"{d['count'] if d else 'no evening'} | {d['seconds']:.2f} | {e['moves']} | " if d else
      f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {float(sys.argv[5]):.2f} | no evening | - | - | ", end="")
s = r["seconds"]
print(f"{s['geodesics']:.2f} + {s['quality']:.2f} | {r['distances'].get('balls_on_device', 0)} | "
      f"{r['quality'].get('rho', float('nan')):.3f} |")
PY
    done
  done
done
