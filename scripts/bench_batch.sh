#!/usr/bin/env bash
# bench_batch.sh [SHAPES] [RANKS] [WORKDIR]: the population benchmark of
# docs/PERFORMANCE.md ("Populations"). Generates SHAPES (default 100)
# atrium-like shapes of about 10k vertices (generate --population, seed 1),
# then with n = 1024 and the default run options:
#   - one process:           meshes per minute
#   - mpirun -n RANKS (2):    meshes per minute, the speed-up, and whether
#                             every particle file equals the one-process one
#   - the share of the time in geodesics and in particles (summary.json)
#   - a batch of one mesh against `run` on it, three times each, alternating
# Every run without the distance cache (--no-cache), so each computes its
# distances. MESHPARTICLES=path/to/binary (default build/meshparticles).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
shapes=${1:-100} ranks=${2:-2} work=${3:-/tmp/meshparticles_bench_batch}
bin=${MESHPARTICLES:-$ROOT/build/meshparticles}
options=(-n 1024 --no-cache)
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
rm -rf "$work" && mkdir -p "$work"

seconds() {  # seconds COMMAND...: wall time, the command's output in $work/last.log
  local start=$(date +%s%N)
  "$@" > "$work/last.log" 2>&1 || [ $? -eq 2 ] || { cat "$work/last.log"; exit 1; }
  echo "scale=3; ($(date +%s%N) - $start) / 1000000000" | bc
}

"$bin" generate --population "$shapes" --vertices 10000 --seed 1 --out-dir "$work/population" 2> /dev/null
echo "population: $shapes shapes, $(head -2 "$work/population/atrium_000.off" | tail -1 | cut -d' ' -f1) vertices each, n = 1024"

one=$(seconds "$bin" batch "$work/population" "${options[@]}" --out "$work/one")
many=$(seconds mpirun "${root[@]}" -n "$ranks" --oversubscribe "$bin" batch "$work/population" "${options[@]}" --out "$work/many")
same=yes
for folder in "$work/one"/*/; do
  cmp -s "$folder/particles.particles" "$work/many/$(basename "$folder")/particles.particles" || same=no
done
echo "one process:   $one s, $(echo "scale=2; 60 * $shapes / $one" | bc) meshes/min"
echo "mpirun -n $ranks:   $many s, $(echo "scale=2; 60 * $shapes / $many" | bc) meshes/min, speed-up $(echo "scale=2; $one / $many" | bc)x; particle files equal to one process: $same"
python3 - "$work/one/summary.json" << 'EOF'
import json, sys
rows = [r for r in json.load(open(sys.argv[1]))["meshes"] if r["status"] == "ok"]
total = sum(r["seconds_total"] for r in rows)
geodesics = sum(r["seconds_geodesics"] for r in rows)
# On local distances the balls are computed on demand during the start, the
# iterations and the quality: seconds_geodesics overlaps the others then, and
# only the total counts each second once.
stores = sorted({r["distances"] for r in rows})
print(f"one process, per mesh: {total / len(rows):.2f} s ({', '.join(stores)} distances); "
      f"geodesics {100 * geodesics / total:.0f} %, the rest (start, iterations, quality) "
      f"{100 * (1 - geodesics / total):.0f} %")
EOF

mesh="$work/population/atrium_000.off"
for round in 1 2 3; do
  run=$(seconds "$bin" run "$mesh" "${options[@]}" --out "$work/run_one")
  batch=$(seconds "$bin" batch "$mesh" "${options[@]}" --force --out "$work/batch_one")
  echo "overhead, round $round: run $run s, batch of one $batch s, ratio $(echo "scale=3; $batch / $run" | bc)"
done
