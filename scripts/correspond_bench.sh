#!/usr/bin/env bash
# scripts/correspond_bench.sh OUT_DIR [SHAPES] [N] [VERTICES]
#
# What: issue 31's measures of `meshparticles correspond` on a population whose
# correspondence is known: SHAPES (default 20) ellipsoid shapes of about
# VERTICES (default 4000) vertices, each meshed on its own and posed at random
# (`generate --population --family ellipsoid`: two true modes, elongation and
# a bump's height), N (default 256) particles. Prints, for correspond and for
# batch (each shape sampled on its own):
#   - the spread of particle i across the shapes, in particle spacings
#     (scripts/correspondence_error.py: median, mean, 90th percentile);
#   - evenness kept: each shape's nn_cv over that of its own independent run
#     (batch's), median and largest;
#   - compactness: the variance the first 2 modes of the model hold;
#   - the wall time of each.
# Why: the numbers of docs/CORRESPONDENCE.md, from one command.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=$here/build/meshparticles
out=${1:?usage: correspond_bench.sh OUT_DIR [SHAPES] [N] [VERTICES]}
shapes=${2:-20} n=${3:-256} vertices=${4:-4000}
[ -x "$bin" ] || { echo "build first: scripts/setup.sh" >&2; exit 2; }
rm -rf "$out" && mkdir -p "$out"
"$bin" generate --population "$shapes" --family ellipsoid --vertices "$vertices" --out-dir "$out/shapes" 2>/dev/null
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
correspond_time=$(seconds "$bin" correspond "$out/shapes" -n "$n" -q --out "$out/correspond")
batch_time=$(seconds "$bin" batch "$out/shapes" -n "$n" -q --out "$out/batch")
echo "== $shapes shapes of about $vertices vertices, n = $n"
echo "correspond: $correspond_time s; batch: $batch_time s"
for kind in correspond batch; do
  if [ $kind = correspond ]; then files=("$out"/correspond/shapes/*.particles); else files=("$out"/batch/*/particles.particles); fi
  printf '%-11s ' "$kind"
  /usr/bin/python3 "$here/scripts/correspondence_error.py" "$out/shapes/population.json" "${files[@]}"
done
/usr/bin/python3 - "$out" <<'PY'
import csv, json, sys
from pathlib import Path
import numpy as np
out = Path(sys.argv[1])
summary = json.loads((out / "correspond/summary.json").read_text())
ratios = []
for shape in summary["shapes"]:
    own = json.loads((out / "batch" / Path(shape["mesh"]).stem / "report.json").read_text())["quality"]["nn_cv"]
    ratios.append(shape["quality"]["nn_cv"] / own)
print(f"evenness kept: nn_cv over the shape's own run's, median {np.median(ratios):.2f}, largest {max(ratios):.2f}")
rows = list(csv.DictReader(open(out / "correspond/model/modes.csv")))
print(f"compactness: the first 2 modes hold {100 * float(rows[1]['cumulative']):.1f}% of the variance")
PY
